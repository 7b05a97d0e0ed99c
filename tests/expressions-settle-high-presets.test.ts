import { describeHighSettles } from './fixtures/high-settles';

// The thesis's five presets on the high head. With the prototypes in tests/expressions-settle-high-prototypes.test.ts,
// fear in tests/expressions-settle-high-mouth-corners.test.ts and happiness and disgust in
// tests/wrinkles-high-no-crumpling.test.ts, every preset is settled on the high head: a change that passed the medium
// head's tests once left the high head's AU10 at the safety net and AU23 with a triangle turned over (anger and
// disgust carry them; docs/solver-notes.md, "Bending at the colliders at a half").
describeHighSettles('the thesis presets', ['thesis-happiness', 'thesis-sadness', 'thesis-laughing', 'thesis-anger', 'thesis-surprise']);
