import { del, get, set } from 'idb-keyval';
import type { RigDocument } from '../core/rig/rig-document';
import { parseRig } from '../core/rig/rig-schema';
import type { Rig } from '../core/rig/rig-types';

/** How long after an edit the rig is written (a drag's many edits make one write). */
const AUTOSAVE_DELAY_MS = 250;

/** Where the autosave stands: nothing to keep (the rig is the original), a write due, written, or failed. */
export type AutosaveStatus = 'clean' | 'pending' | 'saved' | 'failed';

/** What is stored: the rig as a document, and when. */
interface StoredRig {
  savedAt: string;
  rig: Rig;
}

/**
 * Keeps an edited rig in IndexedDB (idb-keyval) under one key, written within `AUTOSAVE_DELAY_MS` of each edit, so
 * that a reopened page starts from it; a rig edited back to the original is deleted instead.
 */
export class RigAutosave {
  private timer: ReturnType<typeof setTimeout> | undefined;
  private statusNow: AutosaveStatus = 'clean';
  private unsubscribe: (() => void) | undefined;
  private document: RigDocument | undefined;
  /** Told whenever the status changes. */
  onStatus: ((status: AutosaveStatus) => void) | undefined;

  constructor(
    private readonly key: string,
    private readonly original: Rig,
  ) {}

  /** The stored rig, checked as a document; undefined if there is none, or it no longer passes the schema (warned). */
  async load(): Promise<Rig | undefined> {
    let stored: StoredRig | undefined;
    try {
      stored = await get<StoredRig>(this.key);
    } catch (error) {
      console.warn(`the autosaved rig could not be read: ${(error as Error).message}`);
      return undefined;
    }
    if (!stored) return undefined;
    try {
      const rig = parseRig(stored.rig, 'autosaved rig');
      this.setStatus(same(rig, this.original) ? 'clean' : 'saved');
      return rig;
    } catch (error) {
      console.warn(`the autosaved rig was not used: ${(error as Error).message}`);
      return undefined;
    }
  }

  /** Forgets the stored rig (a new head was loaded: a rig edited for the one before is not for it). */
  async clear(): Promise<void> {
    try {
      await del(this.key);
    } catch (error) {
      console.warn(`the autosaved rig could not be removed: ${(error as Error).message}`);
    }
    this.setStatus('clean');
  }

  /** Writes the document's rig after each of its changes. */
  watch(document: RigDocument): void {
    this.document = document;
    this.unsubscribe = document.onChange(() => this.schedule());
  }

  get status(): AutosaveStatus {
    return this.statusNow;
  }

  /** Writes a due save now (the page is being left or the face disposed). */
  flush(): void {
    if (this.timer === undefined) return;
    clearTimeout(this.timer);
    this.timer = undefined;
    void this.write();
  }

  dispose(): void {
    this.flush();
    this.unsubscribe?.();
    this.onStatus = undefined;
  }

  private schedule(): void {
    if (this.timer !== undefined) clearTimeout(this.timer);
    this.setStatus('pending');
    this.timer = setTimeout(() => {
      this.timer = undefined;
      void this.write();
    }, AUTOSAVE_DELAY_MS);
  }

  private async write(): Promise<void> {
    const rig = this.document?.rig;
    if (!rig) return;
    try {
      if (same(rig, this.original)) {
        await del(this.key);
        this.setStatus('clean');
      } else {
        await set(this.key, { savedAt: new Date().toISOString(), rig: structuredClone(rig) } satisfies StoredRig);
        // A newer edit may have come meanwhile; its own write reports.
        if (this.timer === undefined) this.setStatus('saved');
      }
    } catch (error) {
      console.warn(`the rig could not be autosaved: ${(error as Error).message}`);
      this.setStatus('failed');
    }
  }

  private setStatus(status: AutosaveStatus): void {
    if (status === this.statusNow) return;
    this.statusNow = status;
    this.onStatus?.(status);
  }
}

function same(a: Rig, b: Rig): boolean {
  return JSON.stringify(a) === JSON.stringify(b);
}
