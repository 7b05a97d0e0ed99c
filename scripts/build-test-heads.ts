/**
 * Builds the heads the tests load in place of the default head, from the MakeHuman hm08 base mesh (CC0), each with a
 * topology and proportions of its own:
 *   npx tsx scripts/build-test-heads.ts [path/to/makehuman-hm08] [--out e2e/assets]
 * - `wide-jaw.glb`: the head decimated to about 60 % of its triangles (a different mesh, no UVs, as a scan might
 *   come), a 12 % wider jaw, a nose 8 mm longer, 8 % larger overall and moved; metres, +y up, its mesh not named
 *   `skin` (the largest mesh is taken), with its own eyeballs as nodes `eye-l` and `eye-r` (plain spheres);
 * - `long-face.obj`: the head's quads with their UVs (so with UV seams), a face 7 % longer and a head 5 % narrower,
 *   in centimetres with +z up and the face toward -y (the units and orientation are to be found).
 * Running it twice gives identical files.
 */
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { MeshoptSimplifier } from 'meshoptimizer';
import { writeGlb } from './model/glb';
import { cutHead, DECIMETRE, MATERIALS, sourceMesh } from '../src/core/head/build/head-build';
import { parseObj } from '../src/core/head/build/obj';
import { faceCount, toRenderMesh, vertexCount, type PolyMesh } from '../src/core/head/polymesh';

const args = process.argv.slice(2);
const outIndex = args.indexOf('--out');
const outDir = resolve(outIndex >= 0 ? args[outIndex + 1] : 'e2e/assets');
const sourceDir = resolve(args.find((a, i) => !a.startsWith('--') && args[i - 1] !== '--out') ?? '../shared/assets/makehuman-hm08');
const head = cutHead(sourceMesh(parseObj(readFileSync(join(sourceDir, 'base.obj'), 'utf8'), 'base.obj'))).mesh;
mkdirSync(outDir, { recursive: true });

/** 0 at `a`, 1 at `b`, smooth between. */
const smoothstep = (a: number, b: number, x: number): number => {
  const t = Math.min(1, Math.max(0, (x - a) / (b - a)));
  return t * t * (3 - 2 * t);
};

/** Moves every vertex of a PolyMesh (metres) through `f`, in place. */
function reshape(mesh: PolyMesh, f: (p: [number, number, number]) => [number, number, number]): void {
  for (let v = 0; v < vertexCount(mesh); v++) {
    const p = f([mesh.positions[3 * v] * DECIMETRE, mesh.positions[3 * v + 1] * DECIMETRE, mesh.positions[3 * v + 2] * DECIMETRE]);
    for (let k = 0; k < 3; k++) mesh.positions[3 * v + k] = p[k] / DECIMETRE;
  }
}

const copy = (m: PolyMesh): PolyMesh => ({ ...m, positions: m.positions.slice() });

// (a) A wider jaw, a longer nose, larger and moved; decimated, welded, written as GLB.
{
  const mesh = copy(head);
  const nose = [0, 0.691, 0.168];
  const shape = ([x, y, z]: [number, number, number]): [number, number, number] => {
    // The jaw widens below the mouth corners, the most at the jaw's angle and below.
    const jaw = smoothstep(0.67, 0.62, y);
    const nearNose = Math.exp(-((x - nose[0]) ** 2 + (y - nose[1]) ** 2 + (z - nose[2]) ** 2) / (2 * 0.012 ** 2));
    const p = [x * (1 + 0.12 * jaw), y - 0.003 * nearNose, z + 0.008 * nearNose];
    return [1.08 * p[0] + 0.01, 1.08 * (p[1] - 0.7) + 1.5, 1.08 * p[2] - 0.02];
  };
  reshape(mesh, shape);
  const render = toRenderMesh(mesh, DECIMETRE);
  // Weld the UV seams (one vertex per position) so that the simplifier may move across them.
  const index = new Map<string, number>();
  const positions: number[] = [];
  const remap = new Uint32Array(render.positions.length / 3);
  for (let r = 0; r < remap.length; r++) {
    const key = `${render.positions[3 * r]},${render.positions[3 * r + 1]},${render.positions[3 * r + 2]}`;
    let w = index.get(key);
    if (w === undefined) {
      w = positions.length / 3;
      index.set(key, w);
      positions.push(render.positions[3 * r], render.positions[3 * r + 1], render.positions[3 * r + 2]);
    }
    remap[r] = w;
  }
  const welded = Float32Array.from(positions);
  const triangles = Uint32Array.from(render.indices, (r) => remap[r]);
  await MeshoptSimplifier.ready;
  const [simplified] = MeshoptSimplifier.simplify(triangles, welded, 3, Math.floor((0.6 * triangles.length) / 3) * 3, 0.01, ['LockBorder']);
  // Keep the vertices still used, numbered in first-use order.
  const renumber = new Map<number, number>();
  const compactIndices = Uint32Array.from(simplified, (v) => {
    let r = renumber.get(v);
    if (r === undefined) {
      r = renumber.size;
      renumber.set(v, r);
    }
    return r;
  });
  const count = renumber.size;
  const compact = new Float32Array(3 * count);
  for (const [v, r] of renumber) compact.set(welded.subarray(3 * v, 3 * v + 3), 3 * r);
  const geometry = {
    positions: compact,
    normals: vertexNormals(compact, compactIndices),
    uvs: new Float32Array(2 * count),
    indices: compactIndices,
  };
  // The eyes: spheres of the hm08 eye's radius (12 mm) times the head's scale, at the reshaped eye joints.
  const eyeball = sphereGeometry(0.012 * 1.08, 24, 16);
  const eyes = (['eye-l', 'eye-r'] as const).map((name) => ({
    name,
    translation: shape([name === 'eye-l' ? 0.0308 : -0.0308, 0.7284, 0.1245]),
    meshName: 'Eyeball',
    parts: [{ geometry: eyeball, material: MATERIALS.sclera }],
  }));
  const bytes = await writeGlb(
    { name: 'Character', children: [{ name: 'Head_Geo', parts: [{ geometry, material: MATERIALS.skin }] }, ...eyes] },
    {},
  );
  writeFileSync(join(outDir, 'wide-jaw.glb'), bytes);
  console.log(
    `wide-jaw.glb: ${count} vertices, ${compactIndices.length / 3} triangles (from ${triangles.length / 3}), ${bytes.length} bytes`,
  );
}

// (b) A longer face and a narrower head, as quads with UV seams, in centimetres, +z up, the face toward -y.
{
  const mesh = copy(head);
  reshape(mesh, ([x, y, z]) => [0.95 * x, 0.691 + 1.07 * (y - 0.691), z]);
  const lines = [
    '# softface test head: the MakeHuman hm08 head (CC0) with a longer face; centimetres, +z up, face toward -y',
    'o LongFace',
  ];
  for (let v = 0; v < vertexCount(mesh); v++) {
    const [x, y, z] = [0, 1, 2].map((k) => mesh.positions[3 * v + k] * DECIMETRE * 100);
    lines.push(`v ${x.toFixed(4)} ${(-z).toFixed(4)} ${y.toFixed(4)}`);
  }
  const uvIndex = new Map<string, number>();
  const faces: string[] = [];
  for (let f = 0; f < faceCount(mesh); f++) {
    const corners: string[] = [];
    for (let c = mesh.faceStart[f]; c < mesh.faceStart[f + 1]; c++) {
      const key = `${mesh.cornerUVs[2 * c].toFixed(5)} ${mesh.cornerUVs[2 * c + 1].toFixed(5)}`;
      let t = uvIndex.get(key);
      if (t === undefined) {
        t = uvIndex.size;
        uvIndex.set(key, t);
      }
      corners.push(`${mesh.corners[c] + 1}/${t + 1}`);
    }
    faces.push(`f ${corners.join(' ')}`);
  }
  for (const key of uvIndex.keys()) lines.push(`vt ${key}`);
  lines.push(...faces, '');
  writeFileSync(join(outDir, 'long-face.obj'), lines.join('\n'));
  console.log(`long-face.obj: ${vertexCount(mesh)} vertices, ${uvIndex.size} uvs, ${faceCount(mesh)} faces`);
}

/** A UV sphere about the origin: `segments` around, `rings` from pole to pole. */
function sphereGeometry(radius: number, segments: number, rings: number) {
  const positions: number[] = [];
  const normals: number[] = [];
  const uvs: number[] = [];
  const indices: number[] = [];
  for (let j = 0; j <= rings; j++) {
    for (let i = 0; i <= segments; i++) {
      const t = (Math.PI * j) / rings;
      const p = (2 * Math.PI * i) / segments;
      const n = [Math.sin(t) * Math.sin(p), Math.cos(t), Math.sin(t) * Math.cos(p)];
      positions.push(...n.map((x) => radius * x));
      normals.push(...n);
      uvs.push(i / segments, j / rings);
    }
  }
  for (let j = 0; j < rings; j++) {
    for (let i = 0; i < segments; i++) {
      const a = j * (segments + 1) + i;
      const b = a + segments + 1;
      indices.push(a, b, a + 1, a + 1, b, b + 1);
    }
  }
  return {
    positions: Float32Array.from(positions),
    normals: Float32Array.from(normals),
    uvs: Float32Array.from(uvs),
    indices: Uint32Array.from(indices),
  };
}

/** Area-weighted vertex normals of a triangle mesh. */
function vertexNormals(P: Float32Array, T: Uint32Array): Float32Array {
  const N = new Float32Array(P.length);
  for (let t = 0; t < T.length; t += 3) {
    const [a, b, c] = [3 * T[t], 3 * T[t + 1], 3 * T[t + 2]];
    const u = [P[b] - P[a], P[b + 1] - P[a + 1], P[b + 2] - P[a + 2]];
    const w = [P[c] - P[a], P[c + 1] - P[a + 1], P[c + 2] - P[a + 2]];
    const n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
    for (const i of [a, b, c]) for (let k = 0; k < 3; k++) N[i + k] += n[k];
  }
  for (let i = 0; i < N.length; i += 3) {
    const l = Math.hypot(N[i], N[i + 1], N[i + 2]) || 1;
    for (let k = 0; k < 3; k++) N[i + k] /= l;
  }
  return N;
}
