/**
 * OpenFace 2's per-frame CSV (FeatureExtraction's output: `frame, face_id, timestamp, confidence, success, ...`, the
 * Action Unit intensities `AU01_r` .. `AU45_r` on a 0..5 scale and their presence `AU01_c` .. `AU45_c`) as a
 * timeline of the Action Units this face has: one keyframe track per unit, its value the intensity over 5, or 0
 * where the presence column says the unit is absent. Frames OpenFace did not track (`success` 0) are left out, so
 * the face holds between the frames around them. Keys a straight line through their neighbours would give within
 * 0.005 are dropped, so that a long recording fits the timeline's 4096 keys per track. Pure: no DOM, no three.js.
 */
import { isActionUnitId } from '../expression/facs';
import { TIMELINE_FORMAT, TIMELINE_VERSION, type Timeline, type TimelineKey } from './timeline';

/** The most keys a timeline track holds (the timeline schema's limit). */
const MAX_KEYS = 4096;
/** A key within this of the straight line through the keys kept around it is left out. */
const KEY_TOLERANCE = 0.005;
/** Most bytes of CSV read: about an hour of frames at 30 per second with every OpenFace column. */
const MAX_OPENFACE_BYTES = 200 * 1024 * 1024;

/** A malformed OpenFace file: the message names the line and column (1-based) of the first problem. */
export class OpenFaceError extends Error {
  constructor(
    what: string,
    readonly line: number,
    readonly column: number | null,
    detail: string,
  ) {
    super(`${what}: line ${line}${column === null ? '' : `, column ${column}`}: ${detail}`);
    this.name = 'OpenFaceError';
  }
}

/** One OpenFace unit column: the face's Action Unit id and where its intensity and presence are. */
interface UnitColumn {
  id: string;
  intensity: number;
  presence: number;
  keys: TimelineKey[];
}

/**
 * Reads an OpenFace 2 CSV into a timeline (see the module's summary); throws an OpenFaceError naming the line and
 * column of the first problem: no `timestamp` column or no `AU.._r` column the face has, a row with another number of
 * cells, a cell that is not a number, timestamps that go back.
 */
export function openFaceTimeline(csv: unknown, what = 'importOpenFace'): Timeline {
  if (typeof csv !== 'string') throw new Error(`${what}: expected the text of an OpenFace CSV file, got ${typeof csv}`);
  if (csv.length > MAX_OPENFACE_BYTES) throw new Error(`${what}: the file has ${csv.length} characters, more than ${MAX_OPENFACE_BYTES}`);
  const lines = csv.split(/\r?\n/);
  const header = lines[0].split(',').map((h) => h.trim());
  const column = (name: string): number => header.indexOf(name);
  const time = column('timestamp');
  if (time < 0) throw new OpenFaceError(what, 1, null, 'expected an OpenFace header with a "timestamp" column');
  const success = column('success');
  const units: UnitColumn[] = [];
  header.forEach((name, i) => {
    const m = /^AU(\d\d)_r$/.exec(name);
    if (!m) return;
    const id = `AU${Number(m[1])}`;
    // OpenFace's units the face has not (AU28 has presence only) are left out.
    if (isActionUnitId(id)) units.push({ id, intensity: i, presence: column(`AU${m[1]}_c`), keys: [] });
  });
  if (units.length === 0) throw new OpenFaceError(what, 1, null, 'expected intensity columns like "AU12_r" of Action Units the face has');
  let start = Number.NaN;
  let last = -Infinity;
  for (let l = 1; l < lines.length; l++) {
    const text = lines[l];
    if (text.trim() === '') continue;
    const cells = text.split(',');
    if (cells.length !== header.length) {
      throw new OpenFaceError(what, l + 1, null, `expected ${header.length} cells as in the header, got ${cells.length}`);
    }
    const number = (c: number): number => {
      const v = Number(cells[c]);
      if (cells[c].trim() === '' || !Number.isFinite(v)) {
        throw new OpenFaceError(what, l + 1, c + 1, `${header[c]}: expected a number, got ${JSON.stringify(cells[c].trim())}`);
      }
      return v;
    };
    const t = number(time);
    if (success >= 0 && number(success) === 0) continue;
    if (Number.isNaN(start)) start = t;
    const at = t - start;
    if (at <= last) throw new OpenFaceError(what, l + 1, time + 1, `timestamp: expected a time after ${last + start} s, got ${t}`);
    last = at;
    for (const u of units) {
      const intensity = number(u.intensity);
      const present = u.presence < 0 || number(u.presence) !== 0;
      const value = present ? Math.min(1, Math.max(0, intensity / 5)) : 0;
      u.keys.push({ time: Math.round(at * 1e6) / 1e6, value: Math.round(value * 1e4) / 1e4 });
    }
  }
  if (Number.isNaN(start)) throw new OpenFaceError(what, lines.length, null, 'expected at least one tracked frame (success 1)');
  const tracks: Timeline['tracks'] = {};
  for (const u of units) {
    const keys = simplify(u.keys);
    if (keys.length > MAX_KEYS) {
      throw new OpenFaceError(
        what,
        lines.length,
        null,
        `${u.id} changes at ${keys.length} frames, more than a timeline track's ${MAX_KEYS} keys: split the file into shorter clips`,
      );
    }
    tracks[u.id] = { keys };
  }
  return { format: TIMELINE_FORMAT, version: TIMELINE_VERSION, duration: Math.max(last, 1e-3), tracks, actions: [] };
}

/**
 * The keys a piecewise-linear track needs: the first and last, and each between whose value differs by more than
 * KEY_TOLERANCE from the line through the key kept before it and the next one.
 */
function simplify(keys: TimelineKey[]): TimelineKey[] {
  if (keys.length <= 2) return keys;
  const out = [keys[0]];
  for (let i = 1; i < keys.length - 1; i++) {
    const a = out[out.length - 1];
    const b = keys[i + 1];
    const k = keys[i];
    const line = a.value + ((b.value - a.value) * (k.time - a.time)) / (b.time - a.time);
    if (Math.abs(k.value - line) > KEY_TOLERANCE) out.push(k);
  }
  out.push(keys[keys.length - 1]);
  return out;
}
