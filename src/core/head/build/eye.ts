import { mulberry32 } from '../../random';
import type { TriGeometry } from './head-spec';

/** Options of the procedural eyeball. */
export interface EyeballOptions {
  /** Eyeball radius in model units. */
  radius: number;
  /** Iris radius as a fraction of the eyeball radius. */
  irisRatio: number;
  /** Pupil radius as a fraction of the iris radius. */
  pupilRatio: number;
  /** How far the cornea's apex stands in front of the eyeball sphere, as a fraction of the radius. */
  corneaBulge: number;
  /** Segments around the optical axis. */
  segments: number;
  /** Iris colours from the pupil edge to the limbus, linear RGB. */
  irisInner: [number, number, number];
  irisOuter: [number, number, number];
  /** Seed of the iris streak pattern. */
  seed: number;
}

const EYEBALL_DEFAULTS: Required<Omit<EyeballOptions, 'radius'>> = {
  irisRatio: 0.45,
  pupilRatio: 0.34,
  corneaBulge: 0.025,
  segments: 64,
  irisInner: [0.32, 0.2, 0.07],
  irisOuter: [0.13, 0.2, 0.17],
  seed: 7,
};

/** The parts of an eyeball, in a frame centred on the eye and looking down +z. */
export interface Eyeball {
  sclera: TriGeometry;
  iris: TriGeometry;
  cornea: TriGeometry;
}

/**
 * Builds an anatomical eyeball instead of the 72-vertex proxy: a sclera sphere open at the limbus, a slightly conical
 * iris disc (with its pupil) set back behind the limbus, and a clear spherical cornea cap that closes the opening.
 */
export function buildEyeball(options: Pick<EyeballOptions, 'radius'> & Partial<EyeballOptions>): Eyeball {
  const o: Required<EyeballOptions> = { ...EYEBALL_DEFAULTS, ...options };
  const r = o.radius;
  const ri = o.irisRatio * r;
  const limbusAngle = Math.asin(o.irisRatio);
  const zi = r * Math.cos(limbusAngle);
  const S = o.segments;

  // Sclera: latitude rings from the limbus to the back pole.
  const sclera = revolve(S, steps(24), (t) => {
    const theta = limbusAngle + t * (Math.PI - limbusAngle);
    return { rho: r * Math.sin(theta), z: r * Math.cos(theta), nRho: Math.sin(theta), nZ: Math.cos(theta) };
  });

  // Iris: from the pupil centre out to the limbus, set back a little and bulging slightly at the pupil.
  const pupilT = o.pupilRatio;
  const rand = mulberry32(o.seed);
  const streak = Array.from({ length: S }, () => rand());
  // Rings: 4 across the pupil, 14 across the iris, so the pupil edge falls on a ring.
  const irisRings = [
    ...steps(4).map((t) => t * pupilT),
    ...steps(14)
      .slice(1)
      .map((t) => pupilT + t * (1 - pupilT)),
  ];
  // The iris is a flat cone whose pupil edge stands a little forward (the lens pushes it), meeting the sclera at the limbus.
  const irisZ = (t: number): number => zi + 0.03 * r * Math.min(1, (1 - t) / (1 - pupilT));
  const iris = revolve(
    S,
    irisRings,
    (t) => ({ rho: ri * t, z: irisZ(t), nRho: 0, nZ: 1 }),
    (seg, t) => {
      if (t <= pupilT + 1e-9) return [0.01, 0.01, 0.012];
      const u = (t - pupilT) / (1 - pupilT);
      const s = 0.72 + 0.5 * streak[seg % S] * (1 - u);
      const limbal = u > 0.85 ? 1 - 3.5 * (u - 0.85) : 1;
      return [0, 1, 2].map((k) => (o.irisInner[k] * (1 - u) + o.irisOuter[k] * u) * s * limbal) as [number, number, number];
    },
  );

  // Cornea: the sphere through the limbus ring and the apex.
  const za = r * (1 + o.corneaBulge);
  const zc = (za * za - ri * ri - zi * zi) / (2 * (za - zi));
  const rc = za - zc;
  const corneaEdge = Math.atan2(ri, zi - zc);
  const cornea = revolve(S, steps(12), (t) => {
    const phi = (1 - t) * corneaEdge;
    return { rho: rc * Math.sin(phi), z: zc + rc * Math.cos(phi), nRho: Math.sin(phi), nZ: Math.cos(phi) };
  });
  return { sclera, iris, cornea };
}

/**
 * A surface of revolution about +z: `profile(t)` for each t of `ts` (0..1) gives the radius, height and the normal's radial and
 * axial parts. A profile that starts or ends on the axis collapses to a single vertex there.
 */
function revolve(
  segments: number,
  ts: readonly number[],
  profile: (t: number) => { rho: number; z: number; nRho: number; nZ: number },
  color?: (segment: number, t: number) => [number, number, number],
): TriGeometry {
  const positions: number[] = [];
  const normals: number[] = [];
  const uvs: number[] = [];
  const colors: number[] = [];
  const ringStart: number[] = [];
  const onAxis: boolean[] = [];
  const rings = ts.length - 1;
  for (let j = 0; j <= rings; j++) {
    const t = ts[j];
    const p = profile(t);
    ringStart.push(positions.length / 3);
    const axis = Math.abs(p.rho) < 1e-12;
    onAxis.push(axis);
    const count = axis ? 1 : segments + 1; // the extra column closes the uv seam
    for (let i = 0; i < count; i++) {
      const a = (2 * Math.PI * i) / segments;
      const c = Math.cos(a);
      const s = Math.sin(a);
      positions.push(p.rho * c, p.rho * s, p.z);
      const nl = Math.hypot(p.nRho, p.nZ) || 1;
      normals.push((p.nRho * c) / nl, (p.nRho * s) / nl, p.nZ / nl);
      uvs.push(axis ? 0.5 : i / segments, t);
      if (color) colors.push(...color(i, t));
    }
  }
  const indices: number[] = [];
  for (let j = 0; j < rings; j++) {
    const a = ringStart[j];
    const b = ringStart[j + 1];
    for (let i = 0; i < segments; i++) {
      if (onAxis[j]) indices.push(a, b + i, b + i + 1);
      else if (onAxis[j + 1]) indices.push(a + i, b, a + i + 1);
      else indices.push(a + i, b + i, b + i + 1, a + i, b + i + 1, a + i + 1);
    }
  }
  // Orient every triangle so that its winding agrees with the normals (outward, counter-clockwise).
  for (let k = 0; k < indices.length; k += 3) {
    const [i0, i1, i2] = [indices[k], indices[k + 1], indices[k + 2]];
    const e1 = [0, 1, 2].map((d) => positions[3 * i1 + d] - positions[3 * i0 + d]);
    const e2 = [0, 1, 2].map((d) => positions[3 * i2 + d] - positions[3 * i0 + d]);
    const n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
    const dot = n[0] * normals[3 * i0] + n[1] * normals[3 * i0 + 1] + n[2] * normals[3 * i0 + 2];
    if (dot < 0) {
      indices[k + 1] = i2;
      indices[k + 2] = i1;
    }
  }
  return {
    positions: Float32Array.from(positions),
    normals: Float32Array.from(normals),
    uvs: Float32Array.from(uvs),
    colors: color ? Float32Array.from(colors) : undefined,
    indices: Uint32Array.from(indices),
  };
}

/** n + 1 evenly spaced values from 0 to 1. */
const steps = (n: number): number[] => Array.from({ length: n + 1 }, (_, i) => i / n);
