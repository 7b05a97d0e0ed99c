import { checkBoolean, checkObject, refusal } from '../core/check';
import { MAX_EXPORT_FPS } from '../core/expression/morph-export';

/** How far `exportGLTF` has come: targets solved so far of all, and the one it solves now (null once all are). */
export interface GLTFExportProgress {
  /** Morph targets solved so far, 0..`total`. */
  done: number;
  /** Morph targets the export solves: those asked for, and those the exported timeline needs besides. */
  total: number;
  /** The morph target being solved now (an Action Unit id such as `AU12L`, or a preset's name); null once all are. */
  target: string | null;
}

/** Options of `face.exportGLTF`. */
export interface GLTFExportOptions {
  /** Action Units to export as morph targets, by id as `setActionUnit` takes them (`AU12`, `AU12L`, `AU17`). */
  actionUnits?: string[];
  /** Presets of the rig to export as morph targets, by name. */
  presets?: string[];
  /** Whether to export the loaded timeline as an animation of the morph weights; null: if one is loaded. */
  timeline?: boolean | null;
  /** Samples per second of the timeline's animation (above 0, at most 120). */
  fps?: number;
  /** A GLB (true) or a glTF JSON document with everything inline (false). */
  binary?: boolean;
  /** How long each target may take to settle, in ms. */
  settleTimeoutMs?: number;
  /** Told before each target is solved, and once all are. */
  onProgress?: ((progress: GLTFExportProgress) => void) | null;
  /** Aborts the export: the face gets its expression back and the promise rejects with the signal's reason. */
  signal?: AbortSignal | null;
}

export const GLTF_EXPORT_DEFAULTS: Readonly<Required<GLTFExportOptions>> = Object.freeze({
  actionUnits: [],
  presets: [],
  timeline: null,
  fps: 30,
  binary: true,
  settleTimeoutMs: 60_000,
  onProgress: null,
  signal: null,
});

/**
 * The options with their defaults, checked: an unknown option or a value of the wrong type or range throws naming the
 * option (the ids and preset names are checked against the face by `planTargets`).
 */
export function checkExportOptions(options: unknown, what = 'exportGLTF'): Required<GLTFExportOptions> {
  if (options === undefined) return { ...GLTF_EXPORT_DEFAULTS };
  for (const key of Object.keys(checkObject(what, options)))
    if (!(key in GLTF_EXPORT_DEFAULTS)) throw refusal(what, '', `one of the options ${Object.keys(GLTF_EXPORT_DEFAULTS).join(', ')}`, key);
  const o = { ...GLTF_EXPORT_DEFAULTS, ...(options as GLTFExportOptions) };
  for (const [key, list] of [
    ['actionUnits', o.actionUnits],
    ['presets', o.presets],
  ] as const) {
    if (!Array.isArray(list) || !list.every((x) => typeof x === 'string')) throw refusal(what, key, 'an array of strings', list);
  }
  if (o.timeline !== null && typeof o.timeline !== 'boolean') throw refusal(what, 'timeline', 'true or false', o.timeline);
  if (typeof o.fps !== 'number' || !Number.isFinite(o.fps) || o.fps <= 0 || o.fps > MAX_EXPORT_FPS)
    throw refusal(what, 'fps', `a number above 0 and at most ${MAX_EXPORT_FPS}`, o.fps);
  checkBoolean(what, 'binary', o.binary);
  if (typeof o.settleTimeoutMs !== 'number' || !(o.settleTimeoutMs > 0))
    throw refusal(what, 'settleTimeoutMs', 'a positive number of ms', o.settleTimeoutMs);
  if (o.onProgress !== null && typeof o.onProgress !== 'function') throw refusal(what, 'onProgress', 'a function', o.onProgress);
  if (o.signal !== null && !(o.signal instanceof AbortSignal)) throw refusal(what, 'signal', 'an AbortSignal', o.signal);
  return { ...o, actionUnits: [...o.actionUnits], presets: [...o.presets] };
}
