import { addFaces, openEmbedPage } from './embed';
import { expect, test } from './fixtures';

test("a face's canvas follows its container's size", async ({ page }) => {
  await openEmbedPage(page);
  await addFaces(page, { a: { resolution: 'low' } }, { width: 300, height: 200, inView: false });
  const size = () =>
    page.evaluate(() => {
      const canvas = document.querySelector('#a canvas') as HTMLCanvasElement;
      const box = canvas.getBoundingClientRect();
      return { pixels: [canvas.width / devicePixelRatio, canvas.height / devicePixelRatio], box: [box.width, box.height] };
    });
  expect(await size()).toEqual({ pixels: [300, 200], box: [300, 200] });
  await page.evaluate(() => Object.assign(document.getElementById('a')!.style, { width: '420px', height: '150px' }));
  // The observer reports after layout, at the next frame.
  await expect.poll(size).toEqual({ pixels: [420, 150], box: [420, 150] });
});
