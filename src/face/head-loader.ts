import type { Mesh } from 'three';
import { checkObject, refusal } from '../core/check';
import {
  AXES,
  UNITS,
  applyHeadTransform,
  checkHeadMesh,
  findHeadTransform,
  mergeVertices,
  positionBounds,
  weldSeams,
  type Axis,
  type HeadTransform,
  type TriangleMesh,
  type Unit,
} from '../core/head/head-mesh';
import { decimateHead, LEVEL_TRIANGLES, levelPlan, subdivideHead, type HeadLevel, type LevelPlan } from '../core/head/head-levels';
import {
  DEFAULT_LANDMARKS,
  findLandmarks,
  LANDMARK_LABELS,
  LANDMARK_NAMES,
  type LandmarkName,
  type Landmarks,
} from '../core/head/landmarks';
import type { Identity, NamedIdentity } from '../core/head/identity';
import { parseRig } from '../core/rig/rig-schema';
import type { Rig, Vec3 } from '../core/rig/rig-types';
import { warpRig } from '../core/rig/rig-warp';
import { fitJawToSkinLips } from '../core/rig/jaw-lips';
import { fitThinPlate } from '../core/head/thin-plate';
import { buildLoadedHead, readHeadScene, skinOf, type HeadFile, type PartSources } from '../render/head-import';
import { disposeHead, loadHeadModel, type HeadModel } from '../render/head-model';

export type { HeadFile, PartSources };

/** How `loadHead` reads a head; every option may be left out. */
export interface LoadHeadOptions {
  /** The name of the skin's mesh (or of its node); by default the largest mesh that is not an eye or teeth. */
  skin?: string | null;
  /** The file's units (`m`, `dm`, `cm`, `mm`), or `auto`: the power of ten that makes the head head-sized. */
  units?: Unit | 'auto';
  /** The file's axis that points up (`+y`, `-z`, ...), or `auto`: away from the neck opening, else +y. */
  up?: Axis | 'auto';
  /** The file's axis the face looks along, or `auto`: across the head's symmetry plane, toward the nose. */
  forward?: Axis | 'auto';
  /**
   * Landmarks given instead of found (some or all), in metres in the app's frame (after units and orientation:
   * +y up, the face toward +z, the subject's left at +x, the midline at x = 0). Names as `LANDMARK_NAMES`.
   */
  landmarks?: Partial<Record<LandmarkName, Vec3>> | null;
  /**
   * The resolution to show it at: `low`, `medium` or `high` aim at the default head's triangle counts (8,524, 34,096,
   * 136,384) by Catmull-Clark subdivision or decimation, never above 200,000 triangles; `file` keeps the file's mesh;
   * null: the face's resolution.
   */
  resolution?: HeadLevel | 'file' | null;
}

export const LOAD_HEAD_DEFAULTS: Readonly<Required<LoadHeadOptions>> = Object.freeze({
  skin: null,
  units: 'auto',
  up: 'auto',
  forward: 'auto',
  landmarks: null,
  resolution: null,
});

/** The largest head file taken: a 200,000-triangle mesh with uvs and normals is some 20 MB as GLB, 30 MB as OBJ. */
export const MAX_HEAD_FILE_BYTES = 64 * 1024 * 1024;

/** What a face shows: the default head or a loaded one, its size, frame and landmarks (read-only). */
export interface HeadDescription {
  /** The default head, a loaded one or an identity's (see `setIdentity`). */
  source: 'default' | 'loaded' | 'identity';
  /** The file's name (the default head's model file for the default head). */
  name: string;
  /** The resolution shown: a level (the default head's, or reached by subdivision or decimation) or the file's own mesh. */
  level: HeadLevel | 'file';
  /** Welded skin vertices: the solver's, as `getSkin` gives them. */
  vertices: number;
  /** Triangles of the skin mesh shown. */
  triangles: number;
  /** Units and axes the file was read with (the default head's are metres, +y, +z). */
  units: Unit;
  /** The file's axis that points up, as given or found (`+y` for the default head and an identity's). */
  up: Axis;
  /** The file's axis the face looks along, as given or found (`+z` for the default head and an identity's). */
  forward: Axis;
  /**
   * The head's landmarks in metres in the app's frame (+y up, the face toward +z): for a loaded head those the rig was
   * carried over by (found, given or placed), for an identity's the default head's carried over with its shape.
   */
  landmarks: Landmarks;
  /** Where the eyes, teeth and jaw pivot came from: the file's named nodes, or the default head (carried over). */
  parts: PartSources;
  /** Milliseconds from the start of `loadHead` or `setIdentity` to the new head shown (0 for the default head). */
  loadMs: number;
  /** The person an identity's head shows (null for the default head and a loaded one). */
  identity: Identity | null;
}

/** A head read, checked and fitted, with its rig carried over: ready to be shown. */
export interface PreparedHead {
  head: HeadModel;
  sources: PartSources;
  level: HeadLevel | 'file';
  rig: Rig;
  landmarks: Landmarks;
  transform: HeadTransform;
  files: HeadFile[];
  options: Required<LoadHeadOptions>;
  /** Set for an identity's head (built in the page, see identity-head.ts; `files` is then empty). */
  identity?: NamedIdentity;
}

/**
 * A head whose landmarks could not all be found: the message names them and why. It carries what is needed to place
 * the missing ones by hand (`face.guideLandmarks`): the skin in the app's frame and the landmarks found.
 */
export class MissingLandmarksError extends Error {
  override readonly name = 'MissingLandmarksError';
  constructor(
    message: string,
    readonly missing: LandmarkName[],
    readonly found: Partial<Landmarks>,
    /** The skin as it would be shown, in metres in the app's frame. */
    readonly skin: TriangleMesh,
  ) {
    super(message);
  }
}

/** Checks `loadHead` options and fills in the defaults; throws naming the first bad one. */
export function checkLoadHeadOptions(options: unknown): Required<LoadHeadOptions> {
  if (options === undefined || options === null) return { ...LOAD_HEAD_DEFAULTS };
  const out: Record<string, unknown> = { ...LOAD_HEAD_DEFAULTS };
  for (const [key, value] of Object.entries(checkObject('loadHead', options))) {
    if (value === undefined) continue;
    const bad = (expected: string): Error => refusal('loadHead', key, expected, value);
    switch (key) {
      case 'skin':
        if (value !== null && (typeof value !== 'string' || value === '')) throw bad('a mesh name');
        break;
      case 'units':
        if (value !== 'auto' && !(typeof value === 'string' && value in UNITS)) throw bad(`one of auto, ${Object.keys(UNITS).join(', ')}`);
        break;
      case 'up':
      case 'forward':
        if (value !== 'auto' && !AXES.includes(value as Axis)) throw bad(`one of auto, ${AXES.join(', ')}`);
        break;
      case 'resolution':
        if (value !== null && value !== 'file' && !(typeof value === 'string' && value in LEVEL_TRIANGLES))
          throw bad(`one of ${Object.keys(LEVEL_TRIANGLES).join(', ')}, file`);
        break;
      case 'landmarks':
        if (value === null) break;
        if (typeof value !== 'object' || Array.isArray(value)) throw bad('an object of points');
        for (const [name, p] of Object.entries(value)) {
          if (!LANDMARK_NAMES.includes(name as LandmarkName))
            throw refusal('loadHead', 'landmarks', `one of the landmarks ${LANDMARK_NAMES.join(', ')}`, name);
          if (!Array.isArray(p) || p.length !== 3 || !p.every((x) => typeof x === 'number' && Number.isFinite(x))) {
            throw refusal('loadHead', `landmarks.${name}`, '[x, y, z] in metres', p);
          }
        }
        break;
      default:
        throw refusal('loadHead', '', `one of the options ${Object.keys(LOAD_HEAD_DEFAULTS).join(', ')}`, key);
    }
    out[key] = value;
  }
  return out as unknown as Required<LoadHeadOptions>;
}

/** A head given to `loadHead`: a URL, a file (or a `.gltf` with its side files), or files read already. */
export type HeadSource = string | URL | File | readonly File[] | FileList | readonly HeadFile[];

/** Reads the source's bytes; refuses a file over `MAX_HEAD_FILE_BYTES` before reading it. */
export async function readHeadFiles(source: HeadSource): Promise<HeadFile[]> {
  const tooBig = (name: string, size: number): Error =>
    new Error(`${name}: the file is ${(size / 1e6).toFixed(1)} MB, more than the ${MAX_HEAD_FILE_BYTES / 1024 / 1024} MB a head may be`);
  if (typeof source === 'string' || source instanceof URL) {
    const url = new URL(String(source), document.baseURI);
    const name = decodeURIComponent(url.pathname.split('/').pop() || url.href);
    let response: Response;
    try {
      response = await fetch(url);
    } catch (error) {
      throw new Error(`${url.href}: could not be fetched (${(error as Error).message})`);
    }
    if (!response.ok) throw new Error(`${url.href}: could not be fetched (${response.status} ${response.statusText})`);
    const length = Number(response.headers.get('content-length'));
    if (length > MAX_HEAD_FILE_BYTES) throw tooBig(name, length);
    const bytes = await response.arrayBuffer();
    if (bytes.byteLength > MAX_HEAD_FILE_BYTES) throw tooBig(name, bytes.byteLength);
    return [{ name, bytes }];
  }
  const list = source instanceof File ? [source] : Array.from(source as ArrayLike<File | HeadFile>);
  if (list.length === 0) throw new Error('loadHead: no file given');
  return Promise.all(
    list.map(async (f) => {
      if (!(f instanceof Blob)) {
        if (typeof f?.name !== 'string' || !(f.bytes instanceof ArrayBuffer))
          throw new Error('loadHead: a file must be a File or { name, bytes: ArrayBuffer }');
        return f;
      }
      if (f.size > MAX_HEAD_FILE_BYTES) throw tooBig(f.name, f.size);
      return { name: f.name, bytes: await f.arrayBuffer() };
    }),
  );
}

/**
 * Reads a head from its files, checks it, finds its frame and landmarks, carries `original` (a rig made on the default
 * head) over to it and builds it with the default head's parts (`defaultModelUrl`) where the file has none. Throws,
 * naming the file and what is wrong, before anything is shown.
 */
export async function prepareHead(
  files: HeadFile[],
  options: Required<LoadHeadOptions>,
  defaultModelUrl: string,
  original: Rig,
  level: HeadLevel | 'file',
): Promise<PreparedHead> {
  const { scene, file } = await readHeadScene(files);
  const source = file.name;
  const read = skinOf(scene, source, options.skin).mesh;
  checkHeadMesh(read, source);
  const { min, max } = positionBounds(read.positions);
  weldSeams(read.positions, 1e-6 * Math.hypot(max[0] - min[0], max[1] - min[1], max[2] - min[2]));
  const mesh = mergeVertices(read);
  const transform = findHeadTransform(mesh.positions, mesh.indices, options, source);
  applyHeadTransform(mesh.positions, transform);
  const search = findLandmarks(mesh.positions, mesh.indices);
  const found = { ...search.found, ...(options.landmarks ?? {}) } as Partial<Landmarks>;
  const missing = search.missing.filter((m) => !found[m.name]);
  if (missing.length > 0) {
    const reasons = [...new Set(missing.map((m) => m.reason))].map((reason) => {
      const names = missing.filter((m) => m.reason === reason).map((m) => LANDMARK_LABELS[m.name]);
      return `${names.join(', ')} (${reason})`;
    });
    throw new MissingLandmarksError(
      `${source}: no face was found on the mesh: ${reasons.join('; ')}. Place them by clicking ("place ` +
        `landmarks" in the Head folder) or give them in options.landmarks, or check its units and axes`,
      missing.map((m) => m.name),
      found,
      mesh,
    );
  }
  const landmarks = found as Landmarks;
  const warp = fitThinPlate(
    LANDMARK_NAMES.map((n) => [...DEFAULT_LANDMARKS[n]] as Vec3),
    LANDMARK_NAMES.map((n) => landmarks[n]),
  );
  const rig = parseRig(warpRig(original, warp), `${source}: the rig carried over`);
  // The landmarks are the file's mesh's; the level's mesh is what the solver moves and the page shows.
  const plan: LevelPlan = level === 'file' ? { subdivisions: 0 } : levelPlan(mesh.indices.length / 3, level);
  const shown = 'decimateTo' in plan ? await decimateHead(mesh, plan.decimateTo) : subdivideHead(mesh, plan.subdivisions);
  const defaults = await loadHeadModel(defaultModelUrl);
  let built: ReturnType<typeof buildLoadedHead>;
  try {
    built = buildLoadedHead(shown, landmarks, { scene, transform, defaults, warp });
  } catch (error) {
    disposeHead(defaults);
    throw error;
  }
  const { head, sources } = built;
  return { head, level, sources, rig: jawOnLips(rig, head.skin, landmarks), landmarks, transform, files, options };
}

/**
 * A carried rig with its jaw's top face put back in the gap between the shown skin's lips at rest (see
 * `fitJawToLips`); as it is where the lips have no gap at the midline.
 */
export function jawOnLips(rig: Rig, skin: Mesh, landmarks: Landmarks): Rig {
  const geometry = skin.geometry;
  const positions = geometry.getAttribute('position').array;
  const normals = geometry.getAttribute('normal').array;
  return fitJawToSkinLips(rig, positions, normals, landmarks['mouth-l'], landmarks['mouth-r']);
}

/**
 * What `describeHead` reports for a head just shown: a loaded one (`prepared`) or the default head, whose level, file
 * name, counts and load time are given.
 */
export function describeShownHead(
  prepared: PreparedHead | undefined,
  shown: { level: HeadLevel; file: string; vertices: number; triangles: number; loadMs: number },
): HeadDescription {
  const transform = prepared?.transform;
  const identity = prepared?.identity;
  return {
    source: identity ? 'identity' : prepared ? 'loaded' : 'default',
    level: prepared ? prepared.level : shown.level,
    name: identity ? identity.name : prepared ? prepared.files[0].name : shown.file,
    vertices: shown.vertices,
    triangles: shown.triangles,
    units: transform?.units ?? 'm',
    up: transform?.up ?? '+y',
    forward: transform?.forward ?? '+z',
    landmarks: structuredClone(prepared ? prepared.landmarks : (DEFAULT_LANDMARKS as Landmarks)),
    parts: prepared ? { ...prepared.sources } : { eyes: 'file', teeth: 'file', jaw: 'file' },
    loadMs: shown.loadMs,
    identity: identity ? structuredClone(identity.identity) : null,
  };
}
