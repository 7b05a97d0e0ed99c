import type { Page } from '@playwright/test';
import { expect, waitForHead } from './fixtures';

/**
 * Pages that can show a test the face as a new page at a URL would, without loading it (see shared-app.ts): each
 * opens the URL its own way and resolves once the face is ready.
 */
export const reopeners = new WeakMap<Page, (url: string) => Promise<void>>();

/** Opens the page and waits until the head is shown and `window.face` is ready. */
export async function openFace(page: Page, url: string): Promise<void> {
  const reopen = reopeners.get(page);
  if (reopen) await reopen(url);
  else await loadFace(page, url);
}

/** Loads the page at `url` and waits until the head is shown and `window.face` is ready. */
export async function loadFace(page: Page, url: string): Promise<void> {
  await page.goto(url);
  await waitForHead(page);
  await page.evaluate(() => window.face.ready);
}

/** The skin's shape after a scripted pull, as plain arrays (simulation vertex order). */
export interface PulledSkin {
  rest: number[];
  positions: number[];
  /** Diagonal of the rest bounds: what tolerances are relative to. */
  size: number;
  /** Largest distance of a vertex from rest. */
  moved: number;
  mode: string;
}

/**
 * Pulls the 50 skin vertices nearest the middle of the forehead 4 mm up, the two halves 2 mm toward each other each,
 * waits for the skin to settle and returns its shape. The sleep tolerance is set to 1e-6 of the mesh size: this pull
 * ends in a float32 jitter of about 5e-7 of the size, which a smaller tolerance would never accept as settled.
 */
export async function pullForehead(page: Page): Promise<PulledSkin> {
  return page.evaluate(async () => {
    const face = window.face;
    const { rest } = face.getSkin();
    const n = rest.length / 3;
    const min = [Infinity, Infinity, Infinity];
    const max = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < rest.length; i++) {
      min[i % 3] = Math.min(min[i % 3], rest[i]);
      max[i % 3] = Math.max(max[i % 3], rest[i]);
    }
    // The forehead: on the midline, 72% of the way up the head (the eyes are at 55%), on the front surface.
    const x = (min[0] + max[0]) / 2;
    const y = min[1] + 0.72 * (max[1] - min[1]);
    let z = -Infinity;
    for (let v = 0; v < n; v++) {
      if (Math.abs(rest[3 * v] - x) < 0.005 && Math.abs(rest[3 * v + 1] - y) < 0.005) z = Math.max(z, rest[3 * v + 2]);
    }
    const distance = (v: number): number => Math.hypot(rest[3 * v] - x, rest[3 * v + 1] - y, rest[3 * v + 2] - z);
    const patch = Array.from({ length: n }, (_, v) => v)
      .sort((a, b) => distance(a) - distance(b))
      .slice(0, 50);
    const targets: number[] = [];
    for (const v of patch) targets.push(rest[3 * v] - Math.sign(rest[3 * v] - x) * 0.002, rest[3 * v + 1] + 0.004, rest[3 * v + 2]);
    face.setSkinParameters({ sleepTolerance: 1e-6 });
    face.setMuscleTargets(patch, targets, 1);
    await face.settle(45_000);
    const { positions } = face.getSkin();
    let moved = 0;
    for (let v = 0; v < n; v++) {
      moved = Math.max(
        moved,
        Math.hypot(positions[3 * v] - rest[3 * v], positions[3 * v + 1] - rest[3 * v + 1], positions[3 * v + 2] - rest[3 * v + 2]),
      );
    }
    const size = Math.hypot(max[0] - min[0], max[1] - min[1], max[2] - min[2]);
    return { rest: Array.from(rest), positions: Array.from(positions), size, moved, mode: face.stats().mode };
  });
}

/** Largest absolute difference between two arrays of the same length. */
export function maxDifference(a: ArrayLike<number>, b: ArrayLike<number>): number {
  expect(a.length).toBe(b.length);
  let d = 0;
  for (let i = 0; i < a.length; i++) d = Math.max(d, Math.abs(a[i] - b[i]));
  return d;
}

/** A rectangle on the page, client pixels. */
export interface Box {
  x: number;
  y: number;
  width: number;
  height: number;
}

/**
 * The mouth's box on the page (client pixels), from points of the rig projected to the screen: centred across on the
 * lips' sphincter, from a little above the lips' parting line to well below it (the jaw opens downward), sized from
 * the distance between the eye sphincters' centres.
 */
export async function mouthBox(page: Page): Promise<Box> {
  return page.evaluate(() => {
    const face = window.face;
    const rig = face.getRig();
    const centre = (name: string): number[] => {
      const m = rig.muscles.find((x) => x.name === name);
      if (!m || m.type === 'linear') throw new Error(`mouthBox: the rig has no sphincter named ${name}`);
      return m.center;
    };
    const at = (name: string) => {
      const p = face.locateMuscle(name);
      if (!p) throw new Error(`mouthBox: ${name} is not on the page`);
      return p;
    };
    const mouth = at('orbicularis-oris-tightener');
    const left = at('orbicularis-oculi-orbital-l');
    const right = at('orbicularis-oculi-orbital-r');
    const perMetre =
      Math.hypot(left.x - right.x, left.y - right.y) /
      Math.abs(centre('orbicularis-oculi-orbital-l')[0] - centre('orbicularis-oculi-orbital-r')[0]);
    return { x: mouth.x - 0.028 * perMetre, y: mouth.y - 0.012 * perMetre, width: 0.056 * perMetre, height: 0.04 * perMetre };
  });
}
