import { type Box3, BufferAttribute, DynamicDrawUsage, type Sphere, type BufferGeometry, type Mesh } from 'three';

/** Where solved skin frames come from (SkinSimulation). */
export interface SkinFrameSource {
  /** Copies the newest frame (xyz per render vertex) if it was not read yet; returns whether it copied. */
  readFrame(intoPositions: Float32Array, intoNormals: Float32Array): boolean;
  /** Bounds of the frame last read: min xyz, max xyz. */
  readonly bounds: Float32Array;
}

/** What is posed on the skin (hair): told after the skin mesh took each new frame. */
export interface SkinFollower {
  skinChanged(): void;
}

/** An update range covering a whole attribute, in components. */
interface UpdateRange {
  start: number;
  count: number;
}

/**
 * Shows solved skin frames on the skin mesh: position and normal attributes updated in place (only when a new frame
 * arrived), and bounds taken from the frame instead of scanning the vertices. Nothing here allocates per frame.
 */
export class SkinView {
  private source: SkinFrameSource | undefined;
  private readonly geometry: BufferGeometry;
  private readonly positions: BufferAttribute;
  private readonly normals: BufferAttribute;
  private readonly positionRange: UpdateRange;
  private readonly normalRange: UpdateRange;
  private followers: readonly SkinFollower[] = [];

  /** Prepares the mesh's attributes for per-frame updates; call before the mesh is first rendered. */
  constructor(mesh: Mesh) {
    this.geometry = mesh.geometry;
    if (!this.geometry.getAttribute('normal')) this.geometry.computeVertexNormals();
    this.positions = dynamicCopy(this.geometry, 'position');
    this.normals = dynamicCopy(this.geometry, 'normal');
    this.positionRange = { start: 0, count: this.positions.array.length };
    this.normalRange = { start: 0, count: this.normals.array.length };
    if (!this.geometry.boundingBox) this.geometry.computeBoundingBox();
    if (!this.geometry.boundingSphere) this.geometry.computeBoundingSphere();
  }

  /** Shows the frames of a simulation from now on. */
  connect(source: SkinFrameSource): void {
    this.source = source;
  }

  /** Tells `follower` of every new frame from now on, until the returned function is called. */
  follow(follower: SkinFollower): () => void {
    this.followers = [...this.followers, follower];
    return () => {
      this.followers = this.followers.filter((f) => f !== follower);
    };
  }

  /** Copies the newest solved frame into the mesh, if one arrived since the last call; returns whether one did. */
  update(): boolean {
    const source = this.source;
    if (!source?.readFrame(this.positions.array as Float32Array, this.normals.array as Float32Array)) return false;
    // While the skin is awake nearly every vertex moves a little each frame (measured: over 95% for a forehead pull),
    // so each attribute is sent whole. The range objects are reused: addUpdateRange would allocate one per call.
    markWhole(this.positions, this.positionRange);
    markWhole(this.normals, this.normalRange);
    const b = source.bounds;
    const box = this.geometry.boundingBox as Box3;
    box.min.set(b[0], b[1], b[2]);
    box.max.set(b[3], b[4], b[5]);
    box.getBoundingSphere(this.geometry.boundingSphere as Sphere);
    for (let i = 0; i < this.followers.length; i++) this.followers[i].skinChanged();
    return true;
  }
}

/** Replaces an attribute by a Float32 copy that owns its memory, marked for frequent updates. */
function dynamicCopy(geometry: BufferGeometry, name: string): BufferAttribute {
  const old = geometry.getAttribute(name);
  const array = new Float32Array(3 * old.count);
  for (let i = 0; i < old.count; i++) {
    array[3 * i] = old.getX(i);
    array[3 * i + 1] = old.getY(i);
    array[3 * i + 2] = old.getZ(i);
  }
  const attribute = new BufferAttribute(array, 3).setUsage(DynamicDrawUsage);
  geometry.setAttribute(name, attribute);
  return attribute;
}

function markWhole(attribute: BufferAttribute, range: UpdateRange): void {
  attribute.clearUpdateRanges();
  attribute.updateRanges.push(range);
  attribute.needsUpdate = true;
}
