import {
  APPEARANCE_DEFAULTS,
  appearanceChanges,
  decodeAppearance,
  decodeExpression,
  decodeFACS,
  decodeIdentity,
  decodeTimeline,
  encodeExpression,
  identityText,
  MAX_HASH_TIMELINE_CHARS,
  type AppearanceOptions,
  type Face,
  type FaceChange,
} from '../embed/index';

/** Options of the URL hash sync. */
export interface HashSyncOptions {
  /** Shortest time between two writes of the hash, in ms (dragging a slider changes the face every frame). */
  intervalMs?: number;
}

const HASH_SYNC_DEFAULTS: Required<HashSyncOptions> = { intervalMs: 250 };

/**
 * Keeps the current expression (Action Unit sliders and preset weights) and appearance (where it differs from the
 * defaults) in the URL hash, with the loaded timeline when its JSON is short (`MAX_HASH_TIMELINE_CHARS`), so that a copied link reopens the
 * same face: applies the hash the
 * page opened with (and any the user types later), and rewrites it with `history.replaceState` after changes, at most
 * every `intervalMs` and always after the last one. Replacing, not pushing, keeps slider moves out of the back
 * button's history.
 */
export class HashSync {
  private readonly o: Required<HashSyncOptions>;
  private readonly unsubscribe: () => void;
  private readonly onHashChange = (): void => this.applyHash(location.hash, true);
  private timer: ReturnType<typeof setTimeout> | undefined;
  private lastWrite = -Infinity;
  /** True while a hash is being applied: its entries arrive one by one, and the half-applied face is no link. */
  private applying = false;

  constructor(
    private readonly face: Face,
    options: HashSyncOptions = {},
  ) {
    this.o = { ...HASH_SYNC_DEFAULTS, ...options };
    this.unsubscribe = face.onChange((change) => this.changed(change));
    this.applyHash(location.hash, false);
    window.addEventListener('hashchange', this.onHashChange);
  }

  /**
   * Applies an expression hash (see expression-hash.ts); with `replace`, on a neutral face rather than on top of the
   * current one, and without a timeline unless the hash has one. Entries the face rejects (a timeline with its
   * path-named problem) are reported as warnings and skipped; the hash is then rewritten without them.
   */
  applyHash(hash: string, replace: boolean): void {
    if (!hash || hash === '#') {
      if (replace) {
        this.applyIdentity(null, true);
        this.face.reset();
        if (this.face.getTimeline()) this.face.clearTimeline();
      }
      return;
    }
    this.applyIdentity(decodeIdentity(hash), replace);
    const { actionUnits, presets } = decodeExpression(hash);
    const timeline = decodeTimeline(hash);
    const appearance = decodeAppearance(hash, APPEARANCE_DEFAULTS);
    const attempt = (apply: () => void): void => {
      try {
        apply();
      } catch (error) {
        console.warn(`URL hash: ${(error as Error).message}`);
      }
    };
    this.applying = true;
    try {
      if (replace) this.face.reset();
      // A FACS code replaces the whole expression; slider and preset entries go over it.
      const code = decodeFACS(hash);
      if (code !== null) attempt(() => this.face.setFACS(code));
      // A hash without appearance entries means the default look.
      const look = replace ? { ...APPEARANCE_DEFAULTS, ...appearance } : appearance;
      for (const [key, value] of Object.entries(look))
        attempt(() => this.face.setAppearance({ [key]: value } as Partial<AppearanceOptions>));
      for (const [id, value] of Object.entries(actionUnits)) attempt(() => this.face.setActionUnit(id, value));
      for (const [name, weight] of Object.entries(presets)) attempt(() => this.face.applyPreset(name, weight));
      if (timeline !== null) attempt(() => this.face.setTimeline(timeline, 'URL hash timeline'));
      else if (replace && this.face.getTimeline()) this.face.clearTimeline();
    } finally {
      this.applying = false;
    }
    this.flush();
  }

  /**
   * Shows the person a hash names, unless shown already; a hash without one, where it replaces the state, brings the
   * default head back from a person's (a loaded head stays). The head is built in the background: a refused identity
   * is a warning, and the hash is then rewritten with the face's own.
   */
  private applyIdentity(text: string | null, replace: boolean): void {
    const current = this.face.getIdentity();
    if (text === null ? !replace || current === null : current !== null && identityText(current) === text) return;
    this.face.setIdentity(text).then(
      () => this.flush(),
      (error: Error) => {
        console.warn(`URL hash: ${error.message}`);
        this.flush();
      },
    );
  }

  /** The hash (with its `#`, or empty for the neutral face) of the current expression and short timeline. */
  currentHash(): string {
    const presets: Record<string, number> = {};
    for (const p of this.face.listPresets()) presets[p.name] = p.weight;
    const timeline = this.face.getTimeline();
    const text = timeline ? JSON.stringify(timeline) : undefined;
    const look = appearanceChanges({ ...this.face.getAppearance() }, APPEARANCE_DEFAULTS);
    const identity = this.face.getIdentity();
    return encodeExpression(
      { actionUnits: this.face.getActionUnits(), presets },
      text !== undefined && text.length <= MAX_HASH_TIMELINE_CHARS ? text : undefined,
      look,
      identity ? identityText(identity) : undefined,
    );
  }

  /** Writes the hash now, dropping any write that was waiting. */
  flush(): void {
    if (this.timer !== undefined) clearTimeout(this.timer);
    this.timer = undefined;
    this.lastWrite = performance.now();
    const url = `${location.pathname}${location.search}${this.currentHash()}`;
    if (url !== `${location.pathname}${location.search}${location.hash}`) history.replaceState(history.state, '', url);
  }

  /** Stops following the face and the address bar; a write still waiting is made now. */
  dispose(): void {
    this.unsubscribe();
    window.removeEventListener('hashchange', this.onHashChange);
    if (this.timer !== undefined) this.flush();
  }

  private changed(change: FaceChange): void {
    if (!['expression', 'timeline', 'appearance', 'head'].includes(change) || this.applying || this.timer !== undefined) return;
    const wait = this.lastWrite + this.o.intervalMs - performance.now();
    if (wait <= 0) this.flush();
    else this.timer = setTimeout(() => this.flush(), wait);
  }
}
