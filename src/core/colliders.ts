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
 * measures to the nearest surface point, as for spheres and capsules.
 */
export function colliderDistance(c: Collider, x: number, y: number, z: number, out: Float32Array | number[], side = 0): number {
  if (side !== 0 && c.b && c.up) {
    const d = slabFaceDistance(c, x, y, z, side, out);
    if (d !== null) return d;
  }
  let px = c.a[0];
  let py = c.a[1];
  let pz = c.a[2];
  if (c.b) {
    const sx = c.b[0] - c.a[0];
    const sy = c.b[1] - c.a[1];
    const sz = c.b[2] - c.a[2];
    const len2 = sx * sx + sy * sy + sz * sz;
    let t = len2 > 0 ? ((x - c.a[0]) * sx + (y - c.a[1]) * sy + (z - c.a[2]) * sz) / len2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    px += t * sx;
    py += t * sy;
    pz += t * sz;
    if (c.up) {
      const ux = c.up[0];
      const uy = c.up[1];
      const uz = c.up[2];
      const up2 = ux * ux + uy * uy + uz * uz;
      let u = up2 > 0 ? ((x - c.a[0]) * ux + (y - c.a[1]) * uy + (z - c.a[2]) * uz) / up2 : 0;
      u = u < 0 ? 0 : u > 1 ? 1 : u;
      px += u * ux;
      py += u * uy;
      pz += u * uz;
    }
  }
  const dx = x - px;
  const dy = y - py;
  const dz = z - pz;
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
  return d - c.radius;
}

/** The side (+1 or -1) of a slab's plane a point lies on; 0 for colliders that are not slabs. */
export function slabSide(c: Collider, x: number, y: number, z: number): number {
  if (!c.b || !c.up) return 0;
  const [nx, ny, nz] = slabNormal(c);
  return (x - c.a[0]) * nx + (y - c.a[1]) * ny + (z - c.a[2]) * nz >= 0 ? 1 : -1;
}

/** Unit normal of a slab's rectangle, (b - a) x up. */
function slabNormal(c: Collider): [number, number, number] {
  const b = c.b!;
  const up = c.up!;
  const sx = b[0] - c.a[0], sy = b[1] - c.a[1], sz = b[2] - c.a[2];
  const nx = sy * up[2] - sz * up[1], ny = sz * up[0] - sx * up[2], nz = sx * up[1] - sy * up[0];
  const length = Math.sqrt(nx * nx + ny * ny + nz * nz) || 1;
  return [nx / length, ny / length, nz / length];
}

/** Distance along the slab's normal toward `side` when the point lies over the slab's face, else null. */
function slabFaceDistance(c: Collider, x: number, y: number, z: number, side: number, out: Float32Array | number[]): number | null {
  const b = c.b!;
  const up = c.up!;
  const rx = x - c.a[0], ry = y - c.a[1], rz = z - c.a[2];
  const sx = b[0] - c.a[0], sy = b[1] - c.a[1], sz = b[2] - c.a[2];
  const t = (rx * sx + ry * sy + rz * sz) / (sx * sx + sy * sy + sz * sz || 1);
  const u = (rx * up[0] + ry * up[1] + rz * up[2]) / (up[0] * up[0] + up[1] * up[1] + up[2] * up[2] || 1);
  if (t < 0 || t > 1 || u < 0 || u > 1) return null;
  // The face's normal, without allocating: (b - a) x up.
  let nx = sy * up[2] - sz * up[1];
  let ny = sz * up[0] - sx * up[2];
  let nz = sx * up[1] - sy * up[0];
  const length = Math.sqrt(nx * nx + ny * ny + nz * nz);
  if (length === 0) return null;
  const k = side / length;
  nx *= k;
  ny *= k;
  nz *= k;
  out[0] = nx;
  out[1] = ny;
  out[2] = nz;
  return rx * nx + ry * ny + rz * nz - c.radius;
}

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
