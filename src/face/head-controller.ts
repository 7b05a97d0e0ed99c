import { readIdentity, stockIdentities, type Identity, type NamedIdentity } from '../core/head/identity';
import type { Vec3 } from '../core/rig/rig-types';
import type { ExpressionController } from './expression-controller';
import type { FaceParts } from './face-parts';
import type { CarriedState } from './face-ports';
import type { HeadDescription, HeadSource, LoadHeadOptions } from './head-loader';
import type { LandmarkGuideState } from './landmark-guide';

/** Which head the face shows: loading another, going back to the default one, placing landmarks a head lacks. */
export class HeadController {
  constructor(
    private readonly parts: FaceParts,
    private readonly ready: Promise<void>,
    private readonly expression: ExpressionController,
  ) {}

  /**
   * Loads a head (a `.glb`, a `.gltf` with its files, or an `.obj`: a URL, a File or a list of Files), carries the
   * rig over to it by its landmarks and shows it in place of the current one, keeping the expression. Resolves to
   * what was loaded; a file that is not a head (not a mesh, truncated, non-finite, no face found, over 200,000
   * triangles or 64 MB) rejects with a message naming the file and what is wrong, and the current head stays.
   */
  async loadHead(source: HeadSource, options?: LoadHeadOptions): Promise<HeadDescription> {
    this.parts.alive();
    await this.ready;
    return this.parts.headSide().loadHead(source, options);
  }

  /** Shows the default head again, with the face's own rig (a kept loaded head is forgotten). */
  async revertHead(): Promise<void> {
    this.parts.alive();
    await this.ready;
    return this.parts.headSide().revertHead();
  }

  /**
   * Loads a head as `loadHead` does; where its landmarks cannot all be found, shows its skin alone and has the
   * missing ones placed by clicking on it (the Head folder says which: "click the left mouth corner"), then loads it
   * with them. Resolves once the head is shown; rejects if the guide is cancelled or the file is refused otherwise.
   */
  async guideLandmarks(source: HeadSource, options?: LoadHeadOptions): Promise<HeadDescription> {
    this.parts.alive();
    await this.ready;
    return this.parts.headSide().guideLandmarks(source, options);
  }

  /** The landmark guide under way (what to click next, what is placed), or null. */
  describeLandmarkGuide(): LandmarkGuideState | null {
    return this.parts.headSide().landmarkGuide()?.state() ?? null;
  }

  /** Places the guide's next landmark at a point of the shown skin (metres), as a click on it does. */
  placeLandmark(point: Vec3): void {
    const guide = this.parts.headSide().landmarkGuide();
    if (!guide) throw new Error('placeLandmark: no landmark guide is under way');
    guide.place(point);
  }

  /** Where a point of the skin the guide shows is on the page (client pixels), to click it (read-only, for tests). */
  locateLandmarkPoint(point: Vec3): {
    /** Client pixels from the viewport's left edge, as `MouseEvent.clientX` counts them. */
    x: number;
    /** Client pixels from the viewport's top edge, as `MouseEvent.clientY` counts them. */
    y: number;
  } | null {
    return this.parts.headSide().landmarkGuide()?.locate(point) ?? null;
  }

  /** Stops the landmark guide; its `guideLandmarks` rejects and the face keeps its head. */
  cancelLandmarkGuide(): void {
    this.parts.headSide().landmarkGuide()?.cancel();
  }

  /**
   * Shows a person: `{ sex, age, ancestry }` (sex 0 female .. 1 male, age 1..90 years, ancestry weights
   * `{ african, asian, european }` scaled to sum to 1; missing fields take MakeHuman's average), a stock name (see
   * `listIdentities`), or null for the default head. The head is built from the MakeHuman base mesh and its macro
   * targets at the face's resolution, with eyes, teeth and the rig carried over; the expression stays. Resolves to
   * the head shown; a bad identity rejects naming the field, and the current head stays.
   */
  async setIdentity(identity: Identity | string | null): Promise<HeadDescription> {
    const named = readIdentity(identity, 'setIdentity');
    this.parts.alive();
    await this.ready;
    return this.parts.headSide().showIdentity(named);
  }

  /** The person the face shows (a copy), or null for the default head and a loaded one. */
  getIdentity(): Identity | null {
    return this.parts.headSide().describeHead().identity;
  }

  /** The stock identities, by name: each sex, three ages (22, 45, 72 years) and three ancestries. */
  listIdentities(): NamedIdentity[] {
    return stockIdentities();
  }

  /** The head shown: default or loaded, its file, size, units, axes and landmarks (read-only). */
  describeHead(): HeadDescription {
    return this.parts.headSide().describeHead();
  }

  /** The state a new head takes over from the current one. */
  carried(): CarriedState {
    return {
      expression: this.expression.current(),
      eyes: this.parts.eyes?.enabled() ?? false,
      skin: this.parts.running().parameters(),
    };
  }

  /** Gives a new head the state the previous one had. */
  restore(state: CarriedState): void {
    try {
      this.parts.expressed().set(state.expression, 'loadHead');
    } catch (error) {
      // A preset the new head's rig does not have (an imported rig had it): the new head starts neutral.
      console.warn(`the expression was not carried over to the new head: ${(error as Error).message}`);
    }
    this.parts.running().setParameters(state.skin);
    this.parts.eyes?.setEnabled(state.eyes);
  }
}

/** The handle's methods that HeadController answers. */
export const HEAD_METHODS = [
  'loadHead',
  'revertHead',
  'guideLandmarks',
  'describeLandmarkGuide',
  'placeLandmark',
  'locateLandmarkPoint',
  'cancelLandmarkGuide',
  'describeHead',
  'setIdentity',
  'getIdentity',
  'listIdentities',
] as const;
