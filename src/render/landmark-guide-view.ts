import {
  BufferAttribute,
  BufferGeometry,
  Group,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  Raycaster,
  SphereGeometry,
  Vector2,
  Vector3,
} from 'three';
import type { TriangleMesh } from '../core/head/head-mesh';
import type { Vec3 } from '../core/rig/rig-types';
import type { HeadView } from './head-view';

/** A pointer that moves less than this (px) between press and release clicks rather than drags (turns the view). */
const CLICK_SLOP = 4;

/**
 * Shows a head's skin on its own, in place of the face's head, for landmarks to be placed on it by clicking: each click
 * on the skin (a plain three.js raycast: one ray per click) is reported with its point, and placed points show as small
 * balls. `dispose` takes it all off the scene and frees it.
 */
export class LandmarkGuideView {
  private readonly group = new Group();
  private readonly mesh: Mesh;
  private readonly markers: Mesh[] = [];
  private readonly markerGeometry: SphereGeometry;
  private readonly markerMaterial = new MeshBasicMaterial({ color: 0xffd54f, depthTest: false });
  private readonly raycaster = new Raycaster();
  private readonly pointer = new Vector2();
  private readonly canvas: HTMLCanvasElement;
  private down: { x: number; y: number } | undefined;

  constructor(
    private readonly view: HeadView,
    skin: TriangleMesh,
    private readonly onPick: (point: Vec3) => void,
  ) {
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(skin.positions, 3));
    geometry.setIndex(new BufferAttribute(skin.indices, 1));
    geometry.computeVertexNormals();
    geometry.computeBoundingBox();
    this.mesh = new Mesh(geometry, new MeshStandardMaterial({ color: 0xc9a08a, roughness: 0.6 }));
    this.group.add(this.mesh);
    const size = geometry.boundingBox!.getSize(new Vector3()).length();
    this.markerGeometry = new SphereGeometry(0.006 * size, 12, 8);
    view.scene.add(this.group);
    view.frameBounds(geometry.boundingBox!);
    this.canvas = view.renderer.domElement;
    this.canvas.addEventListener('pointerdown', this.onDown);
    this.canvas.addEventListener('pointerup', this.onUp);
  }

  /** Shows the placed points (replacing those shown). */
  showPoints(points: readonly Vec3[]): void {
    for (const m of this.markers.splice(0)) this.group.remove(m);
    for (const p of points) {
      const m = new Mesh(this.markerGeometry, this.markerMaterial);
      m.position.fromArray(p);
      m.renderOrder = 3;
      this.group.add(m);
      this.markers.push(m);
    }
    this.view.invalidate();
  }

  /** Where a point of the skin is on the page, in client pixels. */
  locate(point: Vec3): { x: number; y: number } {
    this.view.camera.updateMatrixWorld();
    const p = new Vector3(...point).project(this.view.camera);
    const r = this.canvas.getBoundingClientRect();
    return { x: r.left + ((p.x + 1) / 2) * r.width, y: r.top + ((1 - p.y) / 2) * r.height };
  }

  dispose(): void {
    this.canvas.removeEventListener('pointerdown', this.onDown);
    this.canvas.removeEventListener('pointerup', this.onUp);
    this.view.scene.remove(this.group);
    this.view.invalidate();
    this.mesh.geometry.dispose();
    (this.mesh.material as MeshStandardMaterial).dispose();
    this.markerGeometry.dispose();
    this.markerMaterial.dispose();
  }

  private readonly onDown = (event: PointerEvent): void => {
    this.down = { x: event.clientX, y: event.clientY };
  };

  private readonly onUp = (event: PointerEvent): void => {
    const down = this.down;
    this.down = undefined;
    if (!down || Math.hypot(event.clientX - down.x, event.clientY - down.y) > CLICK_SLOP) return;
    const r = this.canvas.getBoundingClientRect();
    this.pointer.set(((event.clientX - r.left) / r.width) * 2 - 1, -((event.clientY - r.top) / r.height) * 2 + 1);
    this.view.camera.updateMatrixWorld();
    this.raycaster.setFromCamera(this.pointer, this.view.camera);
    const hit = this.raycaster.intersectObject(this.mesh, false)[0];
    if (hit) this.onPick([hit.point.x, hit.point.y, hit.point.z]);
  };
}
