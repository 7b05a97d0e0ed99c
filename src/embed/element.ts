/**
 * `import 'softface/element'` registers `<soft-face>` (once, even if imported twice) and gives it a default size:
 * a block 400 px high, which any style of the page's own overrides.
 *
 * @module softface/element
 */
import { SoftFaceElement } from './soft-face-element';

export { SoftFaceElement, type SoftFaceChangeDetail } from './soft-face-element';

if (!customElements.get('soft-face')) {
  // A constructed sheet rather than a <style> element: a content security policy without 'unsafe-inline' allows it.
  // :where() gives it no specificity, so the page's own rules win.
  const sheet = new CSSStyleSheet();
  sheet.replaceSync(':where(soft-face) { display: block; height: 400px; }');
  document.adoptedStyleSheets = [...document.adoptedStyleSheets, sheet];
  customElements.define('soft-face', SoftFaceElement);
}
