/**
 * Rigid shapes the skin may not sink into: the eyeballs as spheres, the teeth as a chain of capsules. The thesis had
 * no such constraint; a closing lid needs one to slide over the eye instead of passing through it.
 */

/**
 * A sphere around `a`; a capsule when `b` is given (the segment a-b swept by the radius); a slab when `up` is given
 * too (the rectangle a, b, b + up, a + up swept by the radius, with `up` perpendicular to b - a).
 */
export interface Collider {
  name: string;
  a: [number, number, number];
  b?: [number, number, number];
  up?: [number, number, number];
  radius: number;
}

/**
 * Signed distance from a point to a collider's surface (negative inside) and the outward direction.
 *
 * `side` (+1 or -1, see `slabSide`) makes a slab one-sided where the point lies over its face: the distance is
 * measured along the slab's normal toward that side, so a point that went through the wall (or around its edge and
 * down behind it) is pushed back to the side it started on instead of being held on the wrong one. 0 (the default)
 * measures to the nearest surface point, as for spheres and capsules. The same code as the collision loop's (see
 * shapeDistance), through a scratch shape.
 */
export function colliderDistance(c: Collider, x: number, y: number, z: number, out: Float32Array | number[], side = 0): number {
  writeColliderShape(c, scratchShape, 0);
  const d = shapeDistance(scratchShape, 0, x, y, z, scratchDirection, side);
  out[0] = scratchDirection[0];
  out[1] = scratchDirection[1];
  out[2] = scratchDirection[2];
  return d;
}

/** The side (+1 or -1) of a slab's plane a point lies on; 0 for colliders that are not slabs. */
export function slabSide(c: Collider, x: number, y: number, z: number): number {
  if (!c.b || !c.up) return 0;
  writeColliderShape(c, scratchShape, 0);
  const S = scratchShape;
  return (x - S[0]) * S[13] + (y - S[1]) * S[14] + (z - S[2]) * S[15] >= 0 ? 1 : -1;
}

/**
 * Values per collider in `colliderShapes`: a, b and up (xyz each, zero when absent), the radius; then what the
 * collision loop derives from them, so that it reads one array instead of the collider objects: the kind
 * (SHAPE_SPHERE, SHAPE_CAPSULE, SHAPE_SLAB), 1 / |b - a|^2 and 1 / |up|^2 (0 for a zero length), and a slab's unit
 * normal, (b - a) x up normalized (zero when degenerate).
 */
export const COLLIDER_SHAPE = 16;
const SHAPE_KIND = 10;
const SHAPE_SPHERE = 0;
const SHAPE_CAPSULE = 1;
const SHAPE_SLAB = 2;

/** Writes a collider's shape into `shapes`; returns whether it changed. */
export function writeColliderShape(c: Collider, shapes: Float64Array, index: number): boolean {
  const o = COLLIDER_SHAPE * index;
  let changed = false;
  for (let k = 0; k < 10; k++) {
    const value = k < 3 ? c.a[k] : k < 6 ? (c.b ? c.b[k - 3] : 0) : k < 9 ? (c.up ? c.up[k - 6] : 0) : c.radius;
    if (shapes[o + k] !== value) {
      shapes[o + k] = value;
      changed = true;
    }
  }
  const sx = shapes[o + 3] - shapes[o];
  const sy = shapes[o + 4] - shapes[o + 1];
  const sz = shapes[o + 5] - shapes[o + 2];
  const ux = shapes[o + 6];
  const uy = shapes[o + 7];
  const uz = shapes[o + 8];
  const s2 = sx * sx + sy * sy + sz * sz;
  const u2 = ux * ux + uy * uy + uz * uz;
  shapes[o + SHAPE_KIND] = !c.b ? SHAPE_SPHERE : !c.up ? SHAPE_CAPSULE : SHAPE_SLAB;
  shapes[o + 11] = s2 > 0 ? 1 / s2 : 0;
  shapes[o + 12] = u2 > 0 ? 1 / u2 : 0;
  const nx = sy * uz - sz * uy;
  const ny = sz * ux - sx * uz;
  const nz = sx * uy - sy * ux;
  const length = Math.sqrt(nx * nx + ny * ny + nz * nz);
  const k = length > 0 ? 1 / length : 0;
  shapes[o + 13] = nx * k;
  shapes[o + 14] = ny * k;
  shapes[o + 15] = nz * k;
  return changed;
}

/**
 * Signed distance from a point to the collider shape at `o` in `shapes` and the outward direction (into `out`): the
 * collision loop's form of colliderDistance (see colliders.ts), with the same one-sided slabs for `side` +1 or -1.
 */
export function shapeDistance(S: Float64Array, o: number, x: number, y: number, z: number, out: Float32Array, side: number): number {
  const kind = S[o + SHAPE_KIND];
  const rx = x - S[o];
  const ry = y - S[o + 1];
  const rz = z - S[o + 2];
  let px = 0;
  let py = 0;
  let pz = 0;
  if (kind !== SHAPE_SPHERE) {
    const sx = S[o + 3] - S[o];
    const sy = S[o + 4] - S[o + 1];
    const sz = S[o + 5] - S[o + 2];
    let t = (rx * sx + ry * sy + rz * sz) * S[o + 11];
    if (kind === SHAPE_SLAB) {
      let u = (rx * S[o + 6] + ry * S[o + 7] + rz * S[o + 8]) * S[o + 12];
      const nx = S[o + 13];
      const ny = S[o + 14];
      const nz = S[o + 15];
      // Over the slab's face, a one-sided slab measures along its normal toward the point's rest side.
      if (side !== 0 && t >= 0 && t <= 1 && u >= 0 && u <= 1 && (nx !== 0 || ny !== 0 || nz !== 0)) {
        out[0] = side * nx;
        out[1] = side * ny;
        out[2] = side * nz;
        return side * (rx * nx + ry * ny + rz * nz) - S[o + 9];
      }
      u = u < 0 ? 0 : u > 1 ? 1 : u;
      px = u * S[o + 6];
      py = u * S[o + 7];
      pz = u * S[o + 8];
    }
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    px += t * sx;
    py += t * sy;
    pz += t * sz;
  }
  const dx = rx - px;
  const dy = ry - py;
  const dz = rz - pz;
  const d = Math.sqrt(dx * dx + dy * dy + dz * dz);
  if (d > 0) {
    out[0] = dx / d;
    out[1] = dy / d;
    out[2] = dz / d;
  } else {
    out[0] = 0;
    out[1] = 0;
    out[2] = 1;
  }
  return d - S[o + 9];
}

const scratchShape = new Float64Array(COLLIDER_SHAPE);
const scratchDirection = new Float32Array(3);

/**
 * A chain of slabs along a row of teeth: the teeth vertices are binned by their angle about a point behind the
 * incisors; each bin gives a point on the arch and the height of the teeth there, consecutive points a vertical
 * rectangle, and the radius is the least that encloses every vertex: a thin wall the lips can slide over.
 */
export function archSlabs(name: string, positions: ArrayLike<number>, segments = 8): Collider[] {
  const n = Math.floor(positions.length / 3);
  if (n < 3) return [];
  let minZ = Infinity;
  let cx = 0;
  for (let i = 0; i < n; i++) {
    minZ = Math.min(minZ, positions[3 * i + 2]);
    cx += positions[3 * i] / n;
  }
  const angle = (i: number): number => Math.atan2(positions[3 * i] - cx, positions[3 * i + 2] - minZ);
  let lo = Infinity;
  let hi = -Infinity;
  for (let i = 0; i < n; i++) {
    lo = Math.min(lo, angle(i));
    hi = Math.max(hi, angle(i));
  }
  const bins = segments + 1;
  const binOf = (i: number): number => Math.min(bins - 1, Math.floor(((angle(i) - lo) / (hi - lo || 1)) * bins));
  const sum = Array.from({ length: bins }, () => ({ x: 0, z: 0, count: 0, minY: Infinity, maxY: -Infinity }));
  for (let i = 0; i < n; i++) {
    const s = sum[binOf(i)];
    s.x += positions[3 * i];
    s.z += positions[3 * i + 2];
    s.minY = Math.min(s.minY, positions[3 * i + 1]);
    s.maxY = Math.max(s.maxY, positions[3 * i + 1]);
    s.count++;
  }
  const points = sum.filter((s) => s.count > 0).map((s) => ({ x: s.x / s.count, z: s.z / s.count, minY: s.minY, maxY: s.maxY }));
  const slabs: Collider[] = [];
  for (let k = 0; k + 1 < points.length; k++) {
    const p = points[k];
    const q = points[k + 1];
    const bottom = Math.min(p.minY, q.minY);
    const top = Math.max(p.maxY, q.maxY);
    slabs.push({ name: `${name}-${k}`, a: [p.x, bottom, p.z], b: [q.x, bottom, q.z], up: [0, top - bottom, 0], radius: 0 });
  }
  // Each slab's radius: the farthest of its own vertices (those nearest to its rectangle) from the rectangle.
  const dir = [0, 0, 0];
  const radius = new Array(slabs.length).fill(0);
  for (let i = 0; i < n; i++) {
    let best = 0;
    let bestD = Infinity;
    for (let k = 0; k < slabs.length; k++) {
      const d = colliderDistance(slabs[k], positions[3 * i], positions[3 * i + 1], positions[3 * i + 2], dir);
      if (d < bestD) {
        bestD = d;
        best = k;
      }
    }
    radius[best] = Math.max(radius[best], bestD);
  }
  slabs.forEach((slab, k) => (slab.radius = radius[k]));
  return slabs;
}
