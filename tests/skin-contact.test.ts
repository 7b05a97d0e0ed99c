import { describe, expect, it } from 'vitest';
import { SkinContact } from '../src/core/hair/skin-contact';

/** A flat patch of skin at z = 0 facing +z: a 21 x 21 grid of vertices 0.5 mm apart. */
function patch() {
  const positions: number[] = [];
  const normals: number[] = [];
  for (let j = 0; j <= 20; j++) {
    for (let i = 0; i <= 20; i++) {
      positions.push((i - 10) * 0.0005, (j - 10) * 0.0005, 0);
      normals.push(0, 0, 1);
    }
  }
  return {
    positions: Float32Array.from(positions),
    normals: Float32Array.from(normals),
    vertices: Uint32Array.from({ length: 441 }, (_, i) => i),
  };
}

describe('skin contact', () => {
  const skin = patch();
  const contact = new SkinContact(skin.vertices, 0.0015, 0.00005);
  contact.bin(skin.positions);

  it('pushes a ribbon pair whose middle is behind the skin out to just in front of it, along the normal', () => {
    const points = Float32Array.from([0.0011, -0.0007, -0.0005, 0.0013, -0.0007, -0.0003]);
    expect(contact.resolve(points, 0, 1, skin.positions, skin.normals)).toBe(1);
    expect(points[0]).toBeCloseTo(0.0011, 9);
    expect(points[1]).toBeCloseTo(-0.0007, 9);
    // The pair keeps its shape: both move by the middle's push, from -0.4 mm to 0.05 mm.
    expect(points[2]).toBeCloseTo(-0.00005, 9);
    expect(points[5]).toBeCloseTo(0.00015, 9);
  });

  it('leaves pairs in front of the skin, and pairs out of its reach, where they are', () => {
    const points = Float32Array.from([
      0, 0, 0.0003, 0.0001, 0, 0.0003, 0.02, 0, -0.001, 0.0201, 0, -0.001, 0, 0, -0.002, 0.0001, 0, -0.002,
    ]);
    const before = points.slice();
    expect(contact.resolve(points, 0, 3, skin.positions, skin.normals)).toBe(0);
    expect(Array.from(points)).toEqual(Array.from(before));
  });

  it('follows the skin to where it is binned next', () => {
    const moved = skin.positions.map((v, i) => (i % 3 === 2 ? v + 0.003 : v));
    contact.bin(moved);
    const points = Float32Array.from([0, 0, 0.0025, 0.0001, 0, 0.0025]);
    expect(contact.resolve(points, 0, 1, moved, skin.normals)).toBe(1);
    expect(points[2]).toBeCloseTo(0.00305, 9);
    expect(points[5]).toBeCloseTo(0.00305, 9);
  });
});
