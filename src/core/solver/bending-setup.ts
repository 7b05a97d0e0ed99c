/**
 * The bending constraint's per-vertex setup: its stiffness from the wrinkle spacing (thesis 3.1.2 wishes for such a
 * skin parameter), split into passes, and the fixed values a frame's bending loop reads (see projectBendingPart).
 */
import { allocate, type Memory } from './memory';
import type { SkinParameters } from './skin-parameters';
import type { SkinTopology } from './topology';

/**
 * Relates the bending stiffness to the wavelength. For the scalar Laplacian constraint on the normal displacement,
 * projected once per outer iteration as the position constraint is, small-slope theory gives
 * lambda = 2 pi h (s_b / (C s_p))^(1/4) for the mesh spacing h across the folds (`SkinTopology.spacing`, the finest
 * direction's, so that every mesh folds at the asked spacing: docs/solver-notes.md, "Bending"); C was measured on
 * triangle grids (see tests).
 */
export const BENDING_CALIBRATION = 6;

/**
 * The most bending share one projection takes; a vertex that needs more is projected in passes of equal parts. The
 * share grows as the spacing to the -4th power, so fine skin asks for whole-strength bending, which against the
 * muscles' hold leaves vertices circling for good; the same share in thirds converges (docs/solver-notes.md).
 */
const MAX_BENDING_SHARE = 0.35;

/**
 * The most bending stiffness fine skin at a collider (and the ring around it) gets, and the lips' red at any spacing.
 * The lids over the eyes and the lips over the teeth are meshed finely, so bending there asks for whole-strength
 * projections; those and the collider's push, every outer iteration, hand the skin back and forth without end
 * (docs/solver-notes.md, "Bending"). A quarter keeps them converging; the folds there are set by the collider.
 */
const COLLIDER_BENDING_STIFFNESS = 0.25;
/**
 * The most bending stiffness coarse skin at a collider gets, and the spacings (metres) between which the cap goes
 * from COLLIDER_BENDING_STIFFNESS to it. Coarse skin capped at a quarter bends too weakly to keep its folds apart:
 * under the lower lip the medium head's skin (1.3 to 1.9 mm apart) rippled 4 mm apart under disgust, with 40 % of its
 * folds' power under 4 mm. The high head's (0.6 to 1.0 mm) tangles at more (docs/solver-notes.md, "The cap at the
 * colliders by spacing").
 */
const COARSE_COLLIDER_BENDING_STIFFNESS = 0.4;
const FINE_COLLIDER_SPACING = 0.0008;
const COARSE_COLLIDER_SPACING = 0.0012;
/**
 * Skin within this height (metres) of the mouth's corners keeps the quarter at any spacing: the lips' red, and the
 * skin beside the corners at their height. The red is thin and soft over the lip's muscle and gathers into fine lines
 * when the lips purse (AU18); at the coarse cap it lost a fifth of those folds. A band by height, not a map of the red:
 * the head carries no such map, and the band's width (5, 7 or 9 mm) moved settling frame counts both ways.
 */
const RED_REACH = 0.007;

/** The most bending stiffness skin at a collider with this spacing gets: a quarter when fine, more when coarse. */
export function colliderBendingCap(spacing: number): number {
  const t = (spacing - FINE_COLLIDER_SPACING) / (COARSE_COLLIDER_SPACING - FINE_COLLIDER_SPACING);
  const share = Math.min(1, Math.max(0, t));
  return COLLIDER_BENDING_STIFFNESS + share * (COARSE_COLLIDER_BENDING_STIFFNESS - COLLIDER_BENDING_STIFFNESS);
}

/**
 * Sets each vertex's bending passes per outer iteration, its share per pass (`stiffness`) and its step per unit of the
 * constraint (`gain`) for the parameters `next`; returns the most passes any vertex takes. `mouthHeight`: the mouth
 * corners' height, null for a skin without a mouth.
 */
export function setBendingShares(
  topology: SkinTopology,
  next: SkinParameters,
  colliderVertices: Uint32Array,
  mouthHeight: number | null,
  bendPasses: Uint8Array,
  bendStiffness: Float32Array,
  bendGain: Float32Array,
): number {
  const n = topology.vertexCount;
  const twoPi = 2 * Math.PI;
  for (let v = 0; v < n; v++) {
    const h = topology.spacing[v];
    const ratio = next.wrinkleSpacing > 0 && h > 0 ? next.wrinkleSpacing / (twoPi * h) : 0;
    // Up to a whole share, in passes of at most MAX_BENDING_SHARE.
    const share = Math.min(1, BENDING_CALIBRATION * next.positionStiffness * ratio ** 4);
    const passes = Math.max(1, Math.ceil(share / MAX_BENDING_SHARE));
    bendPasses[v] = passes;
    bendStiffness[v] = share / passes;
  }
  // Skin at a collider and the ring around it: one pass, see COLLIDER_BENDING_STIFFNESS.
  const start = topology.neighbourStart;
  const nb = topology.neighbours;
  const rest = topology.rest;
  const cap = (v: number): void => {
    const red = mouthHeight !== null && Math.abs(rest[3 * v + 1] - mouthHeight) <= RED_REACH;
    const most = red ? COLLIDER_BENDING_STIFFNESS : colliderBendingCap(topology.spacing[v]);
    bendStiffness[v] = Math.min(most, bendPasses[v] * bendStiffness[v]);
    bendPasses[v] = 1;
  };
  for (let j = 0; j < colliderVertices.length; j++) {
    const v = colliderVertices[j];
    cap(v);
    for (let k = start[v]; k < start[v + 1]; k++) cap(nb[k]);
  }
  let maxBendPasses = 1;
  for (let v = 0; v < n; v++) {
    if (bendPasses[v] > maxBendPasses) maxBendPasses = bendPasses[v];
    // The share over the gradient's squared norm, 1 + 1 / degree (see projectBendingPart).
    const degree = start[v + 1] - start[v];
    bendGain[v] = degree > 0 ? bendStiffness[v] / (1 + 1 / degree) : 0;
  }
  return maxBendPasses;
}

/**
 * The neighbours' mean height above each vertex at rest, along the vertex's rest normal: what the bending constraint
 * takes away from the same height now, so that a frame reads only the current positions.
 */
export function bendingAtRest(topology: SkinTopology, offsets: Uint32Array): Float64Array {
  const X = topology.rest;
  const N = topology.restNormals;
  const start = topology.neighbourStart;
  const out = new Float64Array(X.length / 3);
  for (let v = 0; v < out.length; v++) {
    const degree = start[v + 1] - start[v];
    if (degree === 0) continue;
    const i = 3 * v;
    let mean = 0;
    for (let j = start[v]; j < start[v + 1]; j++) {
      const k = offsets[j];
      mean += X[k] * N[i] + X[k + 1] * N[i + 1] + X[k + 2] * N[i + 2];
    }
    out[v] = mean / degree - (X[i] * N[i] + X[i + 1] * N[i + 1] + X[i + 2] * N[i + 2]);
  }
  return out;
}

/** 1 / each vertex's degree (0 for none), for the bending step. */
export function inverseDegrees(topology: SkinTopology, memory: Memory): Float32Array {
  const start = topology.neighbourStart;
  const out = allocate(Float32Array, topology.vertexCount, memory);
  for (let v = 0; v < out.length; v++) {
    const degree = start[v + 1] - start[v];
    out[v] = degree > 0 ? 1 / degree : 0;
  }
  return out;
}
