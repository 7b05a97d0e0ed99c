import { describe, expect, it } from 'vitest';
import { openFaceTimeline, OpenFaceError } from '../src/core/timeline/openface';
import { parseTimeline } from '../src/core/timeline/timeline-schema';

const range = (prefix: string, n: number) => Array.from({ length: n }, (_, i) => `${prefix}${i}`);
const INTENSITY = ['01', '02', '04', '05', '06', '07', '09', '10', '12', '14', '15', '17', '20', '23', '25', '26', '45'];
const PRESENCE = ['01', '02', '04', '05', '06', '07', '09', '10', '12', '14', '15', '17', '20', '23', '25', '26', '28', '45'];
/** The header OpenFace 2.2's FeatureExtraction writes (714 columns, ", " between them). */
const HEADER = [
  'frame',
  'face_id',
  'timestamp',
  'confidence',
  'success',
  ...['gaze_0_x', 'gaze_0_y', 'gaze_0_z', 'gaze_1_x', 'gaze_1_y', 'gaze_1_z', 'gaze_angle_x', 'gaze_angle_y'],
  ...['x', 'y', 'X', 'Y', 'Z'].flatMap((c) => range(`eye_lmk_${c}_`, 56)),
  ...['pose_Tx', 'pose_Ty', 'pose_Tz', 'pose_Rx', 'pose_Ry', 'pose_Rz'],
  ...['x', 'y', 'X', 'Y', 'Z'].flatMap((c) => range(`${c}_`, 68)),
  ...['p_scale', 'p_rx', 'p_ry', 'p_rz', 'p_tx', 'p_ty'],
  ...range('p_', 34),
  ...INTENSITY.map((u) => `AU${u}_r`),
  ...PRESENCE.map((u) => `AU${u}_c`),
];

/** Each header cell's kind, read once: a test file of 20,000 rows would otherwise match 14 million names. */
const KINDS = HEADER.map((name) => {
  const r = /^AU(\d\d)_r$/.exec(name);
  if (r) return { kind: 'intensity', unit: r[1], name };
  const c = /^AU(\d\d)_c$/.exec(name);
  return c ? { kind: 'presence', unit: c[1], name } : { kind: 'other', unit: '', name };
});

/** A row: frame number, timestamp, success, and the given AU intensities (0..5) and presences; 0.5 in every other cell. */
function row(frame: number, time: number, au: Record<string, number>, success = 1, present: Record<string, number> = {}): string {
  return KINDS.map((k) => {
    if (k.kind === 'intensity') return (au[k.unit] ?? 0).toFixed(2);
    if (k.kind === 'presence') return (present[k.unit] ?? ((au[k.unit] ?? 0) > 0 ? 1 : 0)).toFixed(2);
    if (k.name === 'frame') return String(frame);
    if (k.name === 'face_id') return '0';
    if (k.name === 'timestamp') return time.toFixed(3);
    if (k.name === 'confidence') return '0.98';
    if (k.name === 'success') return String(success);
    return '0.5';
  }).join(', ');
}

describe('OpenFace CSV files as timelines', () => {
  it('reads a real header’s units that the face has, intensity over 5, timed from the first tracked frame', () => {
    expect(HEADER).toHaveLength(714);
    const csv = [
      HEADER.join(', '),
      row(1, 0.5, { '12': 0 }),
      row(2, 0.533, { '12': 2.5, '01': 1 }),
      row(3, 0.567, { '12': 5, '01': 1 }),
      row(4, 0.6, { '12': 4 }, 0),
      row(5, 0.633, { '12': 5, '45': 2 }),
      '',
    ].join('\n');
    const t = openFaceTimeline(csv);
    // Every unit OpenFace writes an intensity for, but AU28 (presence only): 17 tracks.
    expect(Object.keys(t.tracks).sort()).toEqual(INTENSITY.map((u) => `AU${Number(u)}`).sort());
    expect(t.tracks.AU12.keys).toEqual([
      { time: 0, value: 0 },
      { time: 0.033, value: 0.5 },
      { time: 0.067, value: 1 },
      { time: 0.133, value: 1 },
    ]);
    // A unit absent by its presence column is 0; the untracked frame (success 0) is left out.
    expect(t.tracks.AU1.keys.map((k) => k.value)).toEqual([0, 0.2, 0.2, 0]);
    expect(t.tracks.AU45.keys.at(-1)).toEqual({ time: 0.133, value: 0.4 });
    expect(t.duration).toBeCloseTo(0.133, 6);
    // A timeline the schema takes.
    expect(() => parseTimeline(t, 'openface')).not.toThrow();
  });

  it('drops keys a straight line gives, so a long steady recording fits a track', () => {
    const rows = [HEADER.join(',')];
    // Each row from one made by `row`, with its frame, time and AU12 set (20,000 rows made cell by cell took 5 s).
    const cells = row(1, 0, { '12': 1 }).split(', ');
    const [frame, time, intensity, presence] = ['frame', 'timestamp', 'AU12_r', 'AU12_c'].map((h) => HEADER.indexOf(h));
    for (let f = 0; f < 20_000; f++) {
      const au12 = 5 * Math.min(1, f / 15_000);
      cells[frame] = String(f + 1);
      cells[time] = (f / 30).toFixed(3);
      cells[intensity] = au12.toFixed(2);
      cells[presence] = au12 > 0 ? '1.00' : '0.00';
      rows.push(cells.join(','));
    }
    const t = openFaceTimeline(rows.join('\n'));
    expect(t.tracks.AU12.keys.length).toBeLessThan(10);
    expect(t.tracks.AU12.keys.at(-1)!.value).toBe(1);
    expect(t.tracks.AU4.keys).toHaveLength(2);
  });

  it('refuses a malformed file naming the line and column, 1-based', () => {
    const good = [HEADER.join(', '), row(1, 0, { '12': 1 }), row(2, 0.1, { '12': 1 })];
    const refused = (lines: string[]) => {
      try {
        openFaceTimeline(lines.join('\n'), 'clip.csv');
      } catch (e) {
        expect(e).toBeInstanceOf(OpenFaceError);
        return (e as Error).message;
      }
      return 'read';
    };
    expect(refused(good)).toBe('read');
    const cell = HEADER.indexOf('AU04_r');
    const bad = row(2, 0.1, {}).split(', ');
    bad[cell] = 'x';
    expect(refused([good[0], good[1], bad.join(', ')])).toBe(`clip.csv: line 3, column ${cell + 1}: AU04_r: expected a number, got "x"`);
    expect(refused([good[0], good[1], 'frame, 2'])).toBe('clip.csv: line 3: expected 714 cells as in the header, got 2');
    expect(refused([good[0], good[2], good[1]])).toMatch(/^clip\.csv: line 3, column 3: timestamp: expected a time after 0\.1 s, got 0$/);
    expect(refused(['a,b,c', '1,2,3'])).toBe('clip.csv: line 1: expected an OpenFace header with a "timestamp" column');
    expect(refused(['frame,timestamp,AU99_r', '1,0,1'])).toMatch(/^clip\.csv: line 1: expected intensity columns like "AU12_r"/);
    expect(refused([good[0], row(1, 0, {}, 0)])).toMatch(/^clip\.csv: line 2: expected at least one tracked frame/);
    expect(() => openFaceTimeline(42)).toThrow(/^importOpenFace: expected the text of an OpenFace CSV file, got number$/);
  });
});
