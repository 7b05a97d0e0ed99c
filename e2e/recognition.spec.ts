import { HIDE_PANELS_CSS, meantLabel, recognizeView, showExpression, startRecognizer } from '../scripts/recognition.mjs';
import { openFace } from './face';
import { expect, test } from './fixtures';

/** Neutral and the prototypes the recogniser has a class for (it has none for contempt). */
const FACES = ['neutral', 'happiness', 'sadness', 'surprise', 'fear', 'anger', 'disgust'];
/**
 * The goal: each of these faces reads as the emotion it is meant to show. One miss is allowed: a recogniser trained
 * on photographs gets some posed photographs wrong too, most often within the known confusions (fear and surprise,
 * disgust and anger).
 */
const AT_LEAST = 6;
/**
 * The size `npm run recognize` renders at: the recogniser's answers move with the picture's size (at 600 px the thin
 * brow and lash hairs are under a pixel wide, and the smile read sad 0.61 that reads happy 0.91 at 900).
 */
const SIZE = 900;

test.use({ viewport: { width: SIZE, height: SIZE } });

/**
 * The presets read as meant to an automatic recogniser (scripts/recognition.mjs, as `npm run recognize` uses it):
 * neutral and the six prototypes with a class, front view (its readings averaged over turns of a degree either way,
 * see VIEW_JITTER), medium head, each settled from the neutral face; the recogniser's top class must be the meant one
 * for at least 6 of the 7.
 */
test('neutral and the prototypes read as meant to an automatic recogniser, front view', async ({ page, browser }) => {
  test.setTimeout(300_000);
  // tfjs's wasm backend, as `npm run recognize` uses it.
  const recognizer = await startRecognizer(browser);
  try {
    await openFace(page, '/?resolution=medium');
    await page.addStyleTag({ content: HIDE_PANELS_CSS });
    const rows: string[] = [];
    let hits = 0;
    for (const name of FACES) {
      expect(await showExpression(page, name), `${name} settles`).toBe(true);
      const r = await recognizeView(page, recognizer, 0);
      const meant = meantLabel(name)!;
      if (r.top === meant) hits++;
      rows.push(
        `${name}: ${r.detected ? `${r.top} ${r.probability!.toFixed(2)}, ${meant} ${r.expressions![meant].toFixed(2)}` : 'no face found'}`,
      );
    }
    console.log(rows.join('\n'));
    expect(hits, `faces that read as meant:\n${rows.join('\n')}`).toBeGreaterThanOrEqual(AT_LEAST);
  } finally {
    await recognizer.close();
  }
});
