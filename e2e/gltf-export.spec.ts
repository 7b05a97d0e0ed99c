import { readFileSync } from 'node:fs';
import type { Page } from '@playwright/test';
import { Mesh, type AnimationClip, type BufferAttribute, type Texture } from 'three';
import { GLTFLoader, type GLTF } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { expect, test } from './shared-app';
import { openFace } from './face';
import { control, openFolder } from './panels';

/** A second long: AU12 rises to 1 at 0.5 s and falls back by 1 s. */
const TIMELINE = {
  format: 'softface-timeline',
  version: 1,
  tracks: {
    AU12: {
      keys: [
        { time: 0, value: 0, easing: 'linear' },
        { time: 0.5, value: 1 },
        { time: 1, value: 0 },
      ],
    },
  },
  actions: [],
};

/**
 * Parses a GLB with three.js's GLTFLoader, here in Node. Decoding the file's images (the pore and eye textures) needs
 * a DOM, which Node has not: a loader plugin leaves every texture out (the file's JSON still lists them).
 */
async function parseGLB(bytes: Uint8Array): Promise<GLTF> {
  const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength) as ArrayBuffer;
  // A texture that resolves to null is one the loader leaves out; the plugin's type does not say so.
  const none = (): Promise<Texture> => Promise.resolve(null) as unknown as Promise<Texture>;
  const loader = new GLTFLoader().register(() => ({ name: 'no-textures', loadTexture: none }));
  return loader.parseAsync(buffer, '');
}

function meshNamed(gltf: GLTF, name: string): Mesh {
  const mesh = gltf.scene.getObjectByName(name);
  if (!(mesh instanceof Mesh)) throw new Error(`the file has no mesh named ${name}`);
  return mesh;
}

/** The skin with one morph target at weight 1 (base + displacement), xyz per render vertex. */
function morphed(mesh: Mesh, target: string): { base: Float32Array; shape: Float32Array } {
  const index = mesh.morphTargetDictionary![target];
  const base = mesh.geometry.getAttribute('position') as BufferAttribute;
  const delta = mesh.geometry.morphAttributes.position![index] as BufferAttribute;
  expect(mesh.geometry.morphTargetsRelative).toBe(true);
  const b = new Float32Array(3 * base.count);
  const shape = new Float32Array(3 * base.count);
  for (let i = 0; i < base.count; i++) {
    for (let k = 0; k < 3; k++) {
      b[3 * i + k] = base.getComponent(i, k);
      shape[3 * i + k] = base.getComponent(i, k) + delta.getComponent(i, k);
    }
  }
  return { base: b, shape };
}

/**
 * The face's own solved skin with only `expression` at 1, settled from neutral (simulation vertex order), against the
 * file's morphed render skin: render vertices are matched to simulation vertices by their rest position (the solver
 * welds equal rest positions into one). Returns the largest distance in metres.
 */
async function largestError(
  page: Page,
  expression: Record<string, number>,
  render: { base: Float32Array; shape: Float32Array },
): Promise<number> {
  const solved = await page.evaluate(async (entries) => {
    const face = window.face;
    face.reset();
    await face.settle(60_000);
    face.setExpression(entries);
    await face.settle(60_000);
    const { rest, positions } = face.getSkin();
    return { rest: Array.from(rest), positions: Array.from(positions) };
  }, expression);
  const simOf = new Map<string, number>();
  for (let v = 0; v < solved.rest.length / 3; v++)
    simOf.set(`${solved.rest[3 * v]},${solved.rest[3 * v + 1]},${solved.rest[3 * v + 2]}`, v);
  let worst = 0;
  // Checked once for all (an expect per vertex took seconds): every render vertex sits on a simulation vertex at rest.
  const apart: number[] = [];
  for (let i = 0; i < render.base.length / 3; i++) {
    const v = simOf.get(`${render.base[3 * i]},${render.base[3 * i + 1]},${render.base[3 * i + 2]}`);
    if (v === undefined) {
      apart.push(i);
      continue;
    }
    const d = Math.hypot(
      render.shape[3 * i] - solved.positions[3 * v],
      render.shape[3 * i + 1] - solved.positions[3 * v + 1],
      render.shape[3 * i + 2] - solved.positions[3 * v + 2],
    );
    worst = Math.max(worst, d);
  }
  expect(apart, 'render vertices on no simulation vertex at rest').toEqual([]);
  return worst;
}

/** The largest displacement a mesh's morph target holds, in metres. */
function largestMove(mesh: Mesh, target: string): number {
  const delta = mesh.geometry.morphAttributes.position![mesh.morphTargetDictionary![target]] as BufferAttribute;
  let worst = 0;
  for (let i = 0; i < delta.count; i++) worst = Math.max(worst, Math.hypot(delta.getX(i), delta.getY(i), delta.getZ(i)));
  return worst;
}

/** A clip's morph weight of one target at a keyframe time (the clip's tracks hold every target's weight per key). */
function weightAt(clip: AnimationClip, mesh: Mesh, target: string, time: number): number {
  const track = clip.tracks.find((t) => t.name === `${mesh.name}.morphTargetInfluences`)!;
  expect(track, `a weight track for ${mesh.name}`).toBeDefined();
  const count = mesh.morphTargetInfluences!.length;
  const key = Array.from(track.times).findIndex((t) => Math.abs(t - time) < 1e-6);
  expect(key, `a key at ${time} s`).toBeGreaterThanOrEqual(0);
  return track.values[key * count + mesh.morphTargetDictionary![target]];
}

test('exportGLTF writes the settled Action Unit and preset as named morph targets and the timeline as their weights', async ({ page }) => {
  test.setTimeout(240_000);
  await openFace(page, '/?resolution=low');
  const run = await page.evaluate(async (timeline) => {
    const face = window.face;
    face.setTimeline(timeline);
    // The user's own expression, which the export must give back.
    face.setExpression({ AU6L: 0.3, 'preset:sadness': 0.5 });
    const before = { actionUnits: face.getActionUnits(), presets: face.listPresets(), timeline: face.timelineState() };
    const progress: string[] = [];
    const blob = await face.exportGLTF({
      actionUnits: ['AU12'],
      presets: ['surprise'],
      fps: 10,
      onProgress: (p) => progress.push(`${p.done}/${p.total} ${p.target}`),
    });
    const after = { actionUnits: face.getActionUnits(), presets: face.listPresets(), timeline: face.timelineState() };
    // As base64: an array of numbers megabytes long takes Playwright seconds to pass back.
    const bytes = new Uint8Array(await blob.arrayBuffer());
    let text = '';
    for (let i = 0; i < bytes.length; i += 0x8000) text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
    return { base64: btoa(text), type: blob.type, progress, before, after };
  }, TIMELINE);
  expect(run.type).toBe('model/gltf-binary');
  expect(run.progress).toEqual(['0/2 AU12', '1/2 surprise', '2/2 null']);
  expect(run.after).toEqual(run.before);

  const gltf = await parseGLB(Uint8Array.from(Buffer.from(run.base64, 'base64')));
  const skin = meshNamed(gltf, 'skin');
  expect(skin.morphTargetDictionary).toEqual({ AU12: 0, surprise: 1 });
  expect(skin.geometry.getAttribute('uv')).toBeDefined();
  expect(gltf.scene.getObjectByName('eye-l')).toBeDefined();
  expect(gltf.scene.getObjectByName('teeth-upper')).toBeDefined();
  // The skin's material goes along with its pore normal map (an image in the file).
  const json = gltf.parser.json as { materials: { name: string; normalTexture?: unknown }[]; images?: unknown[] };
  expect(json.materials.find((m) => m.name === 'skin')?.normalTexture).toBeDefined();
  expect(json.images?.length ?? 0).toBeGreaterThan(0);

  // AU12 at weight 1 is the solved AU12 skin, within 0.1 mm at every vertex; so is the preset.
  const au12 = morphed(skin, 'AU12');
  const au12Error = await largestError(page, { AU12: 1 }, au12);
  console.log(`AU12: largest distance from the solved skin ${(au12Error * 1000).toFixed(4)} mm`);
  expect(au12Error).toBeLessThan(1e-4);
  const surpriseError = await largestError(page, { 'preset:surprise': 1 }, morphed(skin, 'surprise'));
  expect(surpriseError).toBeLessThan(1e-4);
  // A smile moves the mouth corners by millimetres: the targets are not rest copies.
  expect(largestMove(skin, 'AU12')).toBeGreaterThan(2e-3);

  // The surprise opens the jaw: the lower teeth (crowns and gums, one mesh each) carry its turn under the same name;
  // AU12 leaves them.
  const lower = gltf.scene.getObjectByName('teeth-lower');
  const parts: Mesh[] = [];
  lower?.traverse((o) => {
    if (o instanceof Mesh) parts.push(o);
  });
  expect(parts.length).toBeGreaterThan(0);
  for (const part of parts) {
    expect(part.morphTargetDictionary).toEqual({ AU12: 0, surprise: 1 });
    expect(largestMove(part, 'surprise')).toBeGreaterThan(1e-3);
    expect(largestMove(part, 'AU12')).toBeLessThan(1e-7);
  }
  const teeth = parts[0];

  // The timeline is one clip as long as it, AU12's weight following its track.
  expect(gltf.animations.map((a) => a.name)).toEqual(['timeline']);
  const clip = gltf.animations[0];
  expect(clip.duration).toBeCloseTo(1, 5);
  expect(weightAt(clip, skin, 'AU12', 0)).toBeCloseTo(0, 5);
  expect(weightAt(clip, skin, 'AU12', 0.5)).toBeCloseTo(1, 5);
  expect(weightAt(clip, skin, 'AU12', 0.8)).toBeCloseTo(0.4, 5);
  expect(weightAt(clip, skin, 'surprise', 0.5)).toBe(0);
  expect(weightAt(clip, teeth, 'AU12', 0.5)).toBeCloseTo(1, 5);

  // The brows and lashes go along, posed on the skin at rest, with the skin's targets and its clip: surprise raises
  // the brows by millimetres.
  for (const name of ['eyebrows', 'eyelashes']) {
    const hair = meshNamed(gltf, name);
    expect(hair.morphTargetDictionary).toEqual({ AU12: 0, surprise: 1 });
    expect(weightAt(clip, hair, 'AU12', 0.5)).toBeCloseTo(1, 5);
  }
  expect(largestMove(meshNamed(gltf, 'eyebrows'), 'surprise')).toBeGreaterThan(3e-3);
});

test('bad export options reject naming the option and leave the face as it was', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  const r = await page.evaluate(async () => {
    const face = window.face;
    face.setExpression({ AU12: 0.4 });
    const before = face.getActionUnits();
    let changes = 0;
    face.onChange(() => changes++);
    const attempt = async (options: unknown): Promise<string> => {
      try {
        await face.exportGLTF(options as never);
        return 'exported';
      } catch (error) {
        return (error as Error).message;
      }
    };
    const messages = [
      await attempt({ actionUnits: ['AU99'] }),
      await attempt({ presets: ['joy'] }),
      await attempt({ actionUnits: [], presets: [] }),
      await attempt({ actionUnits: ['AU12'], fps: Number.NaN }),
      await attempt({ actionUnits: ['AU12'], timeline: true }),
    ];
    return { messages, changes, same: JSON.stringify(face.getActionUnits()) === JSON.stringify(before) };
  });
  expect(r.messages[0]).toMatch(/^exportGLTF: actionUnits: expected an Action Unit id like .*, got "AU99"$/);
  expect(r.messages[1]).toMatch(/^exportGLTF: presets: expected one of the presets .*, got "joy"$/);
  expect(r.messages[2]).toMatch(/^exportGLTF: actionUnits and presets are empty/);
  expect(r.messages[3]).toMatch(/^exportGLTF: fps: expected a number above 0 and at most 120, got NaN/);
  expect(r.messages[4]).toMatch(/^exportGLTF: timeline: no timeline is loaded/);
  expect(r.changes).toBe(0);
  expect(r.same).toBe(true);
});

test('the Export folder downloads softface.glb with the morph targets typed into it', async ({ page }) => {
  test.setTimeout(180_000);
  await openFace(page, '/?resolution=low');
  // One more folder title, and the Outputs still show whole at 1024 x 768 without scrolling.
  const outputs = page.locator('.softface-panels .lil-gui', { has: page.locator(':scope > .lil-title', { hasText: /^Outputs$/ }) });
  const box = (await outputs.boundingBox())!;
  expect(box.y + box.height).toBeLessThanOrEqual(768);
  await openFolder(page, 'Export');
  const units = control(page, 'gltf-action-units').locator('input');
  await units.fill('AU12L');
  await units.press('Enter');
  const presets = control(page, 'gltf-presets').locator('input');
  await presets.fill('happiness');
  await presets.press('Enter');
  const download = page.waitForEvent('download', { timeout: 150_000 });
  await control(page, 'gltf-export').locator('button').click();
  const file = await download;
  expect(file.suggestedFilename()).toBe('softface.glb');
  const gltf = await parseGLB(readFileSync(await file.path()));
  expect(meshNamed(gltf, 'skin').morphTargetDictionary).toEqual({ AU12L: 0, happiness: 1 });
  expect(gltf.animations).toEqual([]);
  await expect(control(page, 'gltf-message')).toContainText('exported softface.glb');
});

test('an aborted export rejects with the reason and gives the face its expression back; the next export runs', async ({ page }) => {
  test.setTimeout(120_000);
  await openFace(page, '/?resolution=low');
  const r = await page.evaluate(async () => {
    const face = window.face;
    face.setExpression({ AU12L: 0.5 });
    const before = face.getActionUnits();
    const controller = new AbortController();
    let error = '';
    try {
      await face.exportGLTF({
        actionUnits: ['AU12', 'AU26'],
        signal: controller.signal,
        onProgress: (p) => p.target === 'AU12' && controller.abort(new Error('stopped')),
      });
    } catch (e) {
      error = (e as Error).message;
    }
    const restored = JSON.stringify(face.getActionUnits()) === JSON.stringify(before);
    const next = await face.exportGLTF({ actionUnits: ['AU17'], binary: false });
    const document = JSON.parse(await next.text()) as {
      nodes: { name: string; mesh?: number }[];
      meshes: { extras?: { targetNames?: string[] } }[];
    };
    // Meshes are named by the nodes that hold them.
    const targets = document.nodes
      .filter((n) => n.mesh !== undefined)
      .map((n) => [n.name, document.meshes[n.mesh!].extras?.targetNames ?? []] as const);
    return { error, restored, type: next.type, targets };
  });
  expect(r.error).toBe('stopped');
  expect(r.restored).toBe(true);
  // A glTF JSON document this time; AU17 leaves the jaw, so only the skin and the hair on it have targets.
  expect(r.type).toBe('model/gltf+json');
  const withTargets = r.targets.filter(([, names]) => names.length > 0);
  expect(withTargets.map(([name]) => name).sort()).toEqual(['eyebrows', 'eyelashes', 'skin']);
  for (const [, names] of withTargets) expect(names).toEqual(['AU17']);
});
