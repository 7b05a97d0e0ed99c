/**
 * How a person's skin ages, as the skin solver's parameters and a resting pull, from published skin mechanics:
 * - thickness: the skin thins linearly with age after about 25, some 0.6 % of its young thickness a year (Shuster,
 *   Black, McVitie, "The influence of age and sex on skin thickness, skin collagen and density", Br J Dermatol 93,
 *   1975). A thinner plate bends more easily: the fold spacing of a plate on an elastic foundation, 2π (B / k)^(1/4)
 *   with B ∝ t³, goes as t^(3/4), so old skin folds in finer lines;
 * - elasticity: the skin's elastic recovery falls with age (Escoffier et al., "Age-related mechanical properties of
 *   human skin: an in vivo study", J Invest Dermatol 93, 1989); the tissue's pull back to rest (`positionStiffness`)
 *   falls with it, by the same 0.6 % a year here;
 * - tension at rest: skin in the body is stretched (it retracts when cut free, along Langer's lines) and loses that
 *   tension with age as its elastic fibres degrade; a compression first releases it, so young skin takes an
 *   expression's compression with shallow folds and old skin folds deeply (the pre-stress of Flynn & McCormack's
 *   multi-layer finite element model of skin wrinkling and ageing, J Biomech 43, 2010). Here `pretension` is 0.15 up
 *   to 25 years and falls linearly to none at 70;
 * - a resting pull: folds made many thousands of times stop springing back (static lines). Here an old face keeps at
 *   rest a share of its habitual expression's pull, the brow raisers (AU1, AU2), the brow lowerer (AU4) and the cheek
 *   raiser (AU6), from nothing at 40 years to 0.3 at 80, so its lines show where its expression lines form.
 * Pure numbers: no three.js.
 */
import { SKIN_DEFAULTS, type SkinParameters } from '../solver/skin-parameters';

/** Share of the young skin's thickness (and elastic recovery) lost per year after 25. */
const LOSS_PER_YEAR = 0.006;
const PULL_AT_80 = 0.3;
/** The young skin's pretension (SkinParameters.pretension), kept to 25 years and gone at 70. */
const YOUNG_PRETENSION = 0.15;

/** The skin parameters age sets, and the pull a face keeps at rest (Action Unit intensities). */
export interface AgedSkin {
  parameters: Pick<SkinParameters, 'wrinkleSpacing' | 'positionStiffness' | 'pretension'>;
  tone: Record<string, number>;
}

/** The skin of a person of `age` years (the default head's skin is MakeHuman's base: the defaults, no pull). */
export function agedSkin(age: number): AgedSkin {
  const kept = 1 - LOSS_PER_YEAR * Math.max(0, age - 25);
  const pull = PULL_AT_80 * Math.min(1, Math.max(0, (age - 40) / 40));
  return {
    parameters: {
      wrinkleSpacing: SKIN_DEFAULTS.wrinkleSpacing * kept ** 0.75,
      positionStiffness: SKIN_DEFAULTS.positionStiffness * kept,
      pretension: YOUNG_PRETENSION * Math.min(1, Math.max(0, (70 - age) / 45)),
    },
    tone: pull > 0 ? { AU1: pull, AU2: pull, AU4: pull, AU6: pull } : {},
  };
}
