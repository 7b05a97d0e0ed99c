import { execFile } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { promisify } from 'node:util';
import { ISOLATED_PORT } from '../playwright.config';
import { comparePictures, expect, test } from './fixtures';

const run = promisify(execFile);

/** Runs `npm run stimuli`'s renderer on the built app these tests serve; returns what it printed. */
async function stimuli(list: string, out: string): Promise<string> {
  const { stdout } = await run('npx', ['tsx', 'scripts/stimuli/run.ts', list, out], {
    env: { ...process.env, STIMULI_BASE_URL: `http://127.0.0.1:${ISOLATED_PORT}` },
    maxBuffer: 16 * 1024 * 1024,
  });
  return stdout;
}

/** Writes a stimulus list of these entries, each of the low head at 200 x 150 unless it says otherwise. */
function writeList(path: string, stimuli: object[]): void {
  writeFileSync(
    path,
    JSON.stringify({ format: 'softface-stimuli', version: 1, defaults: { resolution: 'low', width: 200, height: 150 }, stimuli }),
  );
}

/** Width and height from a PNG's header. */
function pngSize(file: string): [number, number] {
  const b = readFileSync(file);
  return [b.readUInt32BE(16), b.readUInt32BE(20)];
}

test('a 6-stimulus batch writes its pictures, an EMFACS face, its clip and its manifest, and a second run skips what is there', async ({
  page,
}) => {
  test.setTimeout(240_000);
  const dir = mkdtempSync(join(tmpdir(), 'softface-stimuli-'));
  const list = join(dir, 'list.json');
  const out = join(dir, 'out');
  writeList(list, [
    { name: 'smile', expression: { AU12: 1 }, intensity: [0.3, 1], camera: [{}, { yaw: 40, distance: 0.7 }] },
    {
      name: 'brows',
      timeline: {
        format: 'softface-timeline',
        version: 1,
        tracks: {},
        actions: [{ target: 'AU1', start: 0, intensity: 1, onset: 0.3, apex: 0.2, offset: 0.3 }],
      },
      fps: 5,
    },
    { name: 'emfacs', emotion: 'surprise-prototype-1' },
  ]);
  const first = await stimuli(list, out);
  const files = ['smile_i0.3_l0_c0_low.png', 'smile_i0.3_l0_c1_low.png', 'smile_i1_l0_c0_low.png', 'smile_i1_l0_c1_low.png'];
  for (const f of files) expect(first).toContain(`wrote ${f}`);
  for (const f of files) expect(pngSize(join(out, f))).toEqual([200, 150]);
  // The timeline became a WebM (its frames are decoded and checked in video-record.spec.ts).
  expect(first).toContain('wrote brows_i1_l0_c0_low.webm');
  const webm = readFileSync(join(out, 'brows_i1_l0_c0_low.webm'));
  expect([...webm.subarray(0, 4)]).toEqual([0x1a, 0x45, 0xdf, 0xa3]);
  expect(webm.length).toBeGreaterThan(1000);
  const manifest = readFileSync(join(out, 'manifest.csv'), 'utf8').trim().split('\n');
  expect(manifest[0]).toBe('file,name,format,expression,emotion,timeline,intensity,light,camera,resolution,identity,width,height,fps');
  expect(manifest.slice(1).map((row) => row.split(',')[0])).toEqual([
    ...files,
    'brows_i1_l0_c0_low.webm',
    'emfacs_surprise-prototype-1_i1_l0_c0_low.png',
  ]);
  // The EMFACS face: its code's units set, named in the manifest.
  expect(first).toContain('wrote emfacs_surprise-prototype-1_i1_l0_c0_low.png');
  expect(manifest[6]).toContain('surprise-prototype-1 (1+2+5B+26)');
  const surprise = (
    await comparePictures(page, readFileSync(join(out, files[0])), readFileSync(join(out, 'emfacs_surprise-prototype-1_i1_l0_c0_low.png')))
  ).mean;
  expect(surprise).toBeGreaterThan(0.2);
  expect(manifest[4]).toContain('"{""yaw"":40,""distance"":0.7}"');

  // The pictures are of what the list asked: the stronger smile and the other camera each change the picture.
  const picture = (f: string): Buffer => readFileSync(join(out, f));
  const differs = {
    intensity: (await comparePictures(page, picture(files[0]), picture(files[2]))).mean,
    camera: (await comparePictures(page, picture(files[0]), picture(files[1]))).mean,
  };
  console.log(`mean pixel difference: intensity 0.3 vs 1 ${differs.intensity.toFixed(2)}, front vs turned ${differs.camera.toFixed(2)}`);
  expect(differs.intensity).toBeGreaterThan(0.2);
  expect(differs.camera).toBeGreaterThan(2);

  // The stimuli after the first were rendered on the page it opened: each is the picture it gives alone, on a new page.
  const alone = join(dir, 'alone');
  const aloneList = join(dir, 'alone.json');
  writeList(aloneList, [{ name: 'smile', expression: { AU12: 1 }, camera: [{ yaw: 40, distance: 0.7 }] }]);
  expect(await stimuli(aloneList, alone)).toContain('wrote smile_i1_l0_c0_low.png');
  expect(readFileSync(join(alone, 'smile_i1_l0_c0_low.png')).equals(picture(files[3]))).toBe(true);

  // Run again: every file is there, so nothing is rendered and nothing is touched.
  const all = [...files, 'brows_i1_l0_c0_low.webm', 'emfacs_surprise-prototype-1_i1_l0_c0_low.png'];
  const times = all.map((f) => statSync(join(out, f)).mtimeMs);
  const second = await stimuli(list, out);
  expect(second).not.toContain('wrote ');
  expect(second).toMatch(/6 skipped/);
  expect(all.map((f) => statSync(join(out, f)).mtimeMs)).toEqual(times);
  rmSync(dir, { recursive: true, force: true });
});
