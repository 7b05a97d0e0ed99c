// node .variants.mjs PORT JITTER 'name=AU4:1,AU5:1;name2=...'
import { launchBrowser, openApp } from './scripts/browser.mjs';
import { HIDE_PANELS_CSS, VIEWS, recognizeView, startRecognizer } from './scripts/recognition.mjs';
const [port, jit, spec] = process.argv.slice(2);
const jitter = jit.split(',').map(Number);
const variants = spec.split(';').map((s) => { const [n, aus] = s.split('='); return { n, aus: Object.fromEntries(aus.split(',').map((p) => { const [k, v] = p.split(':'); return [k, Number(v)]; })) }; });
const browser = await launchBrowser();
const recognizer = await startRecognizer(browser, {});
const page = await browser.newPage({ viewport: { width: 900, height: 900 } });
await openApp(page, `http://127.0.0.1:${port}/?resolution=medium`, { timeout: 120000, retries: 51, retryMs: 200 });
await page.addStyleTag({ content: HIDE_PANELS_CSS });
for (const { n, aus } of variants) {
  await page.evaluate(async (aus) => { const f = window.face; f.reset(); await f.settle(60000); for (const [k, v] of Object.entries(aus)) f.setActionUnit(k, v); await f.settle(60000); }, aus);
  const out = [];
  let sum = 0;
  for (const { view, yaw } of VIEWS) {
    const r = await recognizeView(page, recognizer, yaw, jitter);
    if (process.env.IMG) (await import('node:fs')).writeFileSync(`${process.env.IMG}/${n}_${view}.png`, r.png);
    sum += r.expressions[process.env.MEANT ?? "angry"] ?? 0;
    out.push(`${view} ${r.top} ${r.probability.toFixed(2)} (angry ${(r.expressions.angry ?? 0).toFixed(2)})`);
  }
  console.log(`${n}: ${out.join(' | ')} mean meant ${(sum / 3).toFixed(2)}`);
}
await recognizer.close();
await browser.close();
