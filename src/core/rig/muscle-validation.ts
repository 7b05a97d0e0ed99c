/** Checking a muscle before it is packed: every field finite, in its range, and its zone a shape with a smooth falloff. */
import type { Muscle, Vec3 } from './rig-types';

/** Throws an error naming the muscle if its field would be undefined or stepped, or a value is out of its documented range. */
export function validateMuscle(m: Muscle): void {
  const name = typeof m?.name === 'string' ? m.name : '(unnamed)';
  const fail = (what: string): never => {
    throw new Error(`muscle ${name}: ${what}`);
  };
  const finite = (v: unknown, field: string): number => {
    if (typeof v !== 'number' || !Number.isFinite(v)) fail(`${field} must be a finite number, got ${String(v)}`);
    return v as number;
  };
  const within = (v: unknown, field: string, lo: number, hi: number): number => {
    const x = finite(v, field);
    if (x < lo || x > hi) fail(`${field} must be from ${lo} to ${hi}, got ${x}`);
    return x;
  };
  const vector = (v: unknown, field: string, positive = false): Vec3 => {
    if (!Array.isArray(v) || v.length !== 3) fail(`${field} must be three numbers`);
    const a = v as Vec3;
    for (let i = 0; i < 3; i++) {
      const x = finite(a[i], `${field}[${i}]`);
      if (positive && !(x > 0)) fail(`${field}[${i}] must be greater than 0, got ${x}`);
    }
    return a;
  };
  if (m?.brush !== undefined) {
    for (const kind of ['add', 'remove'] as const) {
      const list = (m.brush as unknown as Record<string, unknown> | null)?.[kind];
      if (!Array.isArray(list)) fail(`brush.${kind} must be an array of spheres`);
      (list as unknown[]).forEach((s, i) => {
        if (!Array.isArray(s) || s.length !== 4) fail(`brush.${kind}[${i}] must be [x, y, z, radius]`);
        const sphere = s as number[];
        for (let k = 0; k < 3; k++) finite(sphere[k], `brush.${kind}[${i}][${k}]`);
        if (!(finite(sphere[3], `brush.${kind}[${i}][3]`) > 0)) fail(`brush.${kind}[${i}] radius must be greater than 0, got ${sphere[3]}`);
      });
    }
  }
  switch (m?.type) {
    case 'linear': {
      const o = vector(m.origin, 'origin');
      const p = vector(m.insertion, 'insertion');
      if (o[0] === p[0] && o[1] === p[1] && o[2] === p[2]) fail('origin and insertion must differ');
      within(m.angle, 'angle', 0, 90);
      const start = finite(m.falloffStart, 'falloffStart');
      const end = finite(m.falloffEnd, 'falloffEnd');
      // The radial falloff divides by Rs and by Rf - Rs.
      if (!(start > 0 && end > start)) fail(`falloffs must satisfy 0 < falloffStart < falloffEnd, got ${start} and ${end}`);
      within(m.strength, 'strength', 0, 1);
      within(m.normalWeight, 'normalWeight', 0, 1);
      return;
    }
    case 'sphincter': {
      vector(m.center, 'center');
      vector(m.rotation, 'rotation');
      const radii = vector(m.radii, 'radii', true);
      const inner = vector(m.innerRadii, 'innerRadii', true);
      // An inner ellipsoid poking out of the outer one would make the pull stop in a step over a patch of skin. Equal
      // radii on an axis are allowed (a rig may want no fade along the depth): the step is then only at that axis's
      // two poles, the outer ellipsoid's tips, and the fade is steep only near them.
      for (let i = 0; i < 3; i++)
        if (!(inner[i] <= radii[i])) fail(`innerRadii[${i}] must not exceed radii[${i}] (${radii[i]}), got ${inner[i]}`);
      vector(m.scale, 'scale');
      if (finite(m.strength, 'strength') < 0) fail(`strength must not be negative, got ${m.strength}`);
      within(m.normalWeight, 'normalWeight', 0, 1);
      return;
    }
    case 'lid': {
      vector(m.center, 'center');
      vector(m.rotation, 'rotation');
      vector(m.radii, 'radii', true);
      within(m.maxAngle, 'maxAngle', -90, 90);
      const inner = finite(m.innerFraction, 'innerFraction');
      // innerFraction 1 would leave no room for the fade: a step at the surface.
      if (!(inner >= 0 && inner < 1)) fail(`innerFraction must be at least 0 and less than 1, got ${inner}`);
      return;
    }
    case 'jaw': {
      vector(m.center, 'center');
      vector(m.rotation, 'rotation');
      vector(m.size, 'size', true);
      if (m.joint !== undefined) vector(m.joint, 'joint');
      within(m.maxAngle, 'maxAngle', -90, 90);
      finite(m.curve, 'curve');
      // Without a fade the turn would stop abruptly at the box's faces.
      if (!(finite(m.fade, 'fade') > 0)) fail(`fade must be greater than 0, got ${m.fade}`);
      if (m.lipFade !== undefined && !(finite(m.lipFade, 'lipFade') > 0)) fail(`lipFade must be greater than 0, got ${m.lipFade}`);
      return;
    }
    default:
      fail(`unknown muscle type ${String((m as { type?: unknown })?.type)}`);
  }
}
