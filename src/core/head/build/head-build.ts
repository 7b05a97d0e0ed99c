/**
 * Builds the head model's resolutions from the MakeHuman hm08 base mesh: the skin cut off at the neck and subdivided,
 * eyeballs, teeth and tongue, and the pivots. Pure (no DOM, no three.js, no Node): the build script writes the result
 * as GLB (scripts/model/glb.ts).
 */
import { HEAD_NODES } from '../head-nodes';
import { boundaryLoops, cutAlongLoop, findEdgeLoop, subsetFaces } from './cut';
import { buildEyeball } from './eye';
import { buildArch, fitArchOutline, fitOcclusalPlane, type DentalArch } from './teeth';
import type { MaterialSpec, NodeSpec, PartSpec, TriGeometry } from './head-spec';
import type { ObjMesh } from './obj';
import { catmullClark } from '../subdivide';
import { faceCount, polyMeshFromFaces, toRenderMesh, vertexCount, type PolyMesh } from '../polymesh';

/** MakeHuman works in decimetres; glTF and the app work in metres. */
export const DECIMETRE = 0.1;

/** The resolutions written: name, Catmull-Clark levels. */
export const LEVELS = [
  { name: 'low', subdivisions: 0 },
  { name: 'medium', subdivisions: 1 },
  { name: 'high', subdivisions: 2 },
] as const;

/** Where the neck cut runs: the edge loop through the front-midline vertex nearest this point (hm08, decimetres). */
const NECK_CUT_FRONT: [number, number, number] = [0, 5.78, 0.69];

/** Joint cubes of hm08 whose centres become the model's pivots, by the pivot name used in the model. */
const PIVOT_JOINTS: Record<string, string> = {
  'eye-l': 'joint-l-eye',
  'eye-r': 'joint-r-eye',
  'upperlid-l': 'joint-l-upperlid',
  'upperlid-r': 'joint-r-upperlid',
  'lowerlid-l': 'joint-l-lowerlid',
  'lowerlid-r': 'joint-r-lowerlid',
  'jaw-hinge': 'joint-mouth',
  chin: 'joint-jaw',
  head: 'joint-head',
  neck: 'joint-neck',
};

/** How much narrower the tongue is made, and how far it is lowered (metres): see buildHeadLevels. */
const TONGUE_NARROWING = 0.88;
const TONGUE_DROP = 0.003;

export const MATERIALS = {
  skin: { name: 'skin', baseColor: [0.72, 0.42, 0.31, 1], roughness: 0.55 },
  sclera: { name: 'sclera', baseColor: [0.86, 0.83, 0.79, 1], roughness: 0.3 },
  iris: { name: 'iris', baseColor: [1, 1, 1, 1], roughness: 0.5 },
  cornea: { name: 'cornea', baseColor: [1, 1, 1, 0.06], roughness: 0.02, blend: true },
  teeth: { name: 'teeth', baseColor: [0.84, 0.79, 0.67, 1], roughness: 0.3, doubleSided: true },
  gums: { name: 'gums', baseColor: [0.66, 0.27, 0.28, 1], roughness: 0.4, doubleSided: true },
  tongue: { name: 'tongue', baseColor: [0.52, 0.17, 0.16, 1], roughness: 0.45 },
} satisfies Record<string, MaterialSpec>;

/** Everything the OBJ gives, as one polygon mesh plus the faces of each group. */
export interface SourceMesh {
  mesh: PolyMesh;
  groupFaces: Map<string, number[]>;
}

/** Turns a parsed OBJ into a PolyMesh (faces without texture coordinates get uv 0, 0). */
export function sourceMesh(obj: ObjMesh): SourceMesh {
  const groupFaces = new Map<string, number[]>();
  const faces = obj.faces.map((f, i) => {
    const list = groupFaces.get(f.group) ?? [];
    list.push(i);
    groupFaces.set(f.group, list);
    return { v: f.v, uv: f.vt.flatMap((t) => (t < 0 ? [0, 0] : [obj.uvs[2 * t], obj.uvs[2 * t + 1]])) };
  });
  return { mesh: polyMeshFromFaces(obj.positions, faces), groupFaces };
}

/** The faces of one OBJ group as their own mesh; throws naming the group if the OBJ lacks it. */
export function groupMesh(source: SourceMesh, group: string): ReturnType<typeof subsetFaces> {
  const faces = source.groupFaces.get(group);
  if (!faces || faces.length === 0) throw new Error(`the base mesh has no group "${group}"`);
  return subsetFaces(source.mesh, faces);
}

/** Centre of a group's vertices (the joint cubes mark pivots this way), from their positions (xyz per vertex). */
function centre(positions: Float64Array): [number, number, number] {
  const c: [number, number, number] = [0, 0, 0];
  const n = positions.length / 3;
  for (let v = 0; v < n; v++) for (let k = 0; k < 3; k++) c[k] += positions[3 * v + k] / n;
  return c;
}

/** The head and upper neck cut from the body along the neck edge loop. */
export interface HeadCut {
  mesh: PolyMesh;
  /** The neck loop, as indices into `mesh`. */
  neckLoop: number[];
  /** The base mesh's vertex (its OBJ `v` line, 0-based) of each vertex of `mesh`, ascending. */
  sourceVertex: Uint32Array;
}

/** The body's front-midline vertex nearest `front` (an index into the body group's mesh), where the neck cut starts. */
export function neckCutStart(source: SourceMesh, front = NECK_CUT_FRONT): number {
  const body = groupMesh(source, 'body');
  const P = body.mesh.positions;
  let start = -1;
  let best = Infinity;
  for (let v = 0; v < vertexCount(body.mesh); v++) {
    if (Math.abs(P[3 * v]) > 1e-6) continue;
    const d = Math.hypot(P[3 * v + 1] - front[1], P[3 * v + 2] - front[2]);
    if (d < best) {
      best = d;
      start = v;
    }
  }
  if (start < 0) throw new Error('the body has no vertex on the midline x = 0');
  return start;
}

/**
 * Cuts the head off the closed body surface along the quad edge loop that starts at the body vertex `start` (by
 * default the one nearest NECK_CUT_FRONT; a head made with identity targets starts where the base mesh's does).
 */
export function cutHead(source: SourceMesh, start = neckCutStart(source)): HeadCut {
  const body = groupMesh(source, 'body');
  const P = body.mesh.positions;
  const V = vertexCount(body.mesh);
  // Leave the midline along the edge that points most sideways toward the subject's left (+x).
  let next = -1;
  let bestSideways = 0;
  for (let f = 0; f < faceCount(body.mesh); f++) {
    const s = body.mesh.faceStart[f];
    const n = body.mesh.faceStart[f + 1] - s;
    for (let i = 0; i < n; i++) {
      if (body.mesh.corners[s + i] !== start) continue;
      for (const j of [(i + 1) % n, (i + n - 1) % n]) {
        const w = body.mesh.corners[s + j];
        const d = [0, 1, 2].map((k) => P[3 * w + k] - P[3 * start + k]);
        const sideways = d[0] / Math.hypot(d[0], d[1], d[2]);
        if (sideways > bestSideways) {
          bestSideways = sideways;
          next = w;
        }
      }
    }
  }
  const loop = findEdgeLoop(body.mesh, start, next);
  let top = 0;
  for (let v = 1; v < V; v++) if (P[3 * v + 1] > P[3 * top + 1]) top = v;
  let seed = -1;
  for (let f = 0; f < faceCount(body.mesh) && seed < 0; f++) {
    for (let c = body.mesh.faceStart[f]; c < body.mesh.faceStart[f + 1]; c++) if (body.mesh.corners[c] === top) seed = f;
  }
  const head = cutAlongLoop(body.mesh, loop, seed);
  const boundary = boundaryLoops(head.mesh);
  if (boundary.length !== 1 || boundary[0].length !== loop.length) {
    throw new Error(
      `the neck cut should leave one boundary loop of ${loop.length} vertices, found ${boundary.map((b) => b.length).join(', ')}`,
    );
  }
  return { mesh: head.mesh, neckLoop: boundary[0], sourceVertex: head.sourceVertex.map((v) => body.sourceVertex[v]) };
}

/** Applies `levels` rounds of Catmull-Clark. */
function subdivide(mesh: PolyMesh, levels: number): PolyMesh {
  let m = mesh;
  for (let i = 0; i < levels; i++) m = catmullClark(m);
  return m;
}

/** Counts stated in CREDITS.md and the model's extras. */
export interface LevelStats {
  name: string;
  subdivisions: number;
  /** Distinct skin positions: the vertices the solver simulates. */
  skinVertices: number;
  /** Render vertices: positions split along UV seams. */
  renderVertices: number;
  quads: number;
  triangles: number;
}

/** One head resolution ready to write. */
export interface BuiltHead {
  stats: LevelStats;
  root: NodeSpec;
  sceneExtras: Record<string, unknown>;
}

/** The OBJ groups whose vertex positions a head is built from, besides the body and the tongue (see HeadSource). */
export const POSITION_GROUPS: readonly string[] = [
  ...new Set([...Object.values(PIVOT_JOINTS), 'helper-l-eye', 'helper-upper-teeth', 'helper-lower-teeth']),
];

/** The OBJ group whose faces become the tongue. */
export const TONGUE_GROUP = 'helper-tongue';

/**
 * Everything a head is built from, in the base mesh's decimetres: all that buildHeadLevels reads of base.obj, so that
 * a head can be built from a compact asset as well (see identity-source.ts).
 */
export interface HeadSource {
  /** The head cut off the body at the neck. */
  cut: HeadCut;
  /** Positions (xyz per vertex, in the base mesh's vertex order) of each group of POSITION_GROUPS. */
  groups: ReadonlyMap<string, Float64Array>;
  /** The base mesh's tongue (TONGUE_GROUP). */
  tongue: PolyMesh;
}

/** What a head is built from in a parsed base mesh; `cutStart` as in cutHead. */
function headSource(obj: ObjMesh, cutStart?: number): HeadSource {
  const source = sourceMesh(obj);
  const groups = new Map(POSITION_GROUPS.map((g) => [g, groupMesh(source, g).mesh.positions]));
  return { cut: cutHead(source, cutStart), groups, tongue: groupMesh(source, TONGUE_GROUP).mesh };
}

/** The parts every resolution of a head shares: eyeballs, teeth, tongue and pivots (metres). */
export interface HeadParts {
  pivots: Record<string, [number, number, number]>;
  /** The eyeball's radius (metres), the helper eye's mean distance from the eye joint. */
  eyeRadius: number;
  eyeParts: PartSpec[];
  upperArch: PartSpec[];
  lowerArch: PartSpec[];
  tongue: TriGeometry;
  neckLoopVertices: number;
}

/** Builds the parts shared by every resolution (eyes, teeth, tongue, pivots) from a head's source. */
export function buildHeadParts(source: HeadSource): HeadParts {
  const group = (name: string): Float64Array => {
    const positions = source.groups.get(name);
    if (!positions) throw new Error(`the head's source has no group "${name}"`);
    return positions;
  };
  const pivots: Record<string, [number, number, number]> = {};
  for (const [name, joint] of Object.entries(PIVOT_JOINTS)) pivots[name] = scaled(centre(group(joint)));

  // The helper eye is a sphere around the eye joint: measure its radius, then build a better eyeball of that size.
  const helperEye = group('helper-l-eye');
  const eyeCentre = centre(group('joint-l-eye'));
  const eyeVertices = helperEye.length / 3;
  let radius = 0;
  for (let v = 0; v < eyeVertices; v++) {
    radius += Math.hypot(...([0, 1, 2].map((k) => helperEye[3 * v + k] - eyeCentre[k]) as [number, number, number])) / eyeVertices;
  }
  const eyeball = buildEyeball({ radius: radius * DECIMETRE });
  const eyeParts = [
    { geometry: eyeball.sclera, material: MATERIALS.sclera },
    { geometry: eyeball.iris, material: MATERIALS.iris },
    { geometry: eyeball.cornea, material: MATERIALS.cornea },
  ];

  // Vertices stay in head space; the nodes under the jaw undo the jaw's translation, so turning the jaw node turns
  // them about the hinge.
  const tongue: TriGeometry = toRenderMesh(catmullClark(source.tongue), DECIMETRE);
  // The base mesh's tongue stands above the lower teeth's edges and as wide as the molars: lowered and narrowed a
  // little, it lies in the floor of the mouth inside the lower arch, so that an open mouth shows the lower teeth.
  for (let i = 0; i < tongue.positions.length; i += 3) {
    tongue.positions[i] *= TONGUE_NARROWING;
    tongue.positions[i + 1] -= TONGUE_DROP;
    // Normals of a surface squeezed along x turn toward x by the inverse factor.
    const n = [tongue.normals[i] / TONGUE_NARROWING, tongue.normals[i + 1], tongue.normals[i + 2]];
    const length = Math.hypot(n[0], n[1], n[2]);
    for (let k = 0; k < 3; k++) tongue.normals[i + k] = n[k] / length;
  }
  // The base mesh's low-poly teeth say where the rows sit: the arches are fitted to them.
  const upperBand = group('helper-upper-teeth').map((p) => p * DECIMETRE);
  const lowerBand = group('helper-lower-teeth').map((p) => p * DECIMETRE);
  const occlusal = fitOcclusalPlane(upperBand, lowerBand);
  const archParts = (arch: DentalArch): PartSpec[] => [
    { geometry: arch.teeth, material: MATERIALS.teeth },
    { geometry: arch.gums, material: MATERIALS.gums },
  ];
  return {
    pivots,
    eyeRadius: radius * DECIMETRE,
    eyeParts,
    upperArch: archParts(buildArch(fitArchOutline(upperBand), occlusal, 1)),
    lowerArch: archParts(buildArch(fitArchOutline(lowerBand), occlusal, -1)),
    tongue,
    neckLoopVertices: source.cut.neckLoop.length,
  };
}

/** One resolution of a head: its skin (the cut head subdivided `subdivisions` times) with the shared parts. */
export function buildHeadLevel(cut: HeadCut, parts: HeadParts, { name, subdivisions }: (typeof LEVELS)[number]): BuiltHead {
  const mesh = subdivide(cut.mesh, subdivisions);
  const skin = toRenderMesh(mesh, DECIMETRE);
  const stats: LevelStats = {
    name,
    subdivisions,
    skinVertices: vertexCount(mesh),
    renderVertices: skin.positions.length / 3,
    quads: faceCount(mesh),
    triangles: skin.indices.length / 3,
  };
  const { pivots } = parts;
  const hinge = pivots['jaw-hinge'];
  const negHinge: [number, number, number] = [-hinge[0], -hinge[1], -hinge[2]];
  const root: NodeSpec = {
    name: 'head',
    children: [
      { name: HEAD_NODES.skin, parts: [{ geometry: skin, material: MATERIALS.skin }] },
      ...HEAD_NODES.eyes.map((eye) => ({
        name: eye,
        translation: pivots[eye],
        meshName: 'eyeball',
        parts: parts.eyeParts,
        extras: { softface: { pivot: eye } },
      })),
      { name: HEAD_NODES.upperTeeth, parts: parts.upperArch },
      {
        name: HEAD_NODES.jaw,
        translation: hinge,
        extras: { softface: { pivot: 'jaw-hinge' } },
        children: [
          { name: HEAD_NODES.lowerTeeth, translation: negHinge, parts: parts.lowerArch },
          { name: HEAD_NODES.tongue, translation: negHinge, parts: [{ geometry: parts.tongue, material: MATERIALS.tongue }] },
        ],
      },
      {
        name: 'pivots',
        children: Object.entries(pivots).map(([pivot, at]) => ({
          name: `pivot-${pivot}`,
          translation: at,
          extras: { softface: { pivot } },
        })),
      },
    ],
  };
  const sceneExtras = {
    softface: {
      format: 'softface-head',
      version: 1,
      units: 'metres',
      up: '+y',
      forward: '+z',
      left: "+x (the subject's left)",
      source: 'MakeHuman hm08 base mesh (CC0 1.0)',
      level: stats,
      eyeRadius: parts.eyeRadius,
      neckLoopVertices: parts.neckLoopVertices,
      pivots,
    },
  };
  return { stats, root, sceneExtras };
}

/**
 * Builds every resolution of the head from a parsed base mesh. `cutStart` is the body vertex the neck cut starts at
 * (see neckCutStart): a mesh moved by identity targets passes the base mesh's, so that every identity's head has the
 * same vertices and faces.
 */
export function buildHeadLevels(obj: ObjMesh, cutStart?: number): BuiltHead[] {
  const source = headSource(obj, cutStart);
  const parts = buildHeadParts(source);
  return LEVELS.map((level) => buildHeadLevel(source.cut, parts, level));
}

const scaled = (p: [number, number, number]): [number, number, number] => [p[0] * DECIMETRE, p[1] * DECIMETRE, p[2] * DECIMETRE];
