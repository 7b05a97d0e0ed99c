import { loadDefaultRig } from './fixtures/head-simulation';
import { describeHighPresets } from './fixtures/high-presets';

// The prototypes on the high head not settled elsewhere (see tests/expressions-settle-high-presets.test.ts): sadness
// and anger are the slowest presets there (279 and 143 frames).
const SETTLED_ELSEWHERE = new Set(['happiness', 'fear', 'disgust']);
describeHighPresets(
  loadDefaultRig()
    .presets.map((p) => p.name)
    .filter((name) => !name.startsWith('thesis-') && !SETTLED_ELSEWHERE.has(name)),
);
