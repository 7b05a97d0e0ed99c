import { type Box3, type Matrix4, PerspectiveCamera, Vector3 } from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { boxCentre } from './head-model';
import { CAMERA_DEFAULTS, CAMERA_RANGES, type CameraOptions } from './view-options';
import { checkOptions } from '../core/check';

const DEGREES = Math.PI / 180;
/** Camera updates allowed for the orbit controls' damping to come to rest (before a capture's first picture). */
const MAX_DAMPING_UPDATES = 10_000;

/** The view's camera and its orbit controls: framing a head from the front, turning about it, projecting points onto the page. */
export class ViewCamera {
  readonly camera: PerspectiveCamera;
  readonly controls: OrbitControls;
  /** The framing camera's offset from the head's centre (CAMERA_DEFAULTS), and scratch for reading the camera. */
  private readonly home = new Vector3(0, 0, 1);
  private readonly scratch = new Vector3();

  /** `moved` is told whenever the camera is placed (the view draws then). */
  constructor(
    fov: number,
    canvas: HTMLCanvasElement,
    private readonly moved: () => void,
  ) {
    this.camera = new PerspectiveCamera(fov, 1, 0.01, 20);
    this.camera.position.set(0, 0.7, 1);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.enableDamping = true;
    this.controls.minDistance = 0.15;
    this.controls.maxDistance = 2.5;
  }

  /** Sets the camera's aspect ratio (width / height) to the canvas's. */
  setAspect(aspect: number): void {
    this.camera.aspect = aspect;
    this.camera.updateProjectionMatrix();
  }

  /** Brings the damping after a drag to rest at once. */
  stop(): void {
    for (let i = 0; i < MAX_DAMPING_UPDATES && this.controls.update(); i++);
  }

  /** Points the camera at the middle of `bounds` from the front (+z), far enough to see it whole; returns the middle. */
  fit(bounds: Box3): Vector3 {
    const centre = boxCentre(bounds);
    const size = bounds.getSize(new Vector3());
    const fit = (0.5 * Math.max(size.y, size.x / this.camera.aspect)) / Math.tan((this.camera.fov * Math.PI) / 360);
    const distance = 1.15 * fit + size.z / 2;
    this.controls.target.copy(centre);
    this.home.set(0, 0.03 * size.y, distance);
    this.place(CAMERA_DEFAULTS);
    return centre;
  }

  /** Places the camera by some CameraOptions; throws, changing nothing, on an unknown option or a bad value. */
  set(partial: Partial<CameraOptions>): void {
    const checked = checkOptions<CameraOptions>('setCamera', partial, CAMERA_DEFAULTS, { ranges: CAMERA_RANGES });
    this.place({ ...this.options(), ...checked });
  }

  /** Where the camera is now, as CameraOptions (after the user's orbit drags too). */
  options(): CameraOptions {
    const offset = this.scratch.subVectors(this.camera.position, this.controls.target);
    const home = this.home;
    // Rounded to a millionth (floating-point noise), and -0 read as 0.
    const round = (x: number): number => Math.round(x * 1e6) / 1e6 + 0;
    const pitch = Math.asin(offset.y / offset.length()) - Math.atan2(home.y, home.z);
    return {
      yaw: round(Math.atan2(offset.x, offset.z) / DEGREES),
      pitch: round(pitch / DEGREES),
      distance: round(offset.length() / home.length()),
    };
  }

  /** Where a point of a model whose world matrix is `matrixWorld` is on `canvas`, in client pixels. */
  project(point: readonly [number, number, number], matrixWorld: Matrix4, canvas: HTMLCanvasElement): { x: number; y: number } {
    this.camera.updateMatrixWorld();
    const p = this.scratch.set(point[0], point[1], point[2]).applyMatrix4(matrixWorld).project(this.camera);
    const r = canvas.getBoundingClientRect();
    return { x: r.left + ((p.x + 1) / 2) * r.width, y: r.top + ((1 - p.y) / 2) * r.height };
  }

  dispose(): void {
    this.controls.dispose();
  }

  private place(o: CameraOptions): void {
    const home = this.home;
    const pitch = Math.atan2(home.y, home.z) + o.pitch * DEGREES;
    const r = o.distance * home.length();
    const yaw = o.yaw * DEGREES;
    this.camera.position
      .set(Math.sin(yaw) * Math.cos(pitch), Math.sin(pitch), Math.cos(yaw) * Math.cos(pitch))
      .multiplyScalar(r)
      .add(this.controls.target);
    this.controls.update();
    this.moved();
  }
}
