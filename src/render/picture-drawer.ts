import {
  type Camera,
  NoBlending,
  PMREMGenerator,
  type Scene,
  SRGBColorSpace,
  type Texture,
  ShaderMaterial,
  Vector2,
  WebGLRenderTarget,
  type WebGLRenderer,
} from 'three';
import { RoomEnvironment } from 'three/addons/environments/RoomEnvironment.js';
import { FullScreenQuad } from 'three/addons/postprocessing/Pass.js';
import { CopyShader } from 'three/addons/shaders/CopyShader.js';

/**
 * Draws a view's scene to its canvas: a moving picture as the canvas is set up, a still (a face at rest, a picture, a
 * video frame) antialiased even where the canvas does not multisample (see Antialias), and the canvas's
 * `data-quality` saying which it shows.
 */
export class PictureDrawer {
  /** Whether the picture on the canvas was drawn without the antialiasing a still gets. */
  rough = false;
  /** The offscreen multisampled target a still is drawn into, and its copy to the canvas (made at the first still). */
  private still: { target: WebGLRenderTarget; copy: FullScreenQuad } | null = null;
  private readonly size = new Vector2();
  /** What the canvas's pipelines were made ahead for (see warmMotion): the head, its environment map, the programs. */
  private warmedHead: object | undefined;
  private warmedEnvironment: Texture | null = null;
  private warmedPrograms = 0;

  /** `multisampled`: whether the renderer's canvas multisamples. */
  constructor(
    private readonly renderer: WebGLRenderer,
    private readonly multisampled: boolean,
  ) {}

  /**
   * Draws `scene`, making its environment map first if it shows a head (`lit`) and has none yet; `reduced` says the
   * canvas is at the motion's lower resolution.
   */
  draw(scene: Scene, camera: Camera, still: boolean, reduced: boolean, lit: boolean): void {
    if (!scene.environment && lit) {
      // Made on the first frame with a head, not with the view: a face that is never in view never pays for it (in
      // software WebGL it is seconds of GPU work, which a lost context waits for).
      const pmrem = new PMREMGenerator(this.renderer);
      const room = new RoomEnvironment();
      scene.environment = pmrem.fromScene(room, 0.04).texture;
      room.dispose();
      pmrem.dispose();
    }
    if (still && !this.multisampled) {
      this.drawStill(scene, camera);
      this.rough = false;
    } else {
      this.renderer.render(scene, camera);
      this.rough = !this.multisampled;
    }
    // What the canvas shows, for a page or a test that waits for the finished picture: `full` (full resolution,
    // antialiased) or `motion` (drawn lower while the face moves). Written only when it changes.
    const quality = reduced || this.rough ? 'motion' : 'full';
    const canvas = this.renderer.domElement;
    if (canvas.dataset.quality !== quality) canvas.dataset.quality = quality;
  }

  /**
   * Draws `scene` once into one pixel of the canvas, where the still already shows the same background, so that the
   * motion's first draw finds its pipelines made; returns whether it drew. Where the canvas does not multisample, a
   * still is drawn into an offscreen target, and the canvas needs pipelines of its own: in software WebGL making them
   * took the first motion frame 1.0 to 1.6 s of the GPU's time, after the first input (docs/page-notes.md). Done
   * again for another `head`, environment map or set of programs.
   */
  warmMotion(scene: Scene, camera: Camera, head: object): boolean {
    const programs = this.renderer.info.programs?.length ?? 0;
    const environment = scene.environment;
    if (this.multisampled) return false;
    if (head === this.warmedHead && environment === this.warmedEnvironment && programs === this.warmedPrograms) return false;
    this.warmedHead = head;
    this.warmedEnvironment = environment;
    this.warmedPrograms = programs;
    const renderer = this.renderer;
    renderer.setScissorTest(true);
    renderer.setScissor(0, 0, 1, 1);
    renderer.render(scene, camera);
    renderer.setScissorTest(false);
    return true;
  }

  /** Frees the still's target and copy. */
  dispose(): void {
    this.still?.target.dispose();
    this.still?.copy.material.dispose();
    this.still?.copy.dispose();
    this.still = null;
  }

  /**
   * Draws the scene into a multisampled target the canvas's size and copies it to the canvas. The target is shaded as
   * the canvas is: three.js shades a render target linear and without tone mapping unless it is marked as WebXR's
   * (the flag WebXRManager sets on its own targets), and its 8-bit storage holds the shaders' sRGB output as the
   * canvas does; the copy writes its pixels unchanged, alpha included, so the still is the picture a multisampled
   * canvas would show.
   */
  private drawStill(scene: Scene, camera: Camera): void {
    const renderer = this.renderer;
    const { x: width, y: height } = renderer.getDrawingBufferSize(this.size);
    if (!this.still) {
      const target = new WebGLRenderTarget(width, height, { samples: 4, colorSpace: SRGBColorSpace });
      target.texture.internalFormat = 'RGBA8';
      (target as WebGLRenderTarget & { isXRRenderTarget: boolean }).isXRRenderTarget = true;
      const material = new ShaderMaterial({ ...CopyShader, uniforms: { tDiffuse: { value: target.texture }, opacity: { value: 1 } } });
      material.blending = NoBlending;
      this.still = { target, copy: new FullScreenQuad(material) };
    }
    const { target, copy } = this.still;
    if (target.width !== width || target.height !== height) target.setSize(width, height);
    renderer.setRenderTarget(target);
    renderer.render(scene, camera);
    renderer.setRenderTarget(null);
    copy.render(renderer);
  }
}
