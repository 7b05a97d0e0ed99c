import type { Object3D } from 'three';
import { LANDMARK_LABELS, type LandmarkName, type Landmarks } from '../core/head/landmarks';
import type { Vec3 } from '../core/rig/rig-types';
import type { HeadView } from '../render/head-view';
import { LandmarkGuideView } from '../render/landmark-guide-view';
import type { MissingLandmarksError } from './head-loader';

/** Where a landmark guide stands: what to click next ("the left mouth corner"), and what is placed so far. */
export interface LandmarkGuideState {
  /** The file whose landmarks are placed. */
  file: string;
  /** The landmark the next click (or `placeLandmark`) places, e.g. `mouth-l`; null once all are placed. */
  next: LandmarkName | null;
  /** What to click for it, as the panel asks. */
  prompt: string;
  /**
   * The landmarks placed so far by this guide, by name: points on the shown skin, in metres in the app's frame (+y up,
   * the face toward +z, the subject's left at +x).
   */
  placed: Partial<Record<LandmarkName, Vec3>>;
  /** Every landmark that could not be found in the file, placed ones included, in the order the guide asks for them. */
  missing: LandmarkName[];
}

/**
 * Placing a head's missing landmarks by hand: its skin is shown alone (the face's head is hidden meanwhile), each click
 * on it places the next missing landmark; `done` resolves with them once all are placed, or rejects on `cancel`.
 */
export class LandmarkGuide {
  readonly done: Promise<Partial<Landmarks>>;
  private readonly placed: Partial<Record<LandmarkName, Vec3>> = {};
  private readonly view: LandmarkGuideView;
  private resolve!: (landmarks: Partial<Landmarks>) => void;
  private reject!: (error: Error) => void;
  private finished = false;

  constructor(
    headView: HeadView,
    private readonly missingError: MissingLandmarksError,
    private readonly hidden: Object3D | undefined,
    private readonly changed: () => void,
  ) {
    this.done = new Promise((resolve, reject) => {
      this.resolve = resolve;
      this.reject = reject;
    });
    if (hidden) hidden.visible = false;
    this.view = new LandmarkGuideView(headView, missingError.skin, (point) => this.place(point));
    // The points found are shown too: what the clicks add to.
    this.view.showPoints(Object.values(missingError.found));
  }

  state(): LandmarkGuideState {
    const next = this.next();
    const file = this.missingError.message.split(':')[0];
    return {
      file,
      next,
      prompt: next ? `click ${LANDMARK_LABELS[next]} (${Object.keys(this.placed).length + 1} of ${this.missingError.missing.length})` : '',
      placed: structuredClone(this.placed),
      missing: [...this.missingError.missing],
    };
  }

  /** Places the next missing landmark at `point` (metres, the app's frame); throws naming a bad point. */
  place(point: Vec3): void {
    const next = this.next();
    if (!next || this.finished) throw new Error('placeLandmark: no landmark guide is under way');
    if (!Array.isArray(point) || point.length !== 3 || !point.every((x) => typeof x === 'number' && Number.isFinite(x))) {
      throw new Error(`placeLandmark: the point must be [x, y, z] in metres, got ${JSON.stringify(point)}`);
    }
    this.placed[next] = [point[0], point[1], point[2]];
    this.view.showPoints([...Object.values(this.missingError.found), ...Object.values(this.placed)]);
    this.changed();
    if (!this.next()) {
      this.finished = true;
      this.resolve({ ...this.placed });
    }
  }

  /** Where a point of the shown skin is on the page (client pixels), for scripts that click it. */
  locate(point: Vec3): { x: number; y: number } {
    return this.view.locate(point);
  }

  /** Stops the guide: `done` rejects, and nothing is loaded. */
  cancel(): void {
    if (this.finished) return;
    this.finished = true;
    this.reject(new Error(`${this.state().file}: placing the landmarks was cancelled`));
  }

  /** Takes the skin shown off the scene and shows the face's head again. */
  dispose(): void {
    this.view.dispose();
    if (this.hidden) this.hidden.visible = true;
  }

  private next(): LandmarkName | null {
    return this.missingError.missing.find((name) => !this.placed[name]) ?? null;
  }
}
