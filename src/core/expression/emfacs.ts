/**
 * The EMFACS table (Friesen & Ekman 1983): for each basic emotion, the FACS codes of its prototypes and major
 * variants, as the FACS Investigator's Guide (Ekman, Friesen & Hager 2002, chapter 12) tables them. A study picks an
 * emotion's faces from it by name (`fear-prototype-2`), or all of them (`fear`). Pure: no DOM, no three.js.
 *
 * How the table's shorthand is written out here: "25, 26 or 27" and "with or without 54+64" become one code each; an
 * AU the table marks as "any intensity" has no letter (E, full); a letter is the table's. Contempt is not in EMFACS:
 * its prototype is the unilateral lip corner tightening and raising of Ekman & Friesen (1986), as the face's
 * `contempt` preset has it.
 */
import { refusal } from '../check';

/** The emotions of the table. */
export const EMOTIONS = Object.freeze(['surprise', 'fear', 'happiness', 'sadness', 'disgust', 'anger', 'contempt'] as const);
/** One of `EMOTIONS`. */
export type Emotion = (typeof EMOTIONS)[number];

/** One face of the table: an emotion's prototype or major variant as a FACS code. */
export interface EmotionVariant {
  /** Its name, as `setEmotion` takes it: `fear-prototype-2`, `anger-variant-11` (numbered from 1 within its kind). */
  name: string;
  /** The emotion it shows. */
  emotion: Emotion;
  /** A prototype, or a major variant of one. */
  kind: 'prototype' | 'variant';
  /** The face as a FACS code, as `setFACS` takes it: `1+2+4+5+20+26`. */
  code: string;
  /** Where the code comes from. */
  source: string;
}

const GUIDE = 'EMFACS (Friesen & Ekman 1983), FACS Investigator’s Guide (Ekman, Friesen & Hager 2002)';
const CONTEMPT = 'Ekman & Friesen (1986), a unilateral AU14 with AU12';

/** Every code of `base` joined with each of `endings` (`''` for none). */
const each = (base: string, endings: readonly string[]): string[] => endings.map((e) => (e ? `${base}+${e}` : base));
const opening = ['25', '26', '27'];
const withOpening = (base: string): string[] => each(base, opening);
const headDown = (base: string): string[] => each(base, ['', '54+64']);

/** The anger prototypes; the variants are each of them with one of 4, 5, 7 or 10 left out. */
const ANGER = [
  '4+5+7+10+22+23+25',
  '4+5+7+10+22+23+26',
  '4+5+7+10+23+25',
  '4+5+7+10+23+26',
  '4+5+7+23+25',
  '4+5+7+23+26',
  '4+5+7+17+23',
  '4+5+7+17+24',
  '4+5+7+23',
  '4+5+7+24',
];

/** Each code of `prototypes` with one of `units` left out (where it has it), once each, none that is a prototype. */
function leftOut(prototypes: readonly string[], units: readonly string[]): string[] {
  const out = new Set<string>();
  for (const code of prototypes) {
    const parts = code.split('+');
    for (const u of units) if (parts.includes(u)) out.add(parts.filter((p) => p !== u).join('+'));
  }
  for (const p of prototypes) out.delete(p);
  return [...out];
}

const TABLE: Record<Emotion, { prototypes: string[]; variants: string[]; source: string }> = {
  surprise: {
    prototypes: ['1+2+5B+26', '1+2+5B+27'],
    variants: ['1+2+5B', '1+2+26', '1+2+27', '5B+26', '5B+27'],
    source: GUIDE,
  },
  fear: {
    prototypes: [...withOpening('1+2+4+5+20'), ...withOpening('1+2+4+5')],
    variants: [
      ...withOpening('1+2+4+5+L20'),
      ...withOpening('1+2+4+5+R20'),
      '1+2+4+5',
      '1+2+5',
      ...withOpening('1+2+5'),
      '5+20',
      ...withOpening('5+20'),
    ],
    source: GUIDE,
  },
  happiness: { prototypes: ['6+12', '12C', '12D'], variants: [], source: GUIDE },
  sadness: {
    prototypes: [...headDown('1+4+11+15B'), ...headDown('1+4+15'), ...headDown('6+15')],
    variants: [...headDown('1+4+11'), ...headDown('1+4+15B'), ...headDown('1+4+15B+17'), ...headDown('11+15B'), '11+17'],
    source: GUIDE,
  },
  disgust: { prototypes: ['9', '9+16+15', '9+16+26', '9+17', '10', '10+16+25', '10+16+26', '10+17'], variants: [], source: GUIDE },
  anger: { prototypes: ANGER, variants: leftOut(ANGER, ['4', '5', '7', '10']), source: GUIDE },
  contempt: { prototypes: ['R12A+R14A', 'L12A+L14A'], variants: ['R14', 'L14'], source: CONTEMPT },
};

/** The whole table: every emotion's prototypes, then its major variants, in the order of `EMOTIONS`. */
export const EMFACS: readonly EmotionVariant[] = Object.freeze(
  EMOTIONS.flatMap((emotion) => {
    const { prototypes, variants, source } = TABLE[emotion];
    const entries = (kind: EmotionVariant['kind'], codes: string[]) =>
      codes.map((code, i) => Object.freeze({ name: `${emotion}-${kind}-${i + 1}`, emotion, kind, code, source }));
    return [...entries('prototype', prototypes), ...entries('variant', variants)];
  }),
);

const SELECTOR = 'an emotion (surprise, fear, ...), an emotion and kind (fear:prototype, fear:variant) or a face (fear-prototype-2)';

/**
 * The table's faces a selector names: an emotion (`fear`: all its prototypes and variants), an emotion and a kind
 * (`fear:prototype`, `fear:variant`), or one face by name (`fear-prototype-2`). Throws, starting with `what`, on a
 * selector it does not know.
 */
export function emotionVariants(selector: unknown, what = 'emotion'): EmotionVariant[] {
  if (typeof selector !== 'string') throw refusal(what, '', SELECTOR, selector);
  const [emotion, kind, ...rest] = selector.split(':');
  if (rest.length === 0 && (EMOTIONS as readonly string[]).includes(emotion)) {
    if (kind === undefined) return EMFACS.filter((v) => v.emotion === emotion);
    if (kind === 'prototype' || kind === 'variant') return EMFACS.filter((v) => v.emotion === emotion && v.kind === kind);
  }
  const one = EMFACS.find((v) => v.name === selector);
  if (!one) throw refusal(what, '', SELECTOR, selector);
  return [one];
}
