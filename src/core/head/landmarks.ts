/**
 * Facial landmarks on a head mesh (metres, +y up, the face toward +z, the subject's left at +x): the points the rig
 * is carried over by. Found from a depth image of the face seen from the front: the eye openings and the mouth slit
 * are pits in it (the skin turns inward there), the nose tip is its highest point near the midline, the chin and
 * brows are the most forward points of the profile below the mouth and above the eyes. Pure: no three.js, no DOM.
 */
import type { Vec3 } from '../rig/rig-types';

/** The landmarks, in the order the editor asks for those it could not find. */
export const LANDMARK_NAMES = [
  'nose-tip',
  'eye-inner-l',
  'eye-outer-l',
  'eye-inner-r',
  'eye-outer-r',
  'mouth-l',
  'mouth-r',
  'chin',
  'brow-l',
  'brow-r',
  'ear-l',
  'ear-r',
  'head-top',
  'head-back',
] as const;

/** A landmark's name, one of `LANDMARK_NAMES`; `l` and `r` are the subject's left and right. */
export type LandmarkName = (typeof LANDMARK_NAMES)[number];
/** A point for every landmark: `[x, y, z]` in metres, +y up, the face toward +z, the subject's left at +x. */
export type Landmarks = Record<LandmarkName, Vec3>;

/** What the editor asks the user to click for each landmark ("click the left mouth corner"). */
export const LANDMARK_LABELS: Readonly<Record<LandmarkName, string>> = Object.freeze({
  'nose-tip': 'the tip of the nose',
  'eye-inner-l': "the left eye's inner corner",
  'eye-outer-l': "the left eye's outer corner",
  'eye-inner-r': "the right eye's inner corner",
  'eye-outer-r': "the right eye's outer corner",
  'mouth-l': 'the left mouth corner',
  'mouth-r': 'the right mouth corner',
  chin: 'the front of the chin',
  'brow-l': 'the left brow, above the inner eye corner',
  'brow-r': 'the right brow, above the inner eye corner',
  'ear-l': 'the outermost point of the left ear',
  'ear-r': 'the outermost point of the right ear',
  'head-top': 'the top of the head',
  'head-back': 'the back of the head, at eye level',
});

/**
 * The default head's landmarks (the low head, as `findLandmarks` finds them; the medium head's are within 4 mm, the
 * chin sliding most along its flat profile): the rig in `public/rigs/default.json` was made on this head, so a warp from these points
 * carries it over.
 */
export const DEFAULT_LANDMARKS: Readonly<Landmarks> = Object.freeze({
  'nose-tip': [0, 0.691, 0.1681],
  'eye-inner-l': [0.018, 0.726, 0.1399],
  'eye-outer-l': [0.043, 0.728, 0.1366],
  'eye-inner-r': [-0.018, 0.726, 0.1399],
  'eye-outer-r': [-0.043, 0.728, 0.1366],
  'mouth-l': [0.024, 0.661, 0.1439],
  'mouth-r': [-0.024, 0.661, 0.1439],
  chin: [0, 0.633, 0.1499],
  'brow-l': [0.018, 0.76, 0.1496],
  'brow-r': [-0.018, 0.76, 0.1496],
  'ear-l': [0.0879, 0.724, 0.0375],
  'ear-r': [-0.0879, 0.724, 0.0375],
  'head-top': [0, 0.848, 0.0375],
  'head-back': [0, 0.7284, -0.038],
});

/** Landmarks found, and for each one not found, why. */
export interface LandmarkSearch {
  found: Partial<Landmarks>;
  missing: { name: LandmarkName; reason: string }[];
}

/** Depth image cell size in metres: a millimetre, coarser on meshes wider than 40 cm. */
const CELL = 0.001;
/** Pits narrower than twice this are found: eye openings and the mouth slit are 3 to 12 mm high. */
const CLOSING_RADIUS = 0.006;
/** How much deeper than the surface closed over it a cell must be to count as a pit. */
const PIT_DEPTH = 0.002;
/** The smallest pit that counts (square metres): a few square millimetres. */
const MIN_PIT_AREA = 8e-6;

/** A depth image: the largest z of the surface over each cell of a grid in x and y. */
interface DepthImage {
  width: number;
  height: number;
  cell: number;
  x0: number;
  y0: number;
  z: Float32Array;
}

/** A connected set of pit cells. */
interface Pit {
  cells: number[];
  cx: number;
  cy: number;
  area: number;
}

/**
 * Finds the landmarks of a head at rest. `positions` xyz, `triangles` vertex indices. Landmarks that cannot be found
 * are listed with the reason (a head with closed eyes has no eye openings to find, a sphere has no face).
 */
export function findLandmarks(positions: ArrayLike<number>, triangles: ArrayLike<number>): LandmarkSearch {
  const found: Partial<Landmarks> = {};
  const missing: { name: LandmarkName; reason: string }[] = [];
  const miss = (names: LandmarkName[], reason: string): void => {
    for (const name of names) if (!found[name] && !missing.some((m) => m.name === name)) missing.push({ name, reason });
  };
  const image = depthImage(positions, triangles);
  const closed = closing(image, CLOSING_RADIUS);
  const { width: W, height: H, cell } = image;
  const X = (i: number): number => image.x0 + (i % W) * cell;
  const Y = (i: number): number => image.y0 + Math.floor(i / W) * cell;
  const point = (i: number): Vec3 => [X(i), Y(i), closed[i]];

  // Nose tip: the most forward point within a band around the midline x = 0.
  let nose = -1;
  const band = 0.02;
  for (let i = 0; i < W * H; i++) {
    if (Math.abs(X(i)) < band && Number.isFinite(image.z[i]) && (nose < 0 || image.z[i] > image.z[nose])) nose = i;
  }
  if (nose < 0) {
    miss([...LANDMARK_NAMES], 'the surface does not cross the midline x = 0 in front');
    return { found, missing };
  }
  found['nose-tip'] = [X(nose), Y(nose), image.z[nose]];
  const noseY = Y(nose);

  const pits = findPits(image, closed);
  // Eyes: the largest mirrored pair of pits above the nose tip, away from the midline but not out at the ears.
  let eyes: [Pit, Pit] | undefined;
  let best = 0;
  for (const l of pits) {
    if (l.cx < 0.008 || l.cx > 0.06 || l.cy < noseY + 0.005 || l.cy > noseY + 0.09) continue;
    for (const r of pits) {
      if (r.cx > -0.008 || Math.abs(l.cx + r.cx) > 0.01 || Math.abs(l.cy - r.cy) > 0.01) continue;
      const score = Math.min(l.area, r.area);
      if (score > best) {
        best = score;
        eyes = [l, r];
      }
    }
  }
  let eyeY = 0;
  let eyeTop = 0;
  if (eyes) {
    for (const [pit, side] of [
      [eyes[0], 'l'],
      [eyes[1], 'r'],
    ] as const) {
      let inner = pit.cells[0];
      let outer = pit.cells[0];
      for (const c of pit.cells) {
        if (Math.abs(X(c)) < Math.abs(X(inner))) inner = c;
        if (Math.abs(X(c)) > Math.abs(X(outer))) outer = c;
      }
      found[`eye-inner-${side}`] = point(inner);
      found[`eye-outer-${side}`] = point(outer);
    }
    eyeY = (eyes[0].cy + eyes[1].cy) / 2;
    eyeTop = Math.max(...eyes.flatMap((p) => p.cells.map(Y)));
  } else
    miss(
      ['eye-inner-l', 'eye-outer-l', 'eye-inner-r', 'eye-outer-r', 'brow-l', 'brow-r'],
      'no pair of eye openings was found above the nose',
    );

  // Mouth: the largest pit below the nose near the midline, with the pits level with it (the slit may be broken
  // where the lips touch).
  let mouth: Pit | undefined;
  for (const p of pits) {
    if (Math.abs(p.cx) > 0.03 || p.cy > noseY - 0.005 || p.cy < noseY - 0.07) continue;
    if (!mouth || p.area > mouth.area) mouth = p;
  }
  let mouthY = 0;
  if (mouth) {
    const slit = pits.filter((p) => Math.abs(p.cy - mouth.cy) < 0.004 && Math.abs(p.cx) < 0.04).flatMap((p) => p.cells);
    let left = slit[0];
    let right = slit[0];
    for (const c of slit) {
      if (X(c) > X(left)) left = c;
      if (X(c) < X(right)) right = c;
    }
    found['mouth-l'] = point(left);
    found['mouth-r'] = point(right);
    mouthY = mouth.cy;
  } else miss(['mouth-l', 'mouth-r', 'chin'], 'no mouth opening was found below the nose');

  if (eyes) {
    // Brows: the most forward point straight above each inner eye corner, from just over the opening to 3 cm up.
    for (const side of ['l', 'r'] as const) {
      const column = Math.round((found[`eye-inner-${side}`]![0] - image.x0) / cell);
      let brow = -1;
      for (
        let row = Math.ceil((eyeTop + 0.003 - image.y0) / cell);
        row <= Math.floor((eyeTop + 0.03 - image.y0) / cell) && row < H;
        row++
      ) {
        const i = row * W + column;
        if (Number.isFinite(closed[i]) && (brow < 0 || closed[i] > closed[brow])) brow = i;
      }
      if (brow >= 0) found[`brow-${side}`] = point(brow);
      else miss([`brow-${side}`], 'the surface above the eye was not found');
    }
  }

  if (eyes && mouth) {
    // Chin: the most forward midline point between a quarter and nine tenths of the eye-to-mouth height below the mouth.
    const d = eyeY - mouthY;
    const column = Math.round(-image.x0 / cell);
    let chin = -1;
    for (let row = Math.ceil((mouthY - 0.9 * d - image.y0) / cell); row <= Math.floor((mouthY - 0.25 * d - image.y0) / cell); row++) {
      if (row < 0 || row >= H) continue;
      const i = row * W + column;
      if (Number.isFinite(closed[i]) && (chin < 0 || closed[i] > closed[chin])) chin = i;
    }
    if (chin >= 0) found.chin = point(chin);
    else miss(['chin'], 'the surface below the mouth was not found');

    // Ears: the outermost vertices between the mouth and a little above the eyes.
    const n = Math.floor(positions.length / 3);
    let earL = -1;
    let earR = -1;
    for (let v = 0; v < n; v++) {
      const x = positions[3 * v];
      const y = positions[3 * v + 1];
      if (y <= mouthY || y >= eyeY + 0.3 * d) continue;
      if (earL < 0 || x > positions[3 * earL]) earL = v;
      if (earR < 0 || x < positions[3 * earR]) earR = v;
    }
    const vertex = (v: number): Vec3 => [positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]];
    if (earL >= 0 && earR >= 0) {
      found['ear-l'] = vertex(earL);
      found['ear-r'] = vertex(earR);
      // Top and back: where lines through the head cross its surface last, so that they do not slide along the
      // flat crown and occiput from one mesh to another. The top line is vertical, midway between the ears.
      const earZ = (positions[3 * earL + 2] + positions[3 * earR + 2]) / 2;
      const top = lineExtreme(positions, triangles, [0, 0, earZ], 1);
      if (top) found['head-top'] = top;
      else miss(['head-top'], 'no surface above the ears on the midline');
    } else miss(['ear-l', 'ear-r', 'head-top'], 'no surface at the side between mouth and brows');
    const back = lineExtreme(positions, triangles, [0, eyeY, 0], 2, -1);
    if (back) found['head-back'] = back;
    else miss(['head-back'], 'no surface at the back on the midline at eye level');
  } else miss(['chin', 'ear-l', 'ear-r', 'head-top', 'head-back'], 'they are placed from the eyes and the mouth, which were not found');
  return { found, missing: LANDMARK_NAMES.flatMap((name) => missing.filter((m) => m.name === name)) };
}

/**
 * The last crossing of the surface by the line through `through` along the axis `axis` (1: y, 2: z), in the
 * direction `sign`: the crossing with the largest coordinate along the axis times the sign; undefined if none.
 */
function lineExtreme(P: ArrayLike<number>, T: ArrayLike<number>, through: Vec3, axis: 1 | 2, sign = 1): Vec3 | undefined {
  // The two coordinates across the line: x and the other of y, z.
  const u = 0;
  const w = axis === 1 ? 2 : 1;
  let best: Vec3 | undefined;
  for (let t = 0; t + 2 < T.length; t += 3) {
    const a = 3 * T[t];
    const b = 3 * T[t + 1];
    const c = 3 * T[t + 2];
    const pu = through[u];
    const pw = through[w];
    const d = (P[b + u] - P[a + u]) * (P[c + w] - P[a + w]) - (P[c + u] - P[a + u]) * (P[b + w] - P[a + w]);
    if (Math.abs(d) < 1e-18) continue;
    const l1 = ((pu - P[a + u]) * (P[c + w] - P[a + w]) - (P[c + u] - P[a + u]) * (pw - P[a + w])) / d;
    const l2 = ((P[b + u] - P[a + u]) * (pw - P[a + w]) - (pu - P[a + u]) * (P[b + w] - P[a + w])) / d;
    if (l1 < 0 || l2 < 0 || l1 + l2 > 1) continue;
    const along = P[a + axis] + l1 * (P[b + axis] - P[a + axis]) + l2 * (P[c + axis] - P[a + axis]);
    if (!best || sign * along > sign * best[axis]) {
      best = [...through] as Vec3;
      best[axis] = along;
    }
  }
  return best;
}

/** Rasterises the triangles seen from +z: the largest z over each cell, -Infinity where no surface is. */
function depthImage(P: ArrayLike<number>, T: ArrayLike<number>): DepthImage {
  let x0 = Infinity;
  let x1 = -Infinity;
  let y0 = Infinity;
  let y1 = -Infinity;
  for (let i = 0; i < P.length; i += 3) {
    x0 = Math.min(x0, P[i]);
    x1 = Math.max(x1, P[i]);
    y0 = Math.min(y0, P[i + 1]);
    y1 = Math.max(y1, P[i + 1]);
  }
  const cell = Math.max(CELL, (x1 - x0) / 400, (y1 - y0) / 400);
  // Cells on whole multiples of their size, so that one column lies on the midline x = 0.
  x0 = Math.floor(x0 / cell) * cell;
  y0 = Math.floor(y0 / cell) * cell;
  const width = Math.floor((x1 - x0) / cell) + 1;
  const height = Math.floor((y1 - y0) / cell) + 1;
  const z = new Float32Array(width * height).fill(-Infinity);
  for (let t = 0; t + 2 < T.length; t += 3) {
    const a = 3 * T[t];
    const b = 3 * T[t + 1];
    const c = 3 * T[t + 2];
    const ax = (P[a] - x0) / cell,
      ay = (P[a + 1] - y0) / cell,
      az = P[a + 2];
    const bx = (P[b] - x0) / cell,
      by = (P[b + 1] - y0) / cell,
      bz = P[b + 2];
    const cx = (P[c] - x0) / cell,
      cy = (P[c + 1] - y0) / cell,
      cz = P[c + 2];
    const d = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
    if (Math.abs(d) < 1e-12) continue;
    const i0 = Math.max(0, Math.ceil(Math.min(ax, bx, cx)));
    const i1 = Math.min(width - 1, Math.floor(Math.max(ax, bx, cx)));
    const j0 = Math.max(0, Math.ceil(Math.min(ay, by, cy)));
    const j1 = Math.min(height - 1, Math.floor(Math.max(ay, by, cy)));
    for (let j = j0; j <= j1; j++) {
      for (let i = i0; i <= i1; i++) {
        const u = ((bx - i) * (cy - j) - (cx - i) * (by - j)) / d;
        const v = ((cx - i) * (ay - j) - (ax - i) * (cy - j)) / d;
        const w = 1 - u - v;
        if (u < -1e-9 || v < -1e-9 || w < -1e-9) continue;
        const zz = u * az + v * bz + w * cz;
        if (zz > z[j * width + i]) z[j * width + i] = zz;
      }
    }
  }
  return { width, height, cell, x0, y0, z };
}

/** Morphological closing (largest over a disc, then smallest over it): the surface with its narrow pits filled. */
function closing(image: DepthImage, radius: number): Float32Array {
  const r = Math.max(1, Math.round(radius / image.cell));
  const offsets: [number, number][] = [];
  for (let dj = -r; dj <= r; dj++) for (let di = -r; di <= r; di++) if (di * di + dj * dj <= r * r) offsets.push([di, dj]);
  const { width: W, height: H } = image;
  const pass = (input: Float32Array, larger: boolean): Float32Array => {
    const out = new Float32Array(W * H);
    for (let j = 0; j < H; j++) {
      for (let i = 0; i < W; i++) {
        const here = input[j * W + i];
        // Cells off the surface stay off it, and do not pull their neighbours down when eroding.
        if (here === -Infinity) {
          out[j * W + i] = -Infinity;
          continue;
        }
        let m = here;
        for (const [di, dj] of offsets) {
          const ii = i + di;
          const jj = j + dj;
          if (ii < 0 || jj < 0 || ii >= W || jj >= H) continue;
          const v = input[jj * W + ii];
          if (v === -Infinity) continue;
          if (larger ? v > m : v < m) m = v;
        }
        out[j * W + i] = m;
      }
    }
    return out;
  };
  return pass(pass(image.z, true), false);
}

/** Connected sets of cells at least PIT_DEPTH below the closed surface, at least MIN_PIT_AREA large. */
function findPits(image: DepthImage, closed: Float32Array): Pit[] {
  const { width: W, height: H, cell } = image;
  const pit = new Uint8Array(W * H);
  for (let i = 0; i < W * H; i++) if (Number.isFinite(image.z[i]) && closed[i] - image.z[i] > PIT_DEPTH) pit[i] = 1;
  const pits: Pit[] = [];
  const seen = new Uint8Array(W * H);
  for (let start = 0; start < W * H; start++) {
    if (!pit[start] || seen[start]) continue;
    seen[start] = 1;
    const cells = [start];
    for (let k = 0; k < cells.length; k++) {
      const i = cells[k];
      const x = i % W;
      const y = Math.floor(i / W);
      for (const [nx, ny] of [
        [x - 1, y],
        [x + 1, y],
        [x, y - 1],
        [x, y + 1],
      ]) {
        if (nx < 0 || ny < 0 || nx >= W || ny >= H) continue;
        const j = ny * W + nx;
        if (pit[j] && !seen[j]) {
          seen[j] = 1;
          cells.push(j);
        }
      }
    }
    const area = cells.length * cell * cell;
    if (area < MIN_PIT_AREA) continue;
    let cx = 0;
    let cy = 0;
    for (const i of cells) {
      cx += image.x0 + (i % W) * cell;
      cy += image.y0 + Math.floor(i / W) * cell;
    }
    pits.push({ cells, cx: cx / cells.length, cy: cy / cells.length, area });
  }
  return pits;
}
