import {
  ACESFilmicToneMapping,
  type Box3,
  Color,
  Mesh,
  MeshPhysicalMaterial,
  type PerspectiveCamera,
  Scene,
  SRGBColorSpace,
  type Texture,
  WebGLRenderer,
  type Material,
} from 'three';
import type { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import type { HeadModel } from './head-model';
import { timeRenders, type RenderTiming } from './render-timing';
import { ViewCamera } from './view-camera';
import { ViewLights } from './view-lights';
import type { HairSnapshot } from './hair-view';
import { describeMaterial, type MaterialDescription } from './materials';
import { DrawSchedule } from './draw-schedule';
import {
  APPEARANCE_DEFAULTS,
  APPEARANCE_RANGES,
  RENDER_DEFAULTS,
  type AppearanceOptions,
  type CameraOptions,
  type LightOptions,
  type RenderOptions,
  HEAD_VIEW_DEFAULTS,
  type HeadViewOptions,
  type ViewBackground,
} from './view-options';
import { checkOptions } from '../core/check';
import { disposeTree } from './dispose-tree';
import { softwareWebGL } from './software-webgl';
import { PictureDrawer } from './picture-drawer';
import { DrawFence } from './draw-fence';

/**
 * Work done at each animation frame while the view is in view; `now` is the frame's timestamp in ms. It returns true
 * when it changed what the frame shows (new skin, turned eyes), so that the view draws it; `hold` when what it shows
 * is about to change (the skin has not answered an input yet), so that the view puts off drawing until it has: the
 * hook bounds how long it holds; `moving` when it has nothing new for this frame but more is coming (the solver still
 * works), so that the view does not take the motion for ended; `solving` when it changed what the frame shows and more
 * is coming from a solver that shares the machine's cores, so that slow draws leave the cores to it (see DrawFence).
 */
export type FrameHook = (now: number) => boolean | 'hold' | 'moving' | 'solving' | undefined;

/** A fixed-size rendering of the view for a recorder: the render loop holds until `dispose`. */
export interface ViewCapture {
  /** The canvas, `width` x `height` pixels while the capture lasts. */
  readonly canvas: HTMLCanvasElement;
  /** Renders the scene as it is now. */
  render(): void;
  /** Gives the canvas its own size back and lets the render loop run again. */
  dispose(): void;
}

/** A three.js scene that shows a head: renderer, camera, orbit controls and the default lights. */
export class HeadView {
  readonly renderer: WebGLRenderer;
  readonly scene = new Scene();
  readonly camera: PerspectiveCamera;
  readonly controls: OrbitControls;
  /** The camera's framing and placing. */
  private readonly view: ViewCamera;
  private readonly lights: ViewLights;
  private head: HeadModel | undefined;
  private readonly render: Required<RenderOptions> = { ...RENDER_DEFAULTS };
  private readonly appearance: Required<AppearanceOptions> = { ...APPEARANCE_DEFAULTS };
  /** The pending animation frame's request id (0 when the loop is stopped). */
  private animationFrame = 0;
  private readonly frameHooks: FrameHook[] = [];
  private readonly renderHooks: (() => void)[] = [];
  /** When the loop draws and how. */
  private readonly schedule: DrawSchedule;
  /** The pixel ratio of a full-resolution draw, and whether the canvas is at the motion's lower one now. */
  private readonly pixelRatio: number;
  private readonly motionResolution: number;
  private reduced = false;
  /**
   * The animation frame time of the loop's last draw (-1 once measured), and how long the last full-resolution one
   * held the next animation frame back: the page waits there for the GPU to finish the draw.
   */
  private drawnAt = -1;
  private fullDrawMs = 0;
  private readonly resizeObserver: ResizeObserver;
  /**
   * Whether any of the canvas is in view: a view scrolled away or in a hidden element renders nothing (and runs no
   * frame hooks), so a page with several faces pays only for those it shows. False until the observer first reports.
   */
  private inView = false;
  private readonly viewObserver: IntersectionObserver;
  /** Set while a capture holds the canvas at its own size: the render loop and resizes wait. */
  private capturing = false;
  /** Draws each picture, antialiased as HeadViewOptions.antialias says. */
  private readonly pictures: PictureDrawer;
  /** Whether the GPU is still at the last draw. */
  private readonly fence: DrawFence;

  constructor(
    private readonly container: HTMLElement,
    options: Partial<HeadViewOptions> = {},
  ) {
    const o = { ...HEAD_VIEW_DEFAULTS, ...options };
    // With an alpha channel the background can turn transparent later without a new context; an opaque background
    // fills every pixel, so it looks the same as without one.
    const multisampled = o.antialias === 'always' || (o.antialias === 'auto' && !softwareWebGL());
    this.renderer = new WebGLRenderer({ antialias: multisampled, preserveDrawingBuffer: true, alpha: true });
    this.pictures = new PictureDrawer(this.renderer, multisampled);
    this.fence = new DrawFence(this.renderer.getContext() as WebGL2RenderingContext, o.slowDrawMs);
    this.pixelRatio = Math.min(window.devicePixelRatio, o.maxPixelRatio);
    this.motionResolution = Math.min(1, Math.max(0.25, o.motionResolution));
    this.schedule = new DrawSchedule(this.motionResolution, o.slowDrawMs);
    this.renderer.setPixelRatio(this.pixelRatio);
    this.renderer.outputColorSpace = SRGBColorSpace;
    this.renderer.toneMapping = ACESFilmicToneMapping;
    this.renderer.toneMappingExposure = 1.0;
    container.appendChild(this.renderer.domElement);

    this.setBackground(o.background);
    this.scene.environmentIntensity = 0.2;

    this.lights = new ViewLights(this.scene);

    this.view = new ViewCamera(o.fov, this.renderer.domElement, this.invalidate);
    this.camera = this.view.camera;
    this.controls = this.view.controls;

    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(container);
    this.resize();
    this.viewObserver = new IntersectionObserver((entries) => {
      this.inView = entries[entries.length - 1].isIntersecting;
      this.invalidate();
    });
    this.viewObserver.observe(this.renderer.domElement);
    // Pointer and keys may change what is drawn in ways no setter sees (a gizmo's hover, the editor's tools).
    for (const type of INPUT_EVENTS) this.renderer.domElement.addEventListener(type, this.invalidate);
    window.addEventListener('keydown', this.invalidate);
  }

  /**
   * Asks for new pictures: the view draws only when something changed (a battery on a laptop should not pay for a face
   * that stands still), so whatever changes the scene outside the view's own setters and frame hooks calls this.
   */
  readonly invalidate = (): void => {
    this.schedule.invalidate();
  };

  /** Shows a head (replacing the one shown) and frames it from the front. */
  setHead(head: HeadModel): void {
    if (this.head) this.scene.remove(this.head.root);
    this.head = head;
    this.schedule.headSet();
    this.scene.add(head.root);
    this.frameBounds(head.bounds);
    this.applyRender();
    this.invalidate();
  }

  /** Takes `head` off the scene if it is the one shown (its resources are the caller's to free). */
  removeHead(head: HeadModel): void {
    if (this.head !== head) return;
    this.scene.remove(head.root);
    this.head = undefined;
    this.invalidate();
  }

  /** Shows a background colour, or the page behind the canvas. */
  setBackground(background: ViewBackground): void {
    if (background === 'transparent') {
      this.scene.background = null;
      this.renderer.setClearColor(0x000000, 0);
    } else this.scene.background = new Color(background);
    this.invalidate();
  }

  /** Changes some light options; throws, changing nothing, on an unknown option or a value of the wrong type or range. */
  setLight(partial: Partial<LightOptions>): void {
    this.lights.set(partial);
    this.invalidate();
  }

  /** A copy of the current light options. */
  lightOptions(): LightOptions {
    return this.lights.options();
  }

  /** Changes some render options (wireframe, eyes, teeth); throws, changing nothing, on bad input. */
  setRenderOptions(partial: Partial<RenderOptions>): void {
    Object.assign(this.render, checkOptions<RenderOptions>('setRenderOptions', partial, RENDER_DEFAULTS));
    this.applyRender();
    this.invalidate();
  }

  /** A copy of the current render options. */
  renderOptions(): RenderOptions {
    return { ...this.render };
  }

  /** Changes some appearance options (the hair's colours, density and switches); throws, changing nothing, on bad input. */
  setAppearance(partial: Partial<AppearanceOptions>): void {
    Object.assign(
      this.appearance,
      checkOptions<AppearanceOptions>('setAppearance', partial, APPEARANCE_DEFAULTS, { ranges: APPEARANCE_RANGES }),
    );
    if (this.head) applyAppearance(this.head, this.appearance);
    this.invalidate();
  }

  /** A copy of the current appearance options. */
  appearanceOptions(): AppearanceOptions {
    return { ...this.appearance };
  }

  /** The shown head's hair as drawn now (see HairView.snapshot); null without a head or hair. */
  describeHair(vertexAt: (x: number, y: number, z: number) => number): HairSnapshot | null {
    return this.head?.hair?.snapshot(vertexAt) ?? null;
  }

  /** Renders a frame now and encodes the canvas as a PNG (what the user sees, at the canvas's pixel size). */
  snapshot(): Promise<Blob> {
    // The frame hooks first, as the render loop runs them: the skin takes the solver's newest frame, so a picture
    // taken as soon as `settle` resolves shows the settled skin, not the frame drawn before it.
    const now = performance.now();
    for (let i = 0; i < this.frameHooks.length; i++) this.frameHooks[i](now);
    this.controls.update();
    this.setReduced(false);
    this.drawPicture(true);
    // Read in the same task as the render, so the picture is there even without a preserved drawing buffer.
    return new Promise((resolve, reject) => {
      this.renderer.domElement.toBlob(
        (blob) => (blob ? resolve(blob) : reject(new Error('the canvas could not be encoded as a PNG'))),
        'image/png',
      );
    });
  }

  /**
   * Runs `hook` at each animation frame while the canvas is in view (until the returned function is called); a frame
   * is drawn if a hook says it changed something (see FrameHook). It must not wait for anything.
   */
  onFrame(hook: FrameHook): () => void {
    return remover(this.frameHooks, hook);
  }

  /** Runs `hook` after each drawn frame (until the returned function is called). */
  onRender(hook: () => void): () => void {
    return remover(this.renderHooks, hook);
  }

  /**
   * Holds the render loop (no frame hooks, no drawing) and sizes the canvas to `width` x `height` pixels, for a
   * recorder that renders each picture itself. The camera's damping comes to rest first, so that no motion left from
   * a drag reaches the pictures. Throws if a capture is already running.
   */
  capture(width: number, height: number): ViewCapture {
    if (this.capturing) throw new Error('the view is already being captured');
    this.capturing = true;
    this.view.stop();
    const renderer = this.renderer;
    this.setReduced(false);
    renderer.setPixelRatio(1);
    renderer.setSize(width, height, false);
    this.view.setAspect(width / height);
    let done = false;
    return {
      canvas: renderer.domElement,
      render: () => {
        if (!done) this.drawPicture(true);
      },
      dispose: () => {
        if (done) return;
        done = true;
        this.capturing = false;
        renderer.setPixelRatio(this.pixelRatio);
        this.resize();
      },
    };
  }

  /** Starts the render loop. */
  start(): void {
    const loop = (now: number): void => {
      this.animationFrame = requestAnimationFrame(loop);
      if (this.drawnAt >= 0) {
        if (!this.reduced) this.fullDrawMs = now - this.drawnAt;
        this.drawnAt = -1;
      }
      if (!this.inView || this.capturing) return;
      let changed = false;
      let hold = false;
      let moving = false;
      let solving = false;
      for (let i = 0; i < this.frameHooks.length; i++) {
        const result = this.frameHooks[i](now);
        if (result === true) changed = true;
        else if (result === 'solving') changed = solving = true;
        else if (result === 'hold') hold = true;
        else if (result === 'moving') moving = true;
      }
      // True while the camera moves: a drag, or the damping after one.
      if (this.controls.update()) changed = true;
      const reduced = this.reduced || this.pictures.rough;
      // A draw while the GPU is still at the last one would only wait behind it: held like a frame a hook holds.
      // A solver at work answers a hook every frame, with news ('solving') or without ('moving').
      const solverWorks = solving || moving;
      // Asked at every frame, held or not, so that it times the GPU's draws.
      const busy = this.fence.busy(now, solverWorks);
      const wait = hold || busy;
      const draw = this.schedule.choose(now, changed, wait, moving, reduced, this.head !== undefined, this.fullDrawMs);
      if (draw === 'skip') {
        // At a frame with nothing to draw: the motion's pipelines, made ahead where they are not yet.
        if (!wait && this.head && this.pictures.warmMotion(this.scene, this.camera, this.head)) this.fence.drawn(now, false);
        return;
      }
      this.setReduced(draw === 'reduced');
      this.drawPicture(draw === 'still');
      this.drawnAt = now;
      this.fence.drawn(now, solverWorks);
      for (let i = 0; i < this.renderHooks.length; i++) this.renderHooks[i]();
    };
    this.invalidate();
    if (!this.animationFrame) loop(performance.now());
  }

  /** The shown head's materials as plain data, each once (read-only: for tests and debugging). */
  describeMaterials(): MaterialDescription[] {
    const seen = new Set<Material>();
    this.head?.root.traverse((o) => {
      if (o instanceof Mesh) for (const m of Array.isArray(o.material) ? o.material : [o.material]) seen.add(m as Material);
    });
    return [...seen].map(describeMaterial);
  }

  /** Renders `frames` frames back to back and times them (a benchmark: it blocks the page; see timeRenders). */
  measureRender(frames = 100): RenderTiming {
    this.setReduced(false);
    this.drawPicture(false);
    return timeRenders(this.renderer, this.scene, this.camera, this.head?.hair, frames);
  }

  /**
   * Stops rendering, frees the GPU resources of everything in the scene and the listeners, removes the canvas and
   * gives its WebGL context back: the browser keeps a context alive until the canvas is collected otherwise, and
   * warns (then drops the oldest) past 16 live ones.
   */
  dispose(): void {
    cancelAnimationFrame(this.animationFrame);
    this.animationFrame = 0;
    this.frameHooks.length = 0;
    this.renderHooks.length = 0;
    for (const type of INPUT_EVENTS) this.renderer.domElement.removeEventListener(type, this.invalidate);
    window.removeEventListener('keydown', this.invalidate);
    this.resizeObserver.disconnect();
    this.viewObserver.disconnect();
    this.view.dispose();
    disposeTree(this.scene);
    this.scene.environment?.dispose();
    this.pictures.dispose();
    this.fence.dispose();
    this.renderer.dispose();
    // After dispose, which removed the renderer's context-lost listener: this loss is expected and logs nothing.
    this.renderer.forceContextLoss();
    this.renderer.domElement.remove();
  }

  /**
   * Lights the scene with a prefiltered environment (see loadEnvironment); without one, the view makes its own at the
   * first frame that shows a head.
   */
  setEnvironment(texture: Texture): void {
    this.scene.environment?.dispose();
    this.scene.environment = texture;
    this.invalidate();
  }

  /** Draws the scene to the canvas: a `still` (a face at rest, a picture, a video frame) is always antialiased. */
  private drawPicture(still: boolean): void {
    this.pictures.draw(this.scene, this.camera, still, this.reduced, this.head !== undefined);
  }

  /** Sets the canvas to the motion's lower resolution or back to full (a new size clears it; the caller draws). */
  private setReduced(reduced: boolean): void {
    if (reduced === this.reduced) return;
    this.reduced = reduced;
    this.renderer.setPixelRatio(reduced ? this.pixelRatio * this.motionResolution : this.pixelRatio);
  }

  /** Points the camera at the middle of `bounds` from the front (+z), far enough to see it whole; the key light follows. */
  frameBounds(bounds: Box3): void {
    this.lights.aimAt(this.view.fit(bounds));
  }

  /**
   * Turns the camera about the head's centre and moves it nearer or farther, relative to the framing from the front
   * (see CameraOptions); throws, changing nothing, on an unknown option or a value of the wrong type or range.
   */
  setCamera(partial: Partial<CameraOptions>): void {
    this.view.set(partial);
  }

  /** Where the camera is now, as CameraOptions (after the user's orbit drags too). */
  cameraOptions(): CameraOptions {
    return this.view.options();
  }

  /** Where a point of the shown head's skin (its model space) is on the page, in client pixels; null without a head. */
  locate(point: readonly [number, number, number]): { x: number; y: number } | null {
    if (!this.head) return null;
    this.head.skin.updateWorldMatrix(true, false);
    return this.view.project(point, this.head.skin.matrixWorld, this.renderer.domElement);
  }

  /** Applies the render options to the shown head (again whenever a head is shown). */
  private applyRender(): void {
    const head = this.head;
    if (!head) return;
    const wireframe = this.render.wireframe;
    // The hair keeps its look: ribbons drawn as their edges would turn the lashes into black blots.
    const hair = new Set(head.hair?.meshes().map((m) => m.mesh));
    head.root.traverse((o) => {
      if (!(o instanceof Mesh) || hair.has(o)) return;
      const materials = Array.isArray(o.material) ? o.material : [o.material];
      for (const m of materials)
        if ('wireframe' in m && m.wireframe !== wireframe) {
          m.wireframe = wireframe;
          m.needsUpdate = true;
        }
    });
    applyAppearance(head, this.appearance);
    for (const eye of head.eyes) eye.visible = this.render.showEyes;
    for (const t of head.teeth) t.visible = this.render.showTeeth;
    if (head.tongue) head.tongue.visible = this.render.showTeeth;
  }

  private resize(): void {
    // A capture sizes the canvas itself and calls this again once it ends.
    if (this.capturing) return;
    const w = Math.max(1, this.container.clientWidth);
    const h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    this.view.setAspect(w / h);
    this.invalidate();
  }
}

/**
 * Gives a head the appearance asked for: the hair's, and the skin's colour. A default keeps the head's own (an
 * identity's: identity-look.ts; the skin's linear value, which the sRGB hex only rounds), drawn exactly as before.
 */
function applyAppearance(head: HeadModel, appearance: Required<AppearanceOptions>): void {
  const own = head.hairLook;
  const hair = { ...appearance };
  if (own) {
    if (hair.browColor === APPEARANCE_DEFAULTS.browColor) hair.browColor = own.browColor;
    if (hair.lashColor === APPEARANCE_DEFAULTS.lashColor) hair.lashColor = own.lashColor;
    if (hair.browDensity === APPEARANCE_DEFAULTS.browDensity) hair.browDensity = own.browDensity;
  }
  head.hair?.setAppearance(hair);
  const skin = head.skin.material;
  if (!(skin instanceof MeshPhysicalMaterial)) return;
  skin.userData.ownColor ??= skin.color.clone();
  if (appearance.skinColor === APPEARANCE_DEFAULTS.skinColor) skin.color.copy(skin.userData.ownColor);
  else skin.color.set(appearance.skinColor);
}

/** Events on the canvas after which the view draws for a while (see HeadView.invalidate). */
const INPUT_EVENTS = ['pointerdown', 'pointermove', 'pointerup', 'wheel'] as const;

/** Adds `item` to `list` and returns a function that takes it out again. */
function remover<T>(list: T[], item: T): () => void {
  list.push(item);
  return () => {
    const i = list.indexOf(item);
    if (i >= 0) list.splice(i, 1);
  };
}
