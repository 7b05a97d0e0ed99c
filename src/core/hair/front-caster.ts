/**
 * Rays cast into a mesh from the front (along -z, the face toward +z): the frontmost hit at a point (x, y) of the
 * front view, with its triangle and barycentric weights. Triangles are binned by their extent in x and y once, so a
 * cast tests only the triangles of one cell. Pure: no three.js, no DOM.
 */

/** Where a ray hit: the triangle, the barycentric weights of its three corners, and the hit's depth. */
export interface FrontHit {
  triangle: number;
  /** Weights of the triangle's corners 0, 1 and 2 (they sum to 1). */
  w0: number;
  w1: number;
  w2: number;
  z: number;
}

/** Binned triangles of a mesh, for casts from the front. */
export class FrontCaster {
  private readonly minX: number;
  private readonly minY: number;
  private readonly columns: number;
  private readonly rows: number;
  /** Cell c's triangles are `entries[starts[c] .. starts[c + 1])`. */
  private readonly starts: Uint32Array;
  private readonly entries: Uint32Array;

  /** Bins `triangles` (three vertex indices each into `positions`, xyz per vertex) in square cells of `cell` metres. */
  constructor(
    private readonly positions: ArrayLike<number>,
    private readonly triangles: ArrayLike<number>,
    private readonly cell = 0.002,
  ) {
    let minX = Infinity,
      minY = Infinity,
      maxX = -Infinity,
      maxY = -Infinity;
    for (let i = 0; i < positions.length; i += 3) {
      minX = Math.min(minX, positions[i]);
      maxX = Math.max(maxX, positions[i]);
      minY = Math.min(minY, positions[i + 1]);
      maxY = Math.max(maxY, positions[i + 1]);
    }
    this.minX = minX;
    this.minY = minY;
    this.columns = Math.max(1, Math.ceil((maxX - minX) / cell) + 1);
    this.rows = Math.max(1, Math.ceil((maxY - minY) / cell) + 1);
    // Two passes over the triangles: count per cell, then fill one flat list (instead of an array per cell).
    const cells = this.columns * this.rows;
    const counts = new Uint32Array(cells + 1);
    this.forEachCell((k) => counts[k]++);
    this.starts = new Uint32Array(cells + 1);
    for (let k = 1; k <= cells; k++) this.starts[k] = this.starts[k - 1] + counts[k - 1];
    this.entries = new Uint32Array(this.starts[cells]);
    const cursor = this.starts.slice();
    this.forEachCell((k, t) => (this.entries[cursor[k]++] = t));
  }

  /** Calls `fn` for each cell each triangle's extent covers. */
  private forEachCell(fn: (cell: number, triangle: number) => void): void {
    for (let t = 0; 3 * t < this.triangles.length; t++) {
      const [c0, c1, r0, r1] = this.extent(t);
      for (let r = r0; r <= r1; r++) for (let c = c0; c <= c1; c++) fn(r * this.columns + c, t);
    }
  }

  /** The cells a triangle's extent in x and y covers: first and last column, first and last row. */
  private extent(t: number): [number, number, number, number] {
    const p = this.positions;
    let x0 = Infinity,
      x1 = -Infinity,
      y0 = Infinity,
      y1 = -Infinity;
    for (let k = 0; k < 3; k++) {
      const v = 3 * this.triangles[3 * t + k];
      x0 = Math.min(x0, p[v]);
      x1 = Math.max(x1, p[v]);
      y0 = Math.min(y0, p[v + 1]);
      y1 = Math.max(y1, p[v + 1]);
    }
    return [this.column(x0), this.column(x1), this.row(y0), this.row(y1)];
  }

  private column(x: number): number {
    return Math.min(this.columns - 1, Math.max(0, Math.floor((x - this.minX) / this.cell)));
  }

  private row(y: number): number {
    return Math.min(this.rows - 1, Math.max(0, Math.floor((y - this.minY) / this.cell)));
  }

  /**
   * The frontmost hit at (x, y) below `maxZ` (a ray from the front that starts at `maxZ`), into `out`; false where
   * the ray misses the mesh.
   */
  cast(x: number, y: number, out: FrontHit, maxZ = Infinity): boolean {
    const c = Math.floor((x - this.minX) / this.cell);
    const r = Math.floor((y - this.minY) / this.cell);
    if (c < 0 || r < 0 || c >= this.columns || r >= this.rows) return false;
    const k = r * this.columns + c;
    const p = this.positions;
    let best = -Infinity;
    for (let e = this.starts[k]; e < this.starts[k + 1]; e++) {
      const t = this.entries[e];
      const a = 3 * this.triangles[3 * t],
        b = 3 * this.triangles[3 * t + 1],
        d = 3 * this.triangles[3 * t + 2];
      // Barycentric weights of (x, y) in the triangle's projection onto the xy plane.
      const ax = p[a],
        ay = p[a + 1],
        bx = p[b],
        by = p[b + 1],
        dx = p[d],
        dy = p[d + 1];
      const det = (by - dy) * (ax - dx) + (dx - bx) * (ay - dy);
      if (Math.abs(det) < 1e-18) continue;
      const w0 = ((by - dy) * (x - dx) + (dx - bx) * (y - dy)) / det;
      const w1 = ((dy - ay) * (x - dx) + (ax - dx) * (y - dy)) / det;
      const w2 = 1 - w0 - w1;
      if (w0 < -1e-9 || w1 < -1e-9 || w2 < -1e-9) continue;
      const z = w0 * p[a + 2] + w1 * p[b + 2] + w2 * p[d + 2];
      if (z > best && z <= maxZ) {
        best = z;
        out.triangle = t;
        out.w0 = w0;
        out.w1 = w1;
        out.w2 = w2;
        out.z = z;
      }
    }
    return best > -Infinity;
  }
}
