/**
 * Rigid shapes the skin may not sink into: the eyeballs as spheres, the teeth as a chain of capsules. The thesis had
 * no such constraint; a closing lid needs one to slide over the eye instead of passing through it.
 */

/** A sphere, or a capsule when `b` is given (the segment a-b swept by the radius). */
export interface Collider {
  name: string;
  a: [number, number, number];
  b?: [number, number, number];
  radius: number;
}

/** Signed distance from a point to a collider's surface (negative inside) and the outward direction. */
export function colliderDistance(c: Collider, x: number, y: number, z: number, out: Float32Array | number[]): number {
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

/**
 * A chain of capsules along a dental arch: the teeth vertices are binned by their angle about a point behind the
 * incisors, each bin gives a centre and a radius that covers most of its vertices.
 */
export function archCapsules(name: string, positions: ArrayLike<number>, segments = 6): Collider[] {
  const n = Math.floor(positions.length / 3);
  if (n < 3) return [];
  let minZ = Infinity;
  let maxZ = -Infinity;
  let cx = 0;
  for (let i = 0; i < n; i++) {
    minZ = Math.min(minZ, positions[3 * i + 2]);
    maxZ = Math.max(maxZ, positions[3 * i + 2]);
    cx += positions[3 * i] / n;
  }
  const pivotZ = minZ; // behind the incisors, at the back of the arch
  const angle = (i: number): number => Math.atan2(positions[3 * i] - cx, positions[3 * i + 2] - pivotZ);
  let lo = Infinity;
  let hi = -Infinity;
  for (let i = 0; i < n; i++) {
    lo = Math.min(lo, angle(i));
    hi = Math.max(hi, angle(i));
  }
  const bins = segments + 1;
  const sum = Array.from({ length: bins }, () => [0, 0, 0, 0]);
  const binOf = (i: number): number => Math.min(bins - 1, Math.floor(((angle(i) - lo) / (hi - lo || 1)) * bins));
  for (let i = 0; i < n; i++) {
    const s = sum[binOf(i)];
    s[0] += positions[3 * i];
    s[1] += positions[3 * i + 1];
    s[2] += positions[3 * i + 2];
    s[3]++;
  }
  const centres = sum.filter((s) => s[3] > 0).map((s) => [s[0] / s[3], s[1] / s[3], s[2] / s[3]] as [number, number, number]);
  const radius = new Array(centres.length).fill(0);
  for (let i = 0; i < n; i++) {
    const b = Math.min(centres.length - 1, binOf(i));
    const c = centres[b];
    radius[b] = Math.max(radius[b], Math.hypot(positions[3 * i] - c[0], positions[3 * i + 1] - c[1], positions[3 * i + 2] - c[2]));
  }
  const out: Collider[] = [];
  for (let k = 0; k + 1 < centres.length; k++) {
    out.push({ name: `${name}-${k}`, a: centres[k], b: centres[k + 1], radius: 0.8 * Math.max(radius[k], radius[k + 1]) });
  }
  return out;
}
