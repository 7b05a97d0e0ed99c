import { del, get, set } from 'idb-keyval';
import type { Landmarks } from '../core/head/landmarks';
import type { HeadFile } from '../render/head-import';
import type { LoadHeadOptions } from './head-loader';

/** A loaded head as kept in the browser: its files as they came, how they were read, and the landmarks used. */
export interface StoredHead {
  savedAt: string;
  files: HeadFile[];
  options: Required<LoadHeadOptions>;
  landmarks: Landmarks;
}

/**
 * Keeps the loaded head in IndexedDB (idb-keyval) under one key, beside the autosaved rig, so that a reopened page
 * shows it again: the file bytes are kept rather than the built mesh, and the landmarks with them, so that it is
 * read and fitted the same way and its rig comes out the same.
 */
export class HeadStore {
  constructor(private readonly key: string) {}

  /** Where the autosave keeps the loaded head's edited rig (the default head's edited rig has a key of its own). */
  get rigKey(): string {
    return `${this.key}-rig`;
  }

  /** The kept head, or undefined if there is none or it cannot be read (warned). */
  async load(): Promise<Omit<StoredHead, 'savedAt'> | undefined> {
    try {
      const stored = await get<StoredHead>(this.key);
      if (!stored || !Array.isArray(stored.files) || !stored.landmarks) return undefined;
      return stored;
    } catch (error) {
      console.warn(`the kept head could not be read: ${(error as Error).message}`);
      return undefined;
    }
  }

  async save(head: Omit<StoredHead, 'savedAt'>): Promise<void> {
    try {
      await set(this.key, { savedAt: new Date().toISOString(), ...head } satisfies StoredHead);
    } catch (error) {
      console.warn(`the loaded head could not be kept in the browser: ${(error as Error).message}`);
    }
  }

  /** Forgets the kept head and its edited rig. */
  async clear(): Promise<void> {
    try {
      await del(this.key);
      await del(this.rigKey);
    } catch (error) {
      console.warn(`the kept head could not be removed: ${(error as Error).message}`);
    }
  }
}
