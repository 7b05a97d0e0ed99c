/**
 * A head for any identity (sex, age, ancestry) built from the identity source (identity-source.ts), as the build
 * script builds it from base.obj moved by the identity's macro targets: the same code, so the same numbers. Pure: runs
 * in the browser and in workers.
 */
import type { HeadLevel } from '../head-levels';
import { macroTargetWeights, type Identity } from '../identity';
import type { PolyMesh } from '../polymesh';
import {
  type BuiltHead,
  buildHeadLevel,
  buildHeadParts,
  DECIMETRE,
  type HeadSource,
  LEVELS,
  POSITION_GROUPS,
  TONGUE_GROUP,
} from './head-build';
import { CUT_HEAD_GROUP, type IdentitySource, type IdentitySourceGroup } from './identity-source';

/**
 * The stored vertices' positions (xyz, decimetres) for `identity`: the base mesh's moved by the identity's macro
 * targets as applyMacroTargets moves them, then all moved back together by the head's mean offset; `null` gives the
 * base mesh's own. The targets shape the whole body, so a shorter person's head also sits up to 20 cm lower: taken
 * back, every identity's head stands where the default head does, and a switch keeps the camera's framing.
 */
function identityPositions(source: IdentitySource, identity: Identity | null): Float64Array {
  const P = source.positions.slice();
  if (identity === null) return P;
  for (const { target, weight } of macroTargetWeights(identity)) {
    const offsets = source.targets.get(target);
    if (!offsets) throw new Error(`identity-source.bin: the target "${target}" is missing`);
    for (let i = 0; i < P.length; i++) P[i] += weight * offsets[i];
  }
  const head = groupOf(source, CUT_HEAD_GROUP).vertices;
  const shift = [0, 0, 0];
  for (const v of head) for (let k = 0; k < 3; k++) shift[k] += (P[3 * v + k] - source.positions[3 * v + k]) / head.length;
  for (let i = 0; i < P.length; i++) P[i] -= shift[i % 3];
  return P;
}

/** The group's vertices' positions, in its order. */
function gather(P: Float64Array, group: IdentitySourceGroup): Float64Array {
  const out = new Float64Array(3 * group.vertices.length);
  group.vertices.forEach((v, i) => out.set(P.subarray(3 * v, 3 * v + 3), 3 * i));
  return out;
}

function groupOf(source: IdentitySource, name: string): IdentitySourceGroup {
  const group = source.groups.get(name);
  if (!group) throw new Error(`identity-source.bin: the group "${name}" is missing`);
  return group;
}

/** The group as a polygon mesh at the given positions of the stored vertices (its faces are shared, not copied). */
function polyMesh(P: Float64Array, group: IdentitySourceGroup): PolyMesh {
  return { positions: gather(P, group), faceStart: group.faceStart, corners: group.corners, cornerUVs: group.cornerUVs };
}

/** What buildHeadLevels would read of base.obj moved by the identity's targets (the base mesh's cut start). */
function identityHeadSource(source: IdentitySource, identity: Identity | null): HeadSource {
  const P = identityPositions(source, identity);
  const head = groupOf(source, CUT_HEAD_GROUP);
  return {
    cut: { mesh: polyMesh(P, head), neckLoop: source.neckLoop, sourceVertex: head.vertices.map((v) => source.vertices[v]) },
    groups: new Map(POSITION_GROUPS.map((name) => [name, gather(P, groupOf(source, name))])),
    tongue: polyMesh(P, groupOf(source, TONGUE_GROUP)),
  };
}

/**
 * Builds one resolution of the head of `identity` (a checked one: checkIdentity or STOCK_IDENTITIES), or of the base
 * mesh with no targets for `null` (the default head): exactly what `npm run build:models` writes for that level (for a
 * person, what it writes with `--identity`, moved as a whole to stand where the default head does).
 */
export function buildIdentityHead(source: IdentitySource, identity: Identity | null, level: HeadLevel): BuiltHead {
  const plan = LEVELS.find((l) => l.name === level);
  if (!plan) throw new Error(`buildIdentityHead: level: expected one of ${LEVELS.map((l) => l.name).join(', ')}, got ${level}`);
  const headSource = identityHeadSource(source, identity);
  return buildHeadLevel(headSource.cut, buildHeadParts(headSource), plan);
}

/**
 * The low level's skin for `identity` (or the base mesh's for `null`), cheaply: xyz per render vertex in metres, in
 * the order of head-low.glb's skin positions (seam copies repeat; `source.skinRenderVertex` maps each to its stored
 * vertex). Equal, after rounding to float32, to what buildIdentityHead(source, identity, 'low') gives.
 */
export function identitySkinPositions(source: IdentitySource, identity: Identity | null): Float64Array {
  const P = identityPositions(source, identity);
  const out = new Float64Array(3 * source.skinRenderVertex.length);
  source.skinRenderVertex.forEach((v, r) => {
    for (let k = 0; k < 3; k++) out[3 * r + k] = P[3 * v + k] * DECIMETRE;
  });
  return out;
}
