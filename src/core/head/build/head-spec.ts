/**
 * The shape of a built head model as plain data: nodes, their triangle parts and materials. Pure, so that the head can
 * be built in the browser as well as written to GLB by the build script (scripts/model/glb.ts).
 */

/** An indexed triangle geometry with optional vertex colours. */
export interface TriGeometry {
  positions: Float32Array;
  normals: Float32Array;
  uvs: Float32Array;
  colors?: Float32Array;
  indices: Uint32Array;
}

/** A physically based material as glTF describes it. */
export interface MaterialSpec {
  name: string;
  baseColor: [number, number, number, number];
  roughness: number;
  metallic?: number;
  blend?: boolean;
  doubleSided?: boolean;
}

/** One primitive: geometry plus its material. */
export interface PartSpec {
  geometry: TriGeometry;
  material: MaterialSpec;
}

/** A node of the model; `translation` places its origin (its pivot) in the parent's frame. */
export interface NodeSpec {
  name: string;
  translation?: [number, number, number];
  parts?: PartSpec[];
  /** Names this node's mesh when several nodes share one (both eyes). */
  meshName?: string;
  children?: NodeSpec[];
  extras?: Record<string, unknown>;
}
