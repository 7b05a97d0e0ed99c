import { loadDefaultRig } from './fixtures/head-simulation';
import { describeHighSettles } from './fixtures/high-settles';

// The prototypes on the high head not settled elsewhere (see tests/expressions-settle-high-presets.test.ts; anger in
// tests/expressions-settle-high-untangle.test.ts): sadness is the slowest preset there (121 frames).
const SETTLED_ELSEWHERE = new Set(['happiness', 'fear', 'disgust', 'anger']);
describeHighSettles(
  'the prototypes',
  loadDefaultRig()
    .presets.map((p) => p.name)
    .filter((name) => !name.startsWith('thesis-') && !SETTLED_ELSEWHERE.has(name)),
);
