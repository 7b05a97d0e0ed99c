/**
 * The expression carried in the URL hash, kept up to date by HashSync so that a copied link reopens the same face,
 * and carried over when the page reloads with another head resolution: `#AU12L=0.5&AU12R=0.5&preset:happiness=0.3`
 * (non-zero values only; `URLSearchParams` writes the colon as `%3A`, and either form reads back).
 */

/** What the hash carries: Action Unit sliders by side id, and preset weights by name. */
export interface HashExpression {
  actionUnits: Record<string, number>;
  presets: Record<string, number>;
}

const PRESET_PREFIX = 'preset:';

/** The hash (with its `#`) for an expression; zero values are left out. */
export function encodeExpression(e: HashExpression): string {
  const params = new URLSearchParams();
  for (const [id, v] of Object.entries(e.actionUnits)) if (v !== 0) params.set(id, String(round(v)));
  for (const [name, w] of Object.entries(e.presets)) if (w !== 0) params.set(PRESET_PREFIX + name, String(round(w)));
  const text = params.toString();
  return text ? `#${text}` : '';
}

/** Reads an expression from a hash (with or without its `#`); entries that are not finite numbers are skipped. */
export function decodeExpression(hash: string): HashExpression {
  const out: HashExpression = { actionUnits: {}, presets: {} };
  for (const [key, text] of new URLSearchParams(hash.replace(/^#/, ''))) {
    const value = Number(text);
    if (text.trim() === '' || !Number.isFinite(value)) continue;
    if (key.startsWith(PRESET_PREFIX)) out.presets[key.slice(PRESET_PREFIX.length)] = value;
    else out.actionUnits[key] = value;
  }
  return out;
}

/** Slider values have two decimals; four keep the link short without changing them. */
function round(x: number): number {
  return Math.round(x * 1e4) / 1e4;
}
