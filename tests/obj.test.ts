import { describe, expect, it } from 'vitest';
import { parseObj } from '../src/core/head/build/obj';

describe('OBJ parser', () => {
  it('reads positions, uvs, faces and groups, with 1-based and negative indices', () => {
    const obj = parseObj(
      ['v 0 0 0', 'v 1 0 0', 'v 1 1 0', 'vt 0 0', 'vt 1 0', 'vt 1 1', 'g tri', 'f 1/1 2/2 3/3', 'f -3/-3 -2/-2 -1/-1'].join('\n'),
    );
    expect(Array.from(obj.positions)).toEqual([0, 0, 0, 1, 0, 0, 1, 1, 0]);
    expect(obj.uvs).toHaveLength(6);
    expect(obj.faces).toEqual([
      { group: 'tri', v: [0, 1, 2], vt: [0, 1, 2] },
      { group: 'tri', v: [0, 1, 2], vt: [0, 1, 2] },
    ]);
  });

  it('names the line of an index out of range', () => {
    expect(() => parseObj('v 0 0 0\nv 1 0 0\nf 1 2 3', 'head.obj')).toThrow(
      'head.obj line 3: vertex index 3 is out of range (2 defined so far)',
    );
  });

  it('names the line of a vertex that is not three numbers', () => {
    expect(() => parseObj('v 0 0 0\nv 1 zero 0\n')).toThrow(/line 2: a vertex needs three finite numbers/);
  });

  it('says that a file which is not a mesh is not one', () => {
    expect(() => parseObj('{"muscles": []}', 'rig.json')).toThrow('rig.json: no vertices or no faces: this is not an OBJ mesh');
  });
});
