import { openFace } from './face';
import { expect, test } from './shared-app';

test('a refused camera rejects startTracking with a clear message, and the face keeps its expression', async ({ page }) => {
  await openFace(page, '/?resolution=low');
  const result = await page.evaluate(async () => {
    const face = window.face;
    face.setActionUnit('AU12', 0.6);
    // The browser's answer when the viewer says no.
    navigator.mediaDevices.getUserMedia = () => Promise.reject(new DOMException('Permission denied', 'NotAllowedError'));
    let message = '';
    try {
      await face.startTracking();
    } catch (e) {
      message = (e as Error).message;
    }
    let bad = '';
    try {
      await face.startTracking({ source: 'camera' as never });
    } catch (e) {
      bad = (e as Error).message;
    }
    return { message, bad, state: face.trackingState(), au12: face.getEffectiveActionUnits().AU12L };
  });
  expect(result.message).toBe('startTracking: the camera could not be opened (NotAllowedError: Permission denied)');
  expect(result.bad).toMatch(/^startTracking: source: expected a MediaStream or an HTMLVideoElement, got "camera"$/);
  expect(result.state.on).toBe(false);
  expect(result.au12).toBeCloseTo(0.6, 6);
});
