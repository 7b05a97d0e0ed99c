/** A line of text in a folder, found by its `data-control` name. */
export function note(name: string, style: Partial<CSSStyleDeclaration>): HTMLDivElement {
  const div = document.createElement('div');
  div.dataset.control = name;
  Object.assign(div.style, { padding: '2px 8px 4px', fontSize: '11px', lineHeight: '1.35' }, style);
  return div;
}
