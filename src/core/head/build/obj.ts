/** A Wavefront OBJ polygon mesh: positions, texture coordinates and faces tagged with their group. */
export interface ObjMesh {
  /** xyz per `v` line. */
  positions: Float64Array;
  /** uv per `vt` line. */
  uvs: Float64Array;
  faces: ObjFace[];
}

/** One `f` line: 0-based position and texture-coordinate indices, and the group (`g`) it sits in. */
export interface ObjFace {
  group: string;
  v: number[];
  vt: number[];
}

/** Parses OBJ text; throws an error naming the line when the text is not a polygon mesh. */
export function parseObj(text: string, source = 'OBJ'): ObjMesh {
  const positions: number[] = [];
  const uvs: number[] = [];
  const faces: ObjFace[] = [];
  let group = 'default';
  const lines = text.split('\n');
  for (let lineNo = 1; lineNo <= lines.length; lineNo++) {
    const line = lines[lineNo - 1].trim();
    if (line === '' || line.startsWith('#')) continue;
    const parts = line.split(/\s+/);
    const where = `${source} line ${lineNo}`;
    switch (parts[0]) {
      case 'v': {
        const xyz = parts.slice(1, 4).map(Number);
        if (xyz.length < 3 || xyz.some((x) => !Number.isFinite(x)))
          throw new Error(`${where}: a vertex needs three finite numbers, got "${line}"`);
        positions.push(...xyz);
        break;
      }
      case 'vt': {
        const uv = parts.slice(1, 3).map(Number);
        if (uv.length < 2 || uv.some((x) => !Number.isFinite(x)))
          throw new Error(`${where}: a texture coordinate needs two finite numbers, got "${line}"`);
        uvs.push(...uv);
        break;
      }
      case 'g':
        group = parts[1] ?? 'default';
        break;
      case 'f': {
        const v: number[] = [];
        const vt: number[] = [];
        for (const corner of parts.slice(1)) {
          const [vi, ti] = corner.split('/');
          const a = resolveIndex(Number(vi), positions.length / 3, where, 'vertex');
          v.push(a);
          vt.push(ti ? resolveIndex(Number(ti), uvs.length / 2, where, 'texture coordinate') : -1);
        }
        if (v.length < 3) throw new Error(`${where}: a face needs at least three corners, got "${line}"`);
        faces.push({ group, v, vt });
        break;
      }
      default:
        break; // o, s, usemtl, mtllib, vn: not needed for the head
    }
  }
  if (positions.length === 0 || faces.length === 0) throw new Error(`${source}: no vertices or no faces: this is not an OBJ mesh`);
  return { positions: Float64Array.from(positions), uvs: Float64Array.from(uvs), faces };
}

/** OBJ indices are 1-based, negative ones count back from the last element read so far. */
function resolveIndex(index: number, count: number, where: string, what: string): number {
  if (!Number.isInteger(index) || index === 0) throw new Error(`${where}: bad ${what} index ${index}`);
  const i = index > 0 ? index - 1 : count + index;
  if (i < 0 || i >= count) throw new Error(`${where}: ${what} index ${index} is out of range (${count} defined so far)`);
  return i;
}
