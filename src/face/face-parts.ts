import type { SkinSimulation } from '../sim/main/skin-simulation';
import type { FaceExpression } from './face-expression';
import type {
  FaceChange,
  FaceChangeListener,
  FaceEyes,
  FaceGLTFWriter,
  FaceHeads,
  FaceMuscles,
  FaceRecorder,
  FaceShell,
  FaceTimeline,
  FaceView,
} from './face-ports';

/**
 * The parts one face is made of, as its controllers reach them, and the listeners of its changes. EmbeddedFace
 * connects the parts as it builds the face and swaps heads; each getter throws, naming what is missing, while a part
 * is not there yet or after the face was disposed.
 */
export class FaceParts {
  simulation: SkinSimulation | undefined;
  expression: FaceExpression | undefined;
  view: FaceView | undefined;
  eyes: FaceEyes | undefined;
  player: FaceTimeline | undefined;
  gltfWriter: FaceGLTFWriter | undefined;
  recorder: FaceRecorder | undefined;
  muscles: FaceMuscles | undefined;
  heads: FaceHeads | undefined;
  shell: FaceShell | undefined;
  /** The face's `assetBase` option: where the package's files are fetched from (null: where its build put them). */
  assetBase: string | URL | null = null;
  private disposedNow = false;
  /**
   * Replaced, never changed in place, when a listener comes or goes: `emit` walks the array it started with (a
   * listener that unsubscribes while being told does not make the next one miss the change) without copying it, as
   * a playing timeline emits every frame.
   */
  private listeners: readonly FaceChangeListener[] = [];

  /** Whether the face was disposed. */
  get disposed(): boolean {
    return this.disposedNow;
  }

  /** Marks the face disposed and forgets its listeners; the getters throw from then on. */
  dispose(): void {
    this.disposedNow = true;
    this.listeners = [];
  }

  /** Adds a change listener; returns the function that removes it. */
  listen(listener: FaceChangeListener): () => void {
    this.alive();
    this.listeners = [...this.listeners, listener];
    return () => {
      const i = this.listeners.indexOf(listener);
      if (i >= 0) this.listeners = [...this.listeners.slice(0, i), ...this.listeners.slice(i + 1)];
    };
  }

  /** Tells the listeners of a change (nothing after `dispose`). */
  emit(change: FaceChange): void {
    const listeners = this.listeners;
    for (let i = 0; i < listeners.length; i++) listeners[i](change);
  }

  alive(): void {
    if (this.disposedNow) throw new Error('the face was disposed');
  }

  running(): SkinSimulation {
    this.alive();
    if (!this.simulation) throw new Error('the face is not ready yet: await face.ready first');
    return this.simulation;
  }

  expressed(): FaceExpression {
    this.running();
    return this.expression!;
  }

  shown(): FaceView {
    this.alive();
    if (!this.view) throw new Error('the face has no view yet');
    return this.view;
  }

  element(): FaceShell {
    this.alive();
    if (!this.shell) throw new Error('the face has no element yet');
    return this.shell;
  }

  headSide(): FaceHeads {
    this.alive();
    if (!this.heads) throw new Error('the face is not ready yet: await face.ready first');
    return this.heads;
  }

  timeline(): FaceTimeline {
    this.expressed();
    if (!this.player) throw new Error('the face has no timeline player yet: await face.ready first');
    return this.player;
  }

  eyeSimulation(): FaceEyes {
    this.alive();
    if (!this.eyes) throw new Error('the face has no eye simulation yet: await face.ready first');
    return this.eyes;
  }
}
