import { openFace } from './face';
import { expect, test } from './shared-app';
import { control, openFolder } from './panels';

/** A short OpenFace 2 file: its real column names for the units, a few of the others, ", " between cells. */
function openFaceCsv(rows: { time: number; au12: number; au01: number; success?: number }[]): string {
  const header = [
    'frame',
    'face_id',
    'timestamp',
    'confidence',
    'success',
    'pose_Rx',
    'AU01_r',
    'AU12_r',
    'AU45_r',
    'AU01_c',
    'AU12_c',
    'AU28_c',
    'AU45_c',
  ];
  const lines = rows.map((r, i) =>
    [i + 1, 0, r.time.toFixed(3), 0.97, r.success ?? 1, 0.1, r.au01, r.au12, 0, r.au01 > 0 ? 1 : 0, r.au12 > 0 ? 1 : 0, 0, 0].join(', '),
  );
  return [header.join(', '), ...lines].join('\n');
}

test('the Timeline folder imports an OpenFace CSV as tracks the face plays, and names the line and column of a bad one', async ({
  page,
}) => {
  await openFace(page, '/?resolution=low');
  await openFolder(page, 'Timeline');
  const csv = openFaceCsv([
    { time: 1, au12: 0, au01: 0 },
    { time: 1.5, au12: 5, au01: 2 },
    { time: 2, au12: 5, au01: 2, success: 0 },
    { time: 2.5, au12: 1, au01: 0 },
  ]);
  await control(page, 'timeline-file').setInputFiles({ name: 'clip.csv', mimeType: 'text/csv', buffer: Buffer.from(csv) });
  await expect(control(page, 'timeline-message')).toHaveText('imported clip.csv');
  const loaded = await page.evaluate(async () => {
    const face = window.face;
    const t = face.getTimeline()!;
    face.seek(0.5);
    await face.settle(30_000);
    return { tracks: Object.keys(t.tracks).sort(), au12: t.tracks.AU12.keys, duration: t.duration, at: face.getEffectiveActionUnits() };
  });
  // Timed from the first tracked frame; the untracked one left out; intensity over 5.
  expect(loaded.tracks).toEqual(['AU1', 'AU12', 'AU45']);
  expect(loaded.au12).toEqual([
    { time: 0, value: 0 },
    { time: 0.5, value: 1 },
    { time: 1.5, value: 0.2 },
  ]);
  expect(loaded.duration).toBe(1.5);
  expect(loaded.at.AU12L).toBeCloseTo(1, 6);
  expect(loaded.at.AU1L).toBeCloseTo(0.4, 6);

  // A bad cell: refused with its line and column, the timeline as it was.
  const bad = csv.replace('0.97, 1, 0.1, 2, 5', '0.97, 1, 0.1, two, 5');
  await control(page, 'timeline-file').setInputFiles({ name: 'bad.csv', mimeType: 'text/csv', buffer: Buffer.from(bad) });
  await expect(control(page, 'timeline-message')).toHaveText('bad.csv: line 3, column 7: AU01_r: expected a number, got "two"');
  expect(await page.evaluate(() => Object.keys(window.face.getTimeline()!.tracks).length)).toBe(3);
});
