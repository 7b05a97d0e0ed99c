import type { Rig } from '../core/rig/rig-types';
import { ANTIALIAS_CHOICES, type Antialias, type ViewBackground } from '../render/view-options';
import { checkObject, checkOptions, numberIn, refusal } from '../core/check';
import type { SolverMode } from '../sim/shared/protocol';
import {
  APPEARANCE_DEFAULTS,
  APPEARANCE_RANGES,
  LIGHT_DEFAULTS,
  LIGHT_RANGES,
  type AppearanceOptions,
  type LightOptions,
} from '../render/view-options';
import { readExpression, type ExpressionEntries } from './expression-hash';
import { readIdentity, type Identity } from '../core/head/identity';
import { parseFACSCode } from '../core/expression/facs-code';

export type { SolverMode };

/** The head resolutions a face offers, coarsest first: the values of `Resolution`. */
export const RESOLUTIONS = ['low', 'medium', 'high'] as const;
/** The head's mesh resolution: low (4,284 skin vertices), medium (17,091) or high (68,277). */
export type Resolution = (typeof RESOLUTIONS)[number];

/** The values `solver` takes (see `SolverChoice`). */
export const SOLVER_CHOICES = ['auto', 'shared', 'transfer', 'main'] as const;
/**
 * Where the skin solver runs: `shared` (a worker on SharedArrayBuffers; needs a cross-origin isolated page),
 * `transfer` (a worker passing buffers back and forth; works anywhere), `main` (on the page's thread, within a time
 * budget per frame), or `auto`: `shared` where the page is isolated, `transfer` elsewhere.
 */
export type SolverChoice = (typeof SOLVER_CHOICES)[number];

/** What `createFace` takes; every option may be left out. */
export interface FaceOptions {
  /** The head's mesh resolution (see `Resolution`): `medium` by default. */
  resolution?: Resolution;
  /** The muscle rig: the URL of a rig document (JSON), or a rig object, checked as a document would be. */
  rig?: string | URL | Rig | null;
  /** The URL of a softface head model (GLB) to show instead of the package's head of `resolution`. */
  model?: string | URL | null;
  /**
   * A person to show instead of the default head (see `setIdentity`): a stock name (`listIdentities`) or
   * `{ sex, age, ancestry }`; null for the default head. A `model` given as well takes precedence.
   */
  identity?: Identity | string | null;
  /** Where the skin solver runs (see `SolverChoice`): `auto` by default. */
  solver?: SolverChoice;
  /**
   * Threads that solve in `shared` mode: 2 adds a partner worker that takes half of most passes (the same shape,
   * less time per frame where a core is free for it); `auto` takes 2 on machines with at least 4
   * cores. Other modes solve on one thread.
   */
  workers?: 1 | 2 | 'auto';
  /** Whether the face has its own lil-gui panels, over its top right corner. */
  panels?: boolean;
  /** The expression to start with: `"AU12=0.8&AU6L=0.5&preset:happiness=0.3"` or `{ AU12: 0.8, ... }`. */
  expression?: string | ExpressionEntries;
  /** The expression to start with as a FACS code (`"1+2+5B+26"`, see `setFACS`); `expression`'s entries go over it. */
  facs?: string;
  /** Random blinks and gaze saccades (off by default, so that pictures are repeatable). */
  eyeSimulation?: boolean;
  /** Some light options (see `setLight`). */
  light?: Partial<LightOptions>;
  /** Some appearance options: the brows' and lashes' switches and colours, the brows' density (see `setAppearance`). */
  appearance?: Partial<AppearanceOptions>;
  /** A colour `"#rrggbb"`, or `"transparent"` to show the page behind the face. */
  background?: string;
  /**
   * Share of the pixel ratio a moving face is drawn at where a full draw is slow (over 50 ms: software WebGL, or a GPU
   * that cannot keep up), 0.25..1: 0.5 draws a quarter of the pixels, 1 always draws at full resolution. A face that
   * stands still, `savePNG` and videos are drawn at full resolution either way.
   */
  motionResolution?: number;
  /**
   * How long (ms) a full-resolution draw may hold the next animation frame back before draws count as slow and a
   * moving face is drawn at `motionResolution`: 50 by default (below 20 frames a second); 0 counts every draw as
   * slow, a large number none.
   */
  slowDrawMs?: number;
  /**
   * How the face is antialiased: `"always"` multisamples every draw; `"still"` draws a moving face without it and a
   * face at rest, `savePNG` pictures and video frames with it (the same pictures as `"always"`); `"auto"` is `"still"`
   * where WebGL runs in software (SwiftShader: draws of the medium head 2.2 times as fast) and `"always"` elsewhere.
   */
  antialias?: Antialias;
  /**
   * Where models (`models/head-<resolution>.glb`) and rigs (`rigs/default.json`) are fetched from, relative to the
   * page; by default the package's own files, found from the module's own URL.
   */
  assetBase?: string | URL | null;
  /** Called when the user picks another resolution in the panels; without it the panels offer none. */
  onResolution?: ((resolution: Resolution) => void) | null;
  /**
   * Keeps an edited rig in the browser (IndexedDB) and starts from it next time: `true` under a key made from the
   * rig's source, or a key of one's own. Off by default, so that an embedding page always shows its own rig.
   */
  autosave?: boolean | string;
}

/** What `createFace` takes for each option left out (every one listed, frozen). */
export const FACE_DEFAULTS: Readonly<Required<FaceOptions>> = Object.freeze({
  resolution: 'medium',
  rig: null,
  model: null,
  identity: null,
  solver: 'auto',
  workers: 'auto',
  panels: false,
  expression: '',
  facs: '',
  eyeSimulation: false,
  light: {},
  appearance: {},
  background: '#1d2024',
  motionResolution: 0.5,
  slowDrawMs: 50,
  antialias: 'auto',
  assetBase: null,
  onResolution: null,
  autosave: false,
});

const COLOUR = /^#[0-9a-f]{6}$/i;
/** Allowed range of `motionResolution`: below a quarter the moving face turns to blocks. */
const MOTION_RESOLUTION_RANGE = [0.25, 1] as const;

function isUrl(x: unknown): x is string | URL {
  return (typeof x === 'string' && x.trim() !== '') || x instanceof URL;
}

/**
 * Checks one option and returns it; throws an error that starts with `what` (the caller: `createFace`, or the
 * attribute of `<soft-face>` it came from) and names the option and the bad value.
 */
export function checkFaceOption<K extends keyof FaceOptions>(key: K, value: unknown, what: string): Required<FaceOptions>[K] {
  const bad = (expected: string): Error => refusal(what, key, expected, value);
  switch (key) {
    case 'resolution':
      if (!RESOLUTIONS.includes(value as Resolution)) throw bad(`one of ${RESOLUTIONS.join(', ')}`);
      break;
    case 'solver':
      if (!SOLVER_CHOICES.includes(value as SolverChoice)) throw bad(`one of ${SOLVER_CHOICES.join(', ')}`);
      break;
    case 'workers':
      if (value !== 1 && value !== 2 && value !== 'auto') throw bad('1, 2 or "auto"');
      break;
    case 'panels':
    case 'eyeSimulation':
      if (typeof value !== 'boolean') throw bad('true or false');
      break;
    case 'motionResolution':
      if (typeof value !== 'number' || !(value >= MOTION_RESOLUTION_RANGE[0] && value <= MOTION_RESOLUTION_RANGE[1])) {
        throw bad(numberIn(MOTION_RESOLUTION_RANGE));
      }
      break;
    case 'slowDrawMs':
      if (typeof value !== 'number' || !Number.isFinite(value) || value < 0) throw bad('a finite number of ms, at least 0');
      break;
    case 'antialias':
      if (!ANTIALIAS_CHOICES.includes(value as Antialias)) throw bad(`one of ${ANTIALIAS_CHOICES.join(', ')}`);
      break;
    case 'background':
      if (typeof value !== 'string' || !(COLOUR.test(value) || value === 'transparent')) throw bad('a colour "#rrggbb" or "transparent"');
      break;
    case 'rig':
      if (!(value === null || isUrl(value) || (typeof value === 'object' && !Array.isArray(value)))) throw bad('a URL or a rig object');
      break;
    case 'model':
    case 'assetBase':
      if (!(value === null || isUrl(value))) throw bad('a URL');
      break;
    case 'identity':
      readIdentity(value, `${what}: identity`);
      break;
    case 'onResolution':
      if (!(value === null || typeof value === 'function')) throw bad('a function');
      break;
    case 'autosave':
      if (!(typeof value === 'boolean' || (typeof value === 'string' && value.trim() !== ''))) throw bad('true, false or a key');
      break;
    case 'light':
      checkOptions<LightOptions>(`${what}: light`, value, LIGHT_DEFAULTS, { ranges: LIGHT_RANGES });
      break;
    case 'appearance':
      checkOptions<AppearanceOptions>(`${what}: appearance`, value, APPEARANCE_DEFAULTS, { ranges: APPEARANCE_RANGES });
      break;
    case 'expression':
      // Whether its ids and presets exist is checked against the rig, once it is loaded.
      readExpression(value as string, `${what}: expression`);
      break;
    case 'facs':
      parseFACSCode(value, `${what}: facs`);
      break;
    default:
      throw refusal(what, '', `one of the options ${Object.keys(FACE_DEFAULTS).join(', ')}`, key);
  }
  return value as Required<FaceOptions>[K];
}

/** Checks every option given and fills in the defaults; throws naming the first bad one. */
export function checkFaceOptions(options: unknown, what = 'createFace'): Required<FaceOptions> {
  if (options === undefined) return { ...FACE_DEFAULTS };
  const given = checkObject(what, options);
  const out: Record<string, unknown> = { ...FACE_DEFAULTS };
  for (const [key, value] of Object.entries(given)) {
    // Left out and undefined mean the same.
    if (value !== undefined) out[key] = checkFaceOption(key as keyof FaceOptions, value, what);
  }
  return out as unknown as Required<FaceOptions>;
}

/** `auto` is `shared` on cross-origin isolated pages and `transfer` elsewhere; `shared` needs isolation. */
export function solverMode(choice: SolverChoice): SolverMode {
  if (choice === 'auto') return crossOriginIsolated ? 'shared' : 'transfer';
  if (choice === 'shared' && !crossOriginIsolated) {
    console.warn("createFace: solver 'shared' needs a cross-origin isolated page (SharedArrayBuffer); using 'transfer'");
    return 'transfer';
  }
  return choice;
}

/** The view's form of a checked `background`: a colour number or `transparent`. */
export function viewBackground(background: string): ViewBackground {
  return background === 'transparent' ? 'transparent' : Number.parseInt(background.slice(1), 16);
}
