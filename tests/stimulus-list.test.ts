import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { expandStimulusList, scaleTimeline, stimulusManifest, StimulusListError } from '../scripts/stimuli/stimulus-list';
import { emotionVariants } from '../src/core/expression/emfacs';

const base = { format: 'softface-stimuli', version: 1 };

describe('stimulus lists', () => {
  it('expand each entry over intensities, lights, cameras and resolutions, with names made from the parameters', () => {
    const stimuli = expandStimulusList({
      ...base,
      defaults: { resolution: 'low', width: 320, height: 240 },
      stimuli: [
        { name: 'smile', expression: { AU12: 1, 'preset:happiness': 0.5 }, intensity: [0.5, 1], camera: [{}, { yaw: 30 }] },
        { name: 'frown', expression: { AU4: 0.8 }, resolution: ['low', 'medium'], light: { keyAzimuth: 90 } },
      ],
    });
    expect(stimuli.map((s) => s.file)).toEqual([
      'smile_i0.5_l0_c0_low.png',
      'smile_i0.5_l0_c1_low.png',
      'smile_i1_l0_c0_low.png',
      'smile_i1_l0_c1_low.png',
      'frown_i1_l0_c0_low.png',
      'frown_i1_l0_c0_medium.png',
    ]);
    // The intensity scales the expression's values; the entry's settings win over the defaults.
    expect(stimuli[0].expression).toEqual({ AU12: 0.5, 'preset:happiness': 0.25 });
    expect(stimuli[1].camera).toEqual({ yaw: 30 });
    expect(stimuli[4].light).toEqual({ keyAzimuth: 90 });
    expect(stimuli[5]).toMatchObject({ resolution: 'medium', width: 320, height: 240, format: 'png' });
  });

  it('a timeline entry becomes a WebM with its values scaled by the intensity', () => {
    const timeline = {
      format: 'softface-timeline',
      version: 1,
      tracks: {
        AU12: {
          keys: [
            { time: 0, value: 0 },
            { time: 1, value: 0.8 },
          ],
        },
      },
      actions: [{ target: 'AU1', start: 0, intensity: 1, onset: 0.2, apex: 0.3, offset: 0.2 }],
    };
    const [s] = expandStimulusList({ ...base, stimuli: [{ name: 'clip', timeline, intensity: 0.5, fps: 10 }] });
    expect(s).toMatchObject({ file: 'clip_i0.5_l0_c0_medium.webm', format: 'webm', fps: 10, expression: null });
    expect(s.timeline!.tracks.AU12.keys.map((k) => k.value)).toEqual([0, 0.4]);
    expect(s.timeline!.actions[0].intensity).toBe(0.5);
    expect(scaleTimeline(s.timeline!, 1)).toEqual(s.timeline);
  });

  it('refuses a bad list whole, naming every problem with its path', () => {
    const bad = {
      ...base,
      stimuli: [
        { name: 'a', expression: { AU99: 1, AU12: 2 }, intensity: [0.5, Number.NaN] },
        { name: 'a', expression: { AU1: 1 }, camera: { yaw: 400 }, light: [{ keyColour: '#fff' }] },
        { name: 'b', expression: { AU1: 1 }, timeline: {} },
        {
          name: 'c',
          timeline: {
            format: 'softface-timeline',
            version: 1,
            tracks: {
              AU12: {
                keys: [
                  { time: 1, value: 0 },
                  { time: 0.5, value: 1 },
                ],
              },
            },
            actions: [],
          },
        },
        { name: 'bad name!', expression: {}, size: 3 },
      ],
    };
    let error: StimulusListError | undefined;
    try {
      expandStimulusList(bad, 'list.json');
    } catch (e) {
      error = e as StimulusListError;
    }
    expect(error).toBeInstanceOf(StimulusListError);
    const lines = error!.message.split('\n');
    // The shape first (all of it), then the checks across fields once the shape is right.
    expect(lines).toEqual([
      'list.json: stimuli[0].expression.AU12: expected 0..1, got 2',
      'list.json: stimuli[0].intensity[1]: expected a number, got NaN',
      expect.stringMatching(/^list\.json: stimuli\[4\]\.name: expected a name of letters/),
      'list.json: stimuli[4].size: unknown field',
    ]);
    const fixed = structuredClone(bad);
    fixed.stimuli[0] = { name: 'a', expression: { AU99: 1, AU12: 1 }, intensity: [0.5] };
    fixed.stimuli.pop();
    expect(() => expandStimulusList(fixed, 'list.json')).toThrow(
      [
        'list.json: stimuli[0].expression.AU99: expected an Action Unit or a preset, got "AU99"',
        'list.json: stimuli[1].light[0]: expected one of the options ' +
          'ambientIntensity, keyAzimuth, keyElevation, keyIntensity, keyColor, got "keyColour"',
        'list.json: stimuli[1].camera[0]: yaw: expected a number from -180 to 180, got 400',
        'list.json: stimuli[1].name: a second stimulus named "a"',
        'list.json: stimuli[2]: expected one of an expression or an emotion (PNGs) or a timeline (a WebM)',
      ].join('\n'),
    );
  });

  it('crosses each entry with a list of people, by stock name, text or object, named by their place in the list', () => {
    const stimuli = expandStimulusList({
      ...base,
      defaults: { identity: ['old-african-woman', { sex: 1, age: 30, ancestry: { asian: 1 } }, null] },
      stimuli: [
        { name: 'smile', expression: { AU12: 1 } },
        { name: 'frown', expression: { AU4: 1 }, identity: 'sex:0,age:40,european:1' },
      ],
    });
    expect(stimuli.map((s) => [s.file, s.identity])).toEqual([
      ['smile_i1_l0_c0_medium_p0.png', 'old-african-woman'],
      ['smile_i1_l0_c0_medium_p1.png', 'sex:1,age:30,asian:1'],
      ['smile_i1_l0_c0_medium_p2.png', null],
      ['frown_i1_l0_c0_medium_p0.png', 'sex:0,age:40,european:1'],
    ]);
    expect(stimulusManifest(stimuli).split('\n')[1]).toContain(',medium,old-african-woman,512,');
    expect(() =>
      expandStimulusList(
        { ...base, stimuli: [{ name: 'x', expression: { AU1: 1 }, identity: ['old-african-woman', 'sex:2'] }] },
        'list.json',
      ),
    ).toThrow('list.json: stimuli[0].identity[1]: sex: expected a number from 0 to 1, got 2');
  });

  it('an emotion entry renders every face of the EMFACS table it names, each named after its face', () => {
    const stimuli = expandStimulusList({ ...base, stimuli: [{ name: 'fear', emotion: 'fear', intensity: [0.5, 1] }] });
    const faces = stimuli.filter((s) => s.intensity === 1);
    expect(faces.map((s) => s.emotion!.name)).toEqual(emotionVariants('fear').map((v) => v.name));
    expect(faces.length).toBeGreaterThan(10);
    expect(stimuli[0]).toMatchObject({
      file: 'fear_fear-prototype-1_i0.5_l0_c0_medium.png',
      emotion: { name: 'fear-prototype-1', code: '1+2+4+5+20+25' },
      expression: { AU1: 0.5, AU2: 0.5, AU4: 0.5, AU5: 0.5, AU20: 0.5, AU25: 0.5 },
    });
    expect(stimulusManifest(stimuli).split('\n')[1]).toContain(',fear-prototype-1 (1+2+4+5+20+25),no,0.5,');
    // A list of selectors: a kind and one face, each face once.
    const picked = expandStimulusList({
      ...base,
      stimuli: [{ name: 's', emotion: ['surprise:prototype', 'surprise-prototype-1', 'happiness-prototype-2'] }],
    });
    expect(picked.map((s) => s.emotion!.code)).toEqual(['1+2+5B+26', '1+2+5B+27', '12C']);
    expect(() => expandStimulusList({ ...base, stimuli: [{ name: 's', emotion: ['fear', 'joy'] }] }, 'list.json')).toThrow(
      /^list\.json: stimuli\[0\]\.emotion\[1\]: expected an emotion \(surprise, fear, \.\.\.\), .*, got "joy"$/,
    );
  });

  it('the manifest has a row per stimulus with what it was made from', () => {
    const stimuli = expandStimulusList({
      ...base,
      stimuli: [{ name: 'smile', expression: { AU12: 1 }, light: [{}, { keyColor: '#ff0000', keyIntensity: 2 }] }],
    });
    expect(stimulusManifest(stimuli).split('\n')).toEqual([
      'file,name,format,expression,emotion,timeline,intensity,light,camera,resolution,identity,width,height,fps',
      'smile_i1_l0_c0_medium.png,smile,png,"{""AU12"":1}",,no,1,{},{},medium,,512,512,25',
      'smile_i1_l1_c0_medium.png,smile,png,"{""AU12"":1}",,no,1,"{""keyColor"":""#ff0000"",""keyIntensity"":2}",{},medium,,512,512,25',
      '',
    ]);
  });

  it("docs/stimuli.md's example list is a valid list: 4 smiles, 2 fears and a clip", () => {
    const doc = readFileSync(new URL('../docs/stimuli.md', import.meta.url), 'utf8');
    const section = doc.slice(doc.indexOf('# Stimulus batches'));
    const json = section.slice(section.indexOf('```json') + 7, section.indexOf('```', section.indexOf('```json') + 7));
    const stimuli = expandStimulusList(JSON.parse(json), 'docs/stimuli.md');
    expect(stimuli.map((s) => s.file)).toEqual([
      'smile_i0.5_l0_c0_medium.png',
      'smile_i0.5_l0_c1_medium.png',
      'smile_i1_l0_c0_medium.png',
      'smile_i1_l0_c1_medium.png',
      'fear_i1_l0_c0_low.png',
      'fear_i1_l0_c0_high.png',
      'surprise-clip_i1_l0_c0_medium.webm',
    ]);
  });
});
