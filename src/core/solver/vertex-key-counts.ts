/**
 * How often each edge or triangle has been counted, keyed by its vertex indices in the order given, in typed
 * arrays with open addressing: building the high head's topology took a quarter of a second with a Map keyed by
 * numbers above 2^31 (docs/page-notes.md, "Building the skin").
 */
export class VertexKeyCounts {
  /** Each slot's key as three indices plus one (a missing third index is 0). */
  private readonly keys: Uint32Array;
  private readonly counts: Uint32Array;
  private readonly mask: number;

  /** Room for `capacity` different keys (the table is at most half full). */
  constructor(capacity: number) {
    let size = 16;
    while (size < 2 * capacity) size *= 2;
    this.keys = new Uint32Array(3 * size);
    this.counts = new Uint32Array(size);
    this.mask = size - 1;
  }

  /** The count of key (a, b) or (a, b, c). */
  get(a: number, b: number, c = -1): number {
    return this.counts[this.slot(a + 1, b + 1, c + 1)];
  }

  /** Counts key (a, b) or (a, b, c) once more. */
  add(a: number, b: number, c = -1): void {
    const s = this.slot(a + 1, b + 1, c + 1);
    if (this.counts[s] === 0) {
      this.keys[3 * s] = a + 1;
      this.keys[3 * s + 1] = b + 1;
      this.keys[3 * s + 2] = c + 1;
    }
    this.counts[s]++;
  }

  /** The slot holding the key (indices plus one), or the empty slot where it would go. */
  private slot(a: number, b: number, c: number): number {
    let h = Math.imul(a, 0x9e3779b1) ^ Math.imul(b, 0x85ebca77) ^ Math.imul(c, 0xc2b2ae3d);
    h ^= h >>> 15;
    h = Math.imul(h, 0x2c1b3c6d);
    h ^= h >>> 12;
    const K = this.keys;
    for (let s = h & this.mask; ; s = (s + 1) & this.mask) {
      if (this.counts[s] === 0 || (K[3 * s] === a && K[3 * s + 1] === b && K[3 * s + 2] === c)) return s;
    }
  }
}
