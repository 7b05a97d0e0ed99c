import { describeHighSettles } from './fixtures/high-settles';

// The lower face's Action Units on the high head not settled elsewhere (AU12, AU15 to AU18 in
// tests/wrinkles-high-no-crumpling.test.ts, AU13, AU14 and AU20 in tests/expressions-settle-high-mouth-corners.test.ts).
// AU10 and AU23 are the slowest units of the high head (493 and 209 frames, docs/solver-notes.md); with
// tests/expressions-settle-high-upper-face.test.ts every unit of the rig is settled on the high head.
describeHighSettles('the lower face', ['AU10', 'AU11', 'AU22', 'AU23', 'AU24', 'AU25', 'AU26', 'AU27']);
