import { openFace } from './face';
import { test } from './fixtures';
import { recordTrackingClip } from './tracking-clip';

/** Records the webcam tracker test's fake camera clip (see e2e/tracking-clip.ts); the clip is checked where it is used. */
test('the face records the fake camera clip of a known timeline', async ({ page }) => {
  test.setTimeout(300_000);
  await openFace(page, '/?resolution=low');
  await recordTrackingClip(page);
});
