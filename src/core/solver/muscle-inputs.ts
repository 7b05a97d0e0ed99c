/** The muscles' pull on the skin as the solver takes it, and the checks and writes every entry point shares. */

/**
 * Throws an error naming the first bad muscle-target input: a vertex that is not one of `vertexCount`, a target
 * coordinate that is not finite, a weight outside 0..1. Every entry point checks with this before changing anything.
 */
export function checkMuscleTargets(
  vertexCount: number,
  vertices: ArrayLike<number>,
  targets: ArrayLike<number>,
  weight: number,
  normalWeight: number,
): void {
  const isArrayLike = (a: unknown): boolean => Array.isArray(a) || ArrayBuffer.isView(a);
  if (!isArrayLike(vertices) || !isArrayLike(targets)) throw new Error('setMuscleTargets: vertices and targets must be arrays of numbers');
  if (targets.length !== 3 * vertices.length) {
    throw new Error(`setMuscleTargets: ${vertices.length} vertices need ${3 * vertices.length} target coordinates, got ${targets.length}`);
  }
  for (const [name, w] of [
    ['weight', weight],
    ['normal weight', normalWeight],
  ] as const) {
    if (typeof w !== 'number' || !Number.isFinite(w) || w < 0 || w > 1)
      throw new Error(`setMuscleTargets: ${name} must be a finite number from 0 to 1, got ${w}`);
  }
  for (let i = 0; i < vertices.length; i++) {
    const v = vertices[i];
    if (!Number.isInteger(v) || v < 0 || v >= vertexCount)
      throw new Error(`setMuscleTargets: vertex ${i} is ${v}, not one of the ${vertexCount} skin vertices`);
    for (let k = 0; k < 3; k++) {
      const t = targets[3 * i + k];
      if (typeof t !== 'number' || !Number.isFinite(t)) {
        throw new Error(`setMuscleTargets: the target of vertex ${v} (entry ${i}) has a non-finite ${'xyz'[k]} coordinate: ${t}`);
      }
    }
  }
}

/**
 * The muscles' pull on each vertex, as the rig computes it (MuscleRig.compute) and the solver takes it: the solver's
 * buffers, the worker's control block and a batch of inputs all have this shape.
 */
export interface MuscleInputs {
  /** Muscle target of each vertex, xyz. */
  targets: Float32Array;
  /** Muscle weight along the skin's surface, per vertex, 0..1. */
  weights: Float32Array;
  /** Muscle weight along the rest normal, per vertex, 0..1. */
  normalWeights: Float32Array;
}

/** Writes checked muscle targets (see checkMuscleTargets) and both weights for some vertices into `into`. */
export function writeMuscleTargets(
  into: MuscleInputs,
  vertices: ArrayLike<number>,
  targets: ArrayLike<number>,
  weight: number,
  normalWeight: number,
): void {
  const { targets: T, weights: W, normalWeights: WN } = into;
  for (let i = 0; i < vertices.length; i++) {
    const v = vertices[i];
    T[3 * v] = targets[3 * i];
    T[3 * v + 1] = targets[3 * i + 1];
    T[3 * v + 2] = targets[3 * i + 2];
    W[v] = weight;
    WN[v] = normalWeight;
  }
}

/** Releases every vertex: targets back at rest, both weights 0. */
export function clearMuscleInputs(into: MuscleInputs, rest: Float32Array): void {
  into.targets.set(rest);
  into.weights.fill(0);
  into.normalWeights.fill(0);
}
