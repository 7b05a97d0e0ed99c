/**
 * Hair that rides a skin: each hair (a brow hair, a lash) is a thin ribbon anchored to one skin triangle by
 * barycentric weights, with its vertices stored in the frame the skin has at the anchor (the surface normal, a
 * tangent that turns with the triangle, and their cross product; a lash's turns with its lid, see anchorFrame).
 * Posing the hair on a solved skin rebuilds each frame from the skin's positions and normals, so a hair follows its
 * patch of skin as it moves, turns and stretches; the solver never sees the hair. Pure: no three.js, no DOM.
 */

/** Strands anchored to a skin: ribbons of `verticesPerHair` vertices each, in the frame of their anchor. */
export interface HairStrands {
  /** Number of hairs; a prefix of them can be drawn (density), as they are stored in a shuffled order. */
  count: number;
  /** Vertices of one hair's ribbon (two per point along the hair, the hair's root first). */
  verticesPerHair: number;
  /** Per hair, the anchor triangle's three skin vertices (render order). */
  corners: Uint32Array;
  /** Per hair, the anchor point's barycentric weights in that triangle. */
  weights: Float32Array;
  /**
   * Per hair, two skin vertices (render order) whose difference sets the hair's tangent (see anchorFrame): for a lash,
   * the lid margin 3 mm either side of its root; the same vertex twice where there are none. Absent: none.
   */
  tangentEnds?: Uint32Array;
  /**
   * Per hair, a point (xyz) the hair turns about, or NaN: an eye's centre for a lash, whose tarsal plate slides over
   * the eyeball, so that the lash's normal is the eyeball's radius through its root (see anchorFrame).
   */
  pivots?: Float32Array;
  /**
   * Per hair, its anchor triangle's first two edges at rest in the rest frame, as 1 / a, c / a and 1 / d for the
   * first edge's length a along the tangent and the second edge's parts c along the tangent and d along the
   * bitangent; or NaN: a hair without tangent ends or pivot (a brow hair) then turns with the rotation part of its
   * triangle's stretch, not with the first edge (see anchorFrame).
   */
  restEdges?: Float32Array;
  /** Per vertex, its place in the anchor's frame: along the tangent, the bitangent and the normal, in metres. */
  local: Float32Array;
  /** Per vertex, a brightness factor (hairs differ a little in colour, and tips are lighter than roots). */
  shade: Float32Array;
  /** Triangles of the ribbons, three vertex indices each; hair h's triangles come before hair h + 1's. */
  indices: Uint32Array;
}

/** The two vertices of the root of a hair's ribbon are its first; their midpoint is the root. */
export const ROOT_VERTICES = 2;

/**
 * The skin's frame at hair `h`'s anchor, into `out` (15 numbers): the anchor point, the tangent, the bitangent, the
 * unit normal and the skin's shading normal there (interpolated from the vertex normals). The normal is the shading
 * normal, or for a hair with a pivot (a lash) the direction from the pivot to the anchor point: a lash grows from the
 * stiff tarsal plate, which slides over the eyeball and turns about its centre with the lid, however the lid's skin
 * bunches at the margin (under AU4 and AU7 the margin's own triangles turn over). The tangent is the hair's tangent
 * ends' difference (a lash's: along the margin, 3 mm either side), or else the anchor triangle's first edge, made
 * perpendicular to the normal and, for a hair with `restEdges` (a brow hair), turned back by as much as that edge
 * turned beyond the triangle's own rotation; so the frame turns with the skin patch around the hair.
 */
export function anchorFrame(
  h: HairStrands,
  hair: number,
  positions: ArrayLike<number>,
  normals: ArrayLike<number>,
  out: Float64Array,
): void {
  const i0 = 3 * h.corners[3 * hair],
    i1 = 3 * h.corners[3 * hair + 1],
    i2 = 3 * h.corners[3 * hair + 2];
  const w0 = h.weights[3 * hair],
    w1 = h.weights[3 * hair + 1],
    w2 = h.weights[3 * hair + 2];
  let nx = w0 * normals[i0] + w1 * normals[i1] + w2 * normals[i2];
  let ny = w0 * normals[i0 + 1] + w1 * normals[i1 + 1] + w2 * normals[i2 + 1];
  let nz = w0 * normals[i0 + 2] + w1 * normals[i1 + 2] + w2 * normals[i2 + 2];
  let n = Math.sqrt(nx * nx + ny * ny + nz * nz);
  if (!(n > 1e-12)) {
    // No usable vertex normals (a sliver, or zero normals): the triangle's own.
    const ax = positions[i1] - positions[i0],
      ay = positions[i1 + 1] - positions[i0 + 1],
      az = positions[i1 + 2] - positions[i0 + 2];
    const bx = positions[i2] - positions[i0],
      by = positions[i2 + 1] - positions[i0 + 1],
      bz = positions[i2 + 2] - positions[i0 + 2];
    nx = ay * bz - az * by;
    ny = az * bx - ax * bz;
    nz = ax * by - ay * bx;
    n = Math.sqrt(nx * nx + ny * ny + nz * nz) || 1;
  }
  nx /= n;
  ny /= n;
  nz /= n;
  out[12] = nx;
  out[13] = ny;
  out[14] = nz;
  let tx = positions[i1] - positions[i0],
    ty = positions[i1 + 1] - positions[i0 + 1],
    tz = positions[i1 + 2] - positions[i0 + 2];
  const E = h.tangentEnds;
  if (E && E[2 * hair] !== E[2 * hair + 1]) {
    const e0 = 3 * E[2 * hair],
      e1 = 3 * E[2 * hair + 1];
    tx = positions[e1] - positions[e0];
    ty = positions[e1 + 1] - positions[e0 + 1];
    tz = positions[e1 + 2] - positions[e0 + 2];
  }
  const px = w0 * positions[i0] + w1 * positions[i1] + w2 * positions[i2];
  const py = w0 * positions[i0 + 1] + w1 * positions[i1 + 1] + w2 * positions[i2 + 1];
  const pz = w0 * positions[i0 + 2] + w1 * positions[i1 + 2] + w2 * positions[i2 + 2];
  const P = h.pivots;
  if (P && !Number.isNaN(P[3 * hair])) {
    const rx = px - P[3 * hair],
      ry = py - P[3 * hair + 1],
      rz = pz - P[3 * hair + 2];
    const r = Math.sqrt(rx * rx + ry * ry + rz * rz);
    if (r > 1e-12) {
      nx = rx / r;
      ny = ry / r;
      nz = rz / r;
    }
  }
  const along = tx * nx + ty * ny + tz * nz;
  tx -= along * nx;
  ty -= along * ny;
  tz -= along * nz;
  let t = Math.sqrt(tx * tx + ty * ty + tz * tz);
  if (!(t > 1e-12)) {
    // An edge along the normal: any direction across it will do, as long as it is the same at rest and now.
    tx = Math.abs(nx) < 0.9 ? 1 : 0;
    ty = Math.abs(nx) < 0.9 ? 0 : 1;
    tz = 0;
    const d = tx * nx + ty * ny;
    tx -= d * nx;
    ty -= d * ny;
    tz -= d * nz;
    t = Math.sqrt(tx * tx + ty * ty + tz * tz);
  }
  tx /= t;
  ty /= t;
  tz /= t;
  const S = h.restEdges;
  if (S && !Number.isNaN(S[3 * hair])) {
    // The skin under a brow stretches a lot (closing the lid pulls it down over the eye) and its triangles shear: their
    // first edge turns though the patch does not. The rotation part of the triangle's in-plane deformation gradient
    // F (rest edges to current, in each one's frame; the polar decomposition's angle in 2D) turns the hair instead, as
    // a stiff follicle in stretching tissue turns.
    const vx = ny * tz - nz * ty,
      vy = nz * tx - nx * tz,
      vz = nx * ty - ny * tx;
    const ex = positions[i2] - positions[i0],
      ey = positions[i2 + 1] - positions[i0 + 1],
      ez = positions[i2 + 2] - positions[i0 + 2];
    const q = ex * tx + ey * ty + ez * tz;
    const r = ex * vx + ey * vy + ez * vz;
    // F = [[t / a, q / d - t c / (a d)], [0, r / d]]; its rotation turns by the angle of (F00 + F11, F10 - F01).
    const cos = t * S[3 * hair] + r * S[3 * hair + 2];
    const sin = (t * S[3 * hair + 1] - q) * S[3 * hair + 2];
    const length = Math.sqrt(cos * cos + sin * sin);
    if (length > 1e-9) {
      const k = 1 / length;
      tx = (cos * tx + sin * vx) * k;
      ty = (cos * ty + sin * vy) * k;
      tz = (cos * tz + sin * vz) * k;
    }
  }
  out[0] = px;
  out[1] = py;
  out[2] = pz;
  out[3] = tx;
  out[4] = ty;
  out[5] = tz;
  out[6] = ny * tz - nz * ty;
  out[7] = nz * tx - nx * tz;
  out[8] = nx * ty - ny * tx;
  out[9] = nx;
  out[10] = ny;
  out[11] = nz;
}

const frame = new Float64Array(15);

/**
 * Poses the first `count` hairs on a skin (positions and normals, xyz per render vertex): writes each ribbon
 * vertex's position, and the anchor's normal as every vertex's normal (a hair is lit as the skin it lies on).
 * Allocates nothing: it runs at every new skin frame.
 */
export function poseHair(
  h: HairStrands,
  positions: ArrayLike<number>,
  normals: ArrayLike<number>,
  outPositions: Float32Array,
  outNormals: Float32Array,
  count = h.count,
): void {
  const per = h.verticesPerHair;
  const local = h.local;
  for (let hair = 0; hair < count; hair++) {
    anchorFrame(h, hair, positions, normals, frame);
    const ax = frame[0],
      ay = frame[1],
      az = frame[2];
    const tx = frame[3],
      ty = frame[4],
      tz = frame[5];
    const bx = frame[6],
      by = frame[7],
      bz = frame[8];
    const nx = frame[9],
      ny = frame[10],
      nz = frame[11];
    const sx = frame[12],
      sy = frame[13],
      sz = frame[14];
    const end = 3 * (hair + 1) * per;
    for (let o = 3 * hair * per; o < end; o += 3) {
      const lt = local[o],
        lb = local[o + 1],
        ln = local[o + 2];
      outPositions[o] = ax + lt * tx + lb * bx + ln * nx;
      outPositions[o + 1] = ay + lt * ty + lb * by + ln * ny;
      outPositions[o + 2] = az + lt * tz + lb * bz + ln * nz;
      outNormals[o] = sx;
      outNormals[o + 1] = sy;
      outNormals[o + 2] = sz;
    }
  }
}

/**
 * Builds strands from hairs given in world space at rest: each hair's anchor (triangle and weights) and its ribbon's
 * vertices (`verticesPerHair` xyz each, root pair first), expressed in the anchor's frame on the rest skin.
 */
export function strandsAtRest(
  rest: { positions: ArrayLike<number>; normals: ArrayLike<number> },
  hairs: readonly {
    corners: readonly [number, number, number];
    weights: readonly [number, number, number];
    /** Two skin vertices whose difference sets the hair's tangent (see HairStrands.tangentEnds); absent: none. */
    tangentEnds?: readonly [number, number];
    /** The point the hair turns about (see HairStrands.pivots); absent: none. */
    pivot?: readonly [number, number, number];
    vertices: ArrayLike<number>;
    shade: ArrayLike<number>;
  }[],
  verticesPerHair: number,
  ribbon: readonly (readonly [number, number, number])[],
): HairStrands {
  const count = hairs.length;
  const tangentEnds = new Uint32Array(2 * count);
  const pivots = new Float32Array(3 * count).fill(NaN);
  const restEdges = new Float32Array(3 * count).fill(NaN);
  const h: HairStrands = {
    count,
    verticesPerHair,
    corners: new Uint32Array(3 * count),
    weights: new Float32Array(3 * count),
    tangentEnds,
    pivots,
    restEdges,
    local: new Float32Array(3 * count * verticesPerHair),
    shade: new Float32Array(count * verticesPerHair),
    indices: new Uint32Array(3 * count * ribbon.length),
  };
  hairs.forEach((hair, k) => {
    h.corners.set(hair.corners, 3 * k);
    h.weights.set(hair.weights, 3 * k);
    tangentEnds.set(hair.tangentEnds ?? [hair.corners[0], hair.corners[0]], 2 * k);
    if (hair.pivot) pivots.set(hair.pivot, 3 * k);
    h.shade.set(hair.shade, k * verticesPerHair);
  });
  const f = new Float64Array(15);
  const P = rest.positions;
  hairs.forEach((hair, k) => {
    anchorFrame(h, k, P, rest.normals, f);
    if (!hair.tangentEnds && !hair.pivot) {
      const [i0, i1, i2] = hair.corners.map((c) => 3 * c);
      const e1 = [P[i1] - P[i0], P[i1 + 1] - P[i0 + 1], P[i1 + 2] - P[i0 + 2]];
      const e2 = [P[i2] - P[i0], P[i2 + 1] - P[i0 + 1], P[i2 + 2] - P[i0 + 2]];
      const dot = (e: number[], o: number) => e[0] * f[o] + e[1] * f[o + 1] + e[2] * f[o + 2];
      const d = dot(e2, 6);
      // A sliver (no second edge across the first) keeps the first edge's frame.
      const a = dot(e1, 3);
      if (Math.abs(d) > 1e-9 && a > 1e-9) restEdges.set([1 / a, dot(e2, 3) / a, 1 / d], 3 * k);
    }
    for (let v = 0; v < verticesPerHair; v++) {
      const dx = hair.vertices[3 * v] - f[0],
        dy = hair.vertices[3 * v + 1] - f[1],
        dz = hair.vertices[3 * v + 2] - f[2];
      const o = 3 * (k * verticesPerHair + v);
      h.local[o] = dx * f[3] + dy * f[4] + dz * f[5];
      h.local[o + 1] = dx * f[6] + dy * f[7] + dz * f[8];
      h.local[o + 2] = dx * f[9] + dy * f[10] + dz * f[11];
    }
    ribbon.forEach((tri, i) =>
      h.indices.set(
        [k * verticesPerHair + tri[0], k * verticesPerHair + tri[1], k * verticesPerHair + tri[2]],
        3 * (k * ribbon.length + i),
      ),
    );
  });
  return h;
}

/** The triangles of a ribbon of `points` points along a hair (vertices 2p and 2p + 1 across it at point p). */
export function ribbonTriangles(points: number): [number, number, number][] {
  const out: [number, number, number][] = [];
  for (let p = 0; p + 1 < points; p++) {
    const a = 2 * p;
    out.push([a, a + 1, a + 2], [a + 1, a + 3, a + 2]);
  }
  return out;
}
