/**
 * The identity source: everything the head builder reads of MakeHuman's base.obj and macro targets, restricted to what
 * it needs, in one compact file (`public/models/identity-source.bin`), so that a head for any identity can be built at
 * run time without base.obj or the target files (identity-head.ts builds it). Pure: no DOM, no Node.
 *
 * Layout (little-endian). A 12-byte header, then a zlib stream (fflate) of the payload:
 *
 *   header   0  4 bytes   MAGIC, "SFIS"
 *            4  u32       FORMAT_VERSION
 *            8  u32       the payload's length in bytes, uncompressed
 *   payload     u32 × 4   V stored vertices, U uvs, G groups, T targets
 *               u32[V]    each stored vertex's base.obj vertex (0-based `v` line), ascending
 *               i32[3V]   base positions in POSITION_UNIT (decimetres × 1e4), all x, then all y, then all z
 *               i32[2U]   uvs in UV_UNIT (× 1e6), all u, then all v
 *   G × group   name      u8 length, then that many ASCII bytes
 *               u32 × 3   n vertices, f faces, c corners (f = c = 0 for a group read for its positions only)
 *               u32[n]    each vertex's stored vertex, ascending (so in base.obj's order)
 *               u8[f]     each face's corner count
 *               u32[c]    each corner's vertex, an index into the group's n vertices
 *               u32[c]    each corner's uv, an index into the U uvs (a face without uvs in the OBJ has 0, 0)
 *   T × target  name      u8 length, then ASCII (the target file's name without `.target.gz`)
 *               i16[3V]   offsets in OFFSET_UNIT (decimetres × 1e3), all x, then all y, then all z; 0 where the file
 *                         does not list the vertex
 *
 * The units are the source files' own decimals (base.obj has 4 for positions and 6 for uvs, the targets 3), so the
 * numbers read back are exactly those the OBJ and target parsers give: the writer checks this and refuses otherwise.
 */
import { unzlibSync, zlibSync } from 'fflate';
import type { MacroTarget } from '../identity';
import { toRenderMesh, type PolyMesh } from '../polymesh';
import { boundaryLoops } from './cut';
import { cutHead, groupMesh, POSITION_GROUPS, sourceMesh, TONGUE_GROUP } from './head-build';
import type { ObjMesh } from './obj';

/** The file's name, which every error about its bytes starts with. */
const FILE = 'identity-source.bin';
/** "SFIS": softface identity source. */
const MAGIC = [0x53, 0x46, 0x49, 0x53] as const;
const FORMAT_VERSION = 1;
const HEADER_BYTES = 12;
/** Stored integers per decimetre (positions, offsets) or per uv unit. */
const POSITION_UNIT = 1e4;
const UV_UNIT = 1e6;
const OFFSET_UNIT = 1e3;

/** The group of the identity source holding the head cut off the body at the neck (its faces and uvs). */
export const CUT_HEAD_GROUP = 'cut-head';

/** The 24 macro targets an identity is made of (macroTargetWeights): ancestry, sex and age group. */
export const ETHNIC_TARGETS: readonly string[] = ['african', 'asian', 'caucasian'].flatMap((ancestry) =>
  ['female', 'male'].flatMap((sex) => ['baby', 'child', 'young', 'old'].map((age) => `${ancestry}-${sex}-${age}`)),
);

/** One group of the identity source: its vertices and, for the cut head and the tongue, its faces. */
export interface IdentitySourceGroup {
  /** Index into IdentitySource.vertices of each of the group's vertices, ascending. */
  vertices: Uint32Array;
  /** Faces as in PolyMesh: `faceStart` offsets into `corners` (indices into `vertices`), a uv per corner. */
  faceStart: Uint32Array;
  corners: Uint32Array;
  cornerUVs: Float64Array;
}

/** A read identity source: the stored vertices of the base mesh, its groups and the targets' offsets. */
export interface IdentitySource {
  /** base.obj's vertex (0-based `v` line) of each stored vertex, ascending. */
  vertices: Uint32Array;
  /** xyz per stored vertex, decimetres: base.obj's numbers. */
  positions: Float64Array;
  /** CUT_HEAD_GROUP, TONGUE_GROUP and the POSITION_GROUPS by name. */
  groups: ReadonlyMap<string, IdentitySourceGroup>;
  /** Each of ETHNIC_TARGETS: xyz per stored vertex, decimetres, as float32 as parseMacroTarget reads them. */
  targets: ReadonlyMap<string, Float32Array>;
  /** The cut head's neck loop, as indices into its vertices (found on reading: it depends on the faces alone). */
  neckLoop: number[];
  /** The stored vertex of each render vertex of the low level's skin, in head-low.glb's order (seam copies repeat). */
  skinRenderVertex: Uint32Array;
}

/**
 * Writes the identity source of a parsed base mesh (unmoved) and the ETHNIC_TARGETS (by name, as parseMacroTarget
 * reads them): the head is cut where buildHeadLevels cuts the base mesh. The same input always gives the same bytes.
 */
export function writeIdentitySource(obj: ObjMesh, targets: ReadonlyMap<string, MacroTarget>): Uint8Array {
  const source = sourceMesh(obj);
  const cut = cutHead(source);
  const groups: [string, PolyMesh, Uint32Array][] = [[CUT_HEAD_GROUP, cut.mesh, cut.sourceVertex]];
  for (const name of [...POSITION_GROUPS, TONGUE_GROUP]) {
    const g = groupMesh(source, name);
    // Groups read for their positions only keep no faces: the builder never looks at them.
    const mesh =
      name === TONGUE_GROUP
        ? g.mesh
        : { ...g.mesh, faceStart: new Uint32Array(1), corners: new Uint32Array(0), cornerUVs: new Float64Array(0) };
    groups.push([name, mesh, g.sourceVertex]);
  }
  const objVertices = [...new Set(groups.flatMap(([, , vertices]) => [...vertices]))].sort((a, b) => a - b);
  const stored = new Map(objVertices.map((v, i) => [v, i]));
  const V = objVertices.length;

  const uvKeys = new Map<string, number>();
  const uvs: number[] = [];
  const uvIndex = (u: number, v: number): number => {
    const key = `${u},${v}`;
    let i = uvKeys.get(key);
    if (i === undefined) {
      i = uvs.length / 2;
      uvKeys.set(key, i);
      uvs.push(u, v);
    }
    return i;
  };
  // Built before the header because the uv table is filled on the way.
  const groupBytes = new ByteWriter();
  for (const [name, mesh, vertices] of groups) {
    groupBytes.name(name);
    const f = mesh.faceStart.length - 1;
    groupBytes.u32s([vertices.length, f, mesh.corners.length]);
    groupBytes.u32s(Array.from(vertices, (v) => stored.get(v) as number));
    groupBytes.u8s(Array.from({ length: f }, (_, i) => mesh.faceStart[i + 1] - mesh.faceStart[i]));
    groupBytes.u32s(mesh.corners);
    // Faces without texture coordinates got uv 0, 0 from sourceMesh: stored as such, as the builder sees them.
    groupBytes.u32s(Array.from(mesh.corners, (_, c) => uvIndex(mesh.cornerUVs[2 * c], mesh.cornerUVs[2 * c + 1])));
  }

  const out = new ByteWriter();
  out.u32s([V, uvs.length / 2, groups.length, ETHNIC_TARGETS.length]);
  out.u32s(objVertices);
  out.i32s(
    planar(objVertices.length, (i, k) => quantise(obj.positions[3 * objVertices[i] + k], POSITION_UNIT, `vertex ${objVertices[i]}`)),
  );
  out.i32s(planar(uvs.length / 2, (i, k) => quantise(uvs[2 * i + k], UV_UNIT, `uv ${i}`), 2));
  out.bytes(groupBytes.concat());
  for (const name of ETHNIC_TARGETS) {
    const target = targets.get(name);
    if (!target) throw new Error(`${FILE}: the target "${name}" was not given`);
    const dense = new Float32Array(3 * V);
    target.indices.forEach((v, i) => {
      const s = stored.get(v);
      if (s !== undefined) dense.set(target.offsets.subarray(3 * i, 3 * i + 3), 3 * s);
    });
    out.name(name);
    out.i16s(planar(V, (i, k) => quantise(dense[3 * i + k], OFFSET_UNIT, `target ${name}, stored vertex ${i}`, true)));
  }
  const payload = out.concat();
  const packed = zlibSync(payload, { level: 9, mem: 12 });
  const file = new Uint8Array(HEADER_BYTES + packed.length);
  const view = new DataView(file.buffer);
  file.set(MAGIC, 0);
  view.setUint32(4, FORMAT_VERSION, true);
  view.setUint32(8, payload.length, true);
  file.set(packed, HEADER_BYTES);
  return file;
}

/**
 * Reads an identity source written by writeIdentitySource; throws `identity-source.bin: ...` naming what is wrong
 * when the bytes are not one (another magic or version, truncated or damaged data, an index out of range, a group or
 * target missing).
 */
export function readIdentitySource(bytes: Uint8Array): IdentitySource {
  if (bytes.length < HEADER_BYTES) throw new Error(`${FILE}: truncated: ${bytes.length} bytes, less than the ${HEADER_BYTES}-byte header`);
  if (MAGIC.some((b, i) => bytes[i] !== b)) {
    const found = Array.from(bytes.subarray(0, 4), (b) => b.toString(16).padStart(2, '0')).join(' ');
    throw new Error(`${FILE}: not an identity source: it starts with bytes ${found}, not "SFIS"`);
  }
  const header = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const version = header.getUint32(4, true);
  if (version !== FORMAT_VERSION) throw new Error(`${FILE}: format version ${version}; this reader reads version ${FORMAT_VERSION}`);
  const length = header.getUint32(8, true);
  let payload: Uint8Array;
  try {
    payload = unzlibSync(bytes.subarray(HEADER_BYTES));
  } catch (e) {
    throw new Error(`${FILE}: the compressed data is truncated or damaged (${(e as Error).message})`);
  }
  if (payload.length !== length) throw new Error(`${FILE}: truncated: ${payload.length} bytes of data, the header says ${length}`);

  const r = new ByteReader(payload);
  const [V, U, G, T] = r.u32s(4);
  const vertices = r.u32s(V);
  const positions = interleave(r.i32s(3 * V), 3, POSITION_UNIT, Float64Array);
  const uvs = interleave(r.i32s(2 * U), 2, UV_UNIT, Float64Array);
  const groups = new Map<string, IdentitySourceGroup>();
  for (let g = 0; g < G; g++) {
    const name = r.name();
    const [n, f, c] = r.u32s(3);
    const groupVertices = r.u32s(n);
    const sizes = r.u8s(f);
    const corners = r.u32s(c);
    const uvOf = r.u32s(c);
    const faceStart = new Uint32Array(f + 1);
    for (let i = 0; i < f; i++) faceStart[i + 1] = faceStart[i] + sizes[i];
    if (faceStart[f] !== c) throw new Error(`${FILE}: group "${name}": its faces have ${faceStart[f]} corners, not ${c}`);
    inRange(groupVertices, V, `group "${name}": a vertex`, 'stored vertices');
    inRange(corners, n, `group "${name}": a corner`, 'vertices of the group');
    const cornerUVs = new Float64Array(2 * c);
    uvOf.forEach((t, i) => {
      if (t >= U) throw new Error(`${FILE}: group "${name}": corner ${i} has uv ${t}, but there are ${U}`);
      cornerUVs[2 * i] = uvs[2 * t];
      cornerUVs[2 * i + 1] = uvs[2 * t + 1];
    });
    groups.set(name, { vertices: groupVertices, faceStart, corners, cornerUVs });
  }
  const targets = new Map<string, Float32Array>();
  for (let t = 0; t < T; t++) {
    const name = r.name();
    targets.set(name, interleave(r.i16s(3 * V), 3, OFFSET_UNIT, Float32Array));
  }
  if (r.left() > 0) throw new Error(`${FILE}: ${r.left()} bytes left over after the last target`);
  for (const name of [CUT_HEAD_GROUP, TONGUE_GROUP, ...POSITION_GROUPS])
    if (!groups.has(name)) throw new Error(`${FILE}: the group "${name}" is missing`);
  for (const name of ETHNIC_TARGETS) if (!targets.has(name)) throw new Error(`${FILE}: the target "${name}" is missing`);

  const head = groups.get(CUT_HEAD_GROUP) as IdentitySourceGroup;
  const mesh: PolyMesh = { ...head, positions: new Float64Array(3 * head.vertices.length) };
  const neckLoop = boundaryLoop(mesh);
  const skinRenderVertex = toRenderMesh(mesh).sourceVertex.map((v) => head.vertices[v]);
  return { vertices, positions, groups, targets, neckLoop, skinRenderVertex };
}

/** The one boundary loop of the cut head, as cutHead finds it. */
function boundaryLoop(mesh: PolyMesh): number[] {
  const loops = boundaryLoops(mesh);
  if (loops.length !== 1) throw new Error(`${FILE}: the cut head should have one boundary loop, it has ${loops.length}`);
  return loops[0];
}

/** The integer `x` is stored as in `unit`s; throws unless it reads back as exactly `x` (and fits an i16 if `short`). */
function quantise(x: number, unit: number, where: string, short = false): number {
  const q = Math.round(x * unit);
  const back = short ? Math.fround(q / unit) : q / unit;
  if (!Object.is(back, x) || Math.abs(q) > (short ? 0x7fff : 0x7fffffff))
    throw new Error(`${FILE}: ${where}: ${x} is not a whole number of 1/${unit} that fits the file`);
  return q;
}

/** `count` items of `width` components, given per (item, component), as all first components, then all second... */
function planar(count: number, value: (i: number, k: number) => number, width = 3): number[] {
  const out: number[] = [];
  for (let k = 0; k < width; k++) for (let i = 0; i < count; i++) out.push(value(i, k));
  return out;
}

/** The inverse of planar, divided by `unit`. */
function interleave<A extends Float64Array | Float32Array>(
  values: Int32Array | Int16Array,
  width: number,
  unit: number,
  Out: new (length: number) => A,
): A {
  const count = values.length / width;
  const out = new Out(values.length);
  for (let k = 0; k < width; k++) for (let i = 0; i < count; i++) out[width * i + k] = values[k * count + i] / unit;
  return out;
}

function inRange(values: Uint32Array, limit: number, what: string, of: string): void {
  for (const v of values) if (v >= limit) throw new Error(`${FILE}: ${what} is ${v}, but there are ${limit} ${of}`);
}

/** Appends little-endian numbers to a growing list of chunks. */
class ByteWriter {
  private readonly chunks: Uint8Array[] = [];

  bytes(b: Uint8Array): void {
    this.chunks.push(b);
  }

  u8s(values: ArrayLike<number>): void {
    for (let i = 0; i < values.length; i++)
      if (!(values[i] >= 0 && values[i] <= 0xff)) throw new Error(`${FILE}: ${values[i]} does not fit a byte (a face's corners?)`);
    this.bytes(Uint8Array.from(values));
  }

  u32s(values: ArrayLike<number>): void {
    this.typed(values, 4, (d, i, x) => d.setUint32(i, x, true));
  }

  i32s(values: ArrayLike<number>): void {
    this.typed(values, 4, (d, i, x) => d.setInt32(i, x, true));
  }

  i16s(values: ArrayLike<number>): void {
    this.typed(values, 2, (d, i, x) => d.setInt16(i, x, true));
  }

  /** A short ASCII name: its length as one byte, then its bytes. */
  name(s: string): void {
    if (!/^[\x20-\x7e]{1,255}$/.test(s)) throw new Error(`${FILE}: the name "${s}" is not 1 to 255 ASCII characters`);
    this.u8s([s.length, ...Array.from(s, (ch) => ch.charCodeAt(0))]);
  }

  concat(): Uint8Array {
    const out = new Uint8Array(this.chunks.reduce((n, c) => n + c.length, 0));
    let at = 0;
    for (const c of this.chunks) {
      out.set(c, at);
      at += c.length;
    }
    return out;
  }

  private typed(values: ArrayLike<number>, size: number, set: (d: DataView, at: number, x: number) => void): void {
    const b = new Uint8Array(size * values.length);
    const d = new DataView(b.buffer);
    for (let i = 0; i < values.length; i++) set(d, size * i, values[i]);
    this.bytes(b);
  }
}

/** Whether typed arrays are little-endian here, as the file is (then its arrays are copied, not read one by one). */
const LITTLE_ENDIAN = new Uint8Array(Uint16Array.of(1).buffer)[0] === 1;

/** Reads little-endian numbers in order; throws naming the file when the data ends too soon. */
class ByteReader {
  private readonly view: DataView;
  private at = 0;

  constructor(private readonly data: Uint8Array) {
    this.view = new DataView(data.buffer, data.byteOffset, data.byteLength);
  }

  left(): number {
    return this.data.length - this.at;
  }

  u8s(n: number): Uint8Array {
    return this.data.slice(this.take(n), this.at);
  }

  u32s(n: number): Uint32Array {
    const at = this.take(4 * n);
    if (LITTLE_ENDIAN) return new Uint32Array(this.data.slice(at, this.at).buffer);
    return Uint32Array.from({ length: n }, (_, i) => this.view.getUint32(at + 4 * i, true));
  }

  i32s(n: number): Int32Array {
    const at = this.take(4 * n);
    if (LITTLE_ENDIAN) return new Int32Array(this.data.slice(at, this.at).buffer);
    return Int32Array.from({ length: n }, (_, i) => this.view.getInt32(at + 4 * i, true));
  }

  i16s(n: number): Int16Array {
    const at = this.take(2 * n);
    if (LITTLE_ENDIAN) return new Int16Array(this.data.slice(at, this.at).buffer);
    return Int16Array.from({ length: n }, (_, i) => this.view.getInt16(at + 2 * i, true));
  }

  name(): string {
    const [length] = this.u8s(1);
    return String.fromCharCode(...this.u8s(length));
  }

  /** Advances by `n` bytes, returning where they start. */
  private take(n: number): number {
    if (!(n <= this.left())) throw new Error(`${FILE}: truncated: ${n} bytes wanted at byte ${this.at} of ${this.data.length}`);
    const at = this.at;
    this.at += n;
    return at;
  }
}
