import { describe, expect, it } from 'vitest';
import { mulberry32 } from '../src/core/random';
import { VertexKeyCounts } from '../src/core/solver/vertex-key-counts';

describe('VertexKeyCounts', () => {
  it('counts edges and triangles as a Map of their keys does, full to its capacity', () => {
    const random = mulberry32(11);
    const capacity = 5000;
    const table = new VertexKeyCounts(capacity);
    const reference = new Map<string, number>();
    // Few distinct vertices, so that keys repeat; pairs and triples share their first two indices.
    const keys: number[][] = [];
    while (reference.size < capacity) {
      const key = random() < 0.5 ? [Math.floor(random() * 90), Math.floor(random() * 90)] : [0, 1, 2].map(() => Math.floor(random() * 40));
      const name = key.join(',');
      reference.set(name, (reference.get(name) ?? 0) + 1);
      keys.push(key);
      table.add(key[0], key[1], key[2]);
    }
    for (const key of keys) expect(table.get(key[0], key[1], key[2])).toBe(reference.get(key.join(',')));
    // A pair is not the triple that starts with it, and a key never added counts 0.
    expect(table.get(100, 200)).toBe(0);
    expect(table.get(100, 200, 300)).toBe(0);
    table.add(100, 200);
    expect(table.get(100, 200)).toBe(1);
    expect(table.get(100, 200, 0)).toBe(0);
  });
});
