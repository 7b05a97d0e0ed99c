/**
 * Keeps hair out of the skin: a point of a hair that has come to lie behind the skin near it (within `reach` of a skin
 * vertex, on the inner side of that vertex's normal) is pushed out along the normal to just in front of it. The
 * skin's lids close over each other's lashes (a closed upper lid comes down in front of the lower lid's margin), which
 * no placement at rest can foresee. The skin vertices it looks at are binned in a hashed grid at each frame, so a
 * point is tested against a few dozen of them. Pure: no three.js, no DOM; allocates nothing per frame.
 */

/** Hash table size of the grid (a power of two); cells of different places may share a bucket, which only costs tests. */
const BUCKETS = 4096;

export class SkinContact {
  /** Bucket b's vertices are `sorted[starts[b] .. starts[b + 1])`. */
  private readonly starts = new Int32Array(BUCKETS + 1);
  private readonly cursor = new Int32Array(BUCKETS);
  private readonly middle = new Float64Array(3);
  private readonly sorted: Uint32Array;
  private readonly bucketOf: Int32Array;

  /**
   * `vertices`: the skin vertices (render order) that hair may come near; `reach`: how near a vertex must be to count
   * (metres); `gap`: how far in front of the skin a pushed point is left.
   */
  constructor(
    private readonly vertices: Uint32Array,
    private readonly reach = 0.0015,
    private readonly gap = 0.00005,
  ) {
    this.sorted = new Uint32Array(vertices.length);
    this.bucketOf = new Int32Array(vertices.length);
  }

  private bucket(cx: number, cy: number, cz: number): number {
    return (Math.imul(cx, 73856093) ^ Math.imul(cy, 19349663) ^ Math.imul(cz, 83492791)) & (BUCKETS - 1);
  }

  /** Bins the vertices at the skin's current positions (xyz per render vertex); call once per skin frame. */
  bin(positions: ArrayLike<number>): void {
    const starts = this.starts;
    starts.fill(0);
    const c = 2 * this.reach;
    for (let i = 0; i < this.vertices.length; i++) {
      const v = 3 * this.vertices[i];
      const b = this.bucket(Math.floor(positions[v] / c), Math.floor(positions[v + 1] / c), Math.floor(positions[v + 2] / c));
      this.bucketOf[i] = b;
      starts[b + 1]++;
    }
    for (let b = 0; b < BUCKETS; b++) starts[b + 1] += starts[b];
    for (let b = 0; b < BUCKETS; b++) this.cursor[b] = starts[b];
    for (let i = 0; i < this.vertices.length; i++) this.sorted[this.cursor[this.bucketOf[i]]++] = this.vertices[i];
  }

  /**
   * Pushes the ribbon pairs `[from, to)` of `points` (pair i is the points 2i and 2i + 1, across a hair, xyz each)
   * that lie behind the skin near them out in front of it, each pair by the push of its middle; `positions` and
   * `normals` are the skin's as binned. Returns how many pairs it moved.
   */
  resolve(points: Float32Array, from: number, to: number, positions: ArrayLike<number>, normals: ArrayLike<number>): number {
    let moved = 0;
    const m = this.middle;
    for (let p = from; p < to; p++) {
      const a = 6 * p;
      m[0] = (points[a] + points[a + 3]) / 2;
      m[1] = (points[a + 1] + points[a + 4]) / 2;
      m[2] = (points[a + 2] + points[a + 5]) / 2;
      const x = m[0],
        y = m[1],
        z = m[2];
      // A point pushed out from behind one vertex may lie behind the next nearest: a few rounds settle it.
      for (let round = 0; round < 3 && this.push(m, positions, normals); round++);
      const dx = m[0] - x,
        dy = m[1] - y,
        dz = m[2] - z;
      if (dx === 0 && dy === 0 && dz === 0) continue;
      points[a] += dx;
      points[a + 1] += dy;
      points[a + 2] += dz;
      points[a + 3] += dx;
      points[a + 4] += dy;
      points[a + 5] += dz;
      moved++;
    }
    return moved;
  }

  /** Pushes the point `p` out in front of the skin vertex nearest it, if it is behind it; returns whether it did. */
  private push(p: Float64Array, positions: ArrayLike<number>, normals: ArrayLike<number>): boolean {
    const r = this.reach;
    const c = 2 * r;
    const x = p[0],
      y = p[1],
      z = p[2];
    // Cells twice the reach wide: the cube within reach of the point lies in the 2 x 2 x 2 cells on the sides of its
    // cell's middle that it is nearer to.
    const fx = x / c,
      fy = y / c,
      fz = z / c;
    const cx = Math.floor(fx),
      cy = Math.floor(fy),
      cz = Math.floor(fz);
    const sx = fx - cx < 0.5 ? -1 : 0,
      sy = fy - cy < 0.5 ? -1 : 0,
      sz = fz - cz < 0.5 ? -1 : 0;
    let best = -1;
    let bestD = r * r;
    for (let dx = sx; dx <= sx + 1; dx++) {
      for (let dy = sy; dy <= sy + 1; dy++) {
        for (let dz = sz; dz <= sz + 1; dz++) {
          const b = this.bucket(cx + dx, cy + dy, cz + dz);
          for (let k = this.starts[b]; k < this.starts[b + 1]; k++) {
            const v = 3 * this.sorted[k];
            const ex = x - positions[v],
              ey = y - positions[v + 1],
              ez = z - positions[v + 2];
            const d = ex * ex + ey * ey + ez * ez;
            if (d < bestD) {
              bestD = d;
              best = v;
            }
          }
        }
      }
    }
    if (best < 0) return false;
    const nx = normals[best],
      ny = normals[best + 1],
      nz = normals[best + 2];
    const depth = -((x - positions[best]) * nx + (y - positions[best + 1]) * ny + (z - positions[best + 2]) * nz);
    if (depth <= -this.gap) return false;
    const push = depth + this.gap;
    p[0] = x + push * nx;
    p[1] = y + push * ny;
    p[2] = z + push * nz;
    return true;
  }
}
