import { loadDefaultRig } from './fixtures/head-simulation';
import { describeHighSettles } from './fixtures/high-settles';

// The prototypes on the high head not settled elsewhere (see tests/expressions-settle-high-presets.test.ts): sadness
// and anger are the slowest presets there (276 and 385 frames).
const SETTLED_ELSEWHERE = new Set(['happiness', 'fear', 'disgust']);
describeHighSettles(
  'the prototypes',
  loadDefaultRig()
    .presets.map((p) => p.name)
    .filter((name) => !name.startsWith('thesis-') && !SETTLED_ELSEWHERE.has(name)),
);
