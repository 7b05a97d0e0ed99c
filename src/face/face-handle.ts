import type { MuscleDisplay } from '../core/rig/muscle-display';
import { EDITOR_METHODS, EditorController } from './editor-controller';
import { EXPORT_METHODS, ExportController } from './export-controller';
import { EXPRESSION_METHODS, ExpressionController } from './expression-controller';
import { EYES_METHODS, EyesController } from './eyes-controller';
import type { FaceParts } from './face-parts';
import type { FaceChangeListener } from './face-ports';
import { HEAD_METHODS, HeadController } from './head-controller';
import { LIVE_METHODS, LiveController } from './live-controller';
import { RIG_METHODS, RigController } from './rig-controller';
import { SKIN_METHODS, SkinController } from './skin-controller';
import { TIMELINE_METHODS, TimelineController } from './timeline-controller';
import { VIEW_METHODS, ViewController } from './view-controller';

export { gizmoParts, type EditorState, type FaceEditorView, type GizmoMode } from './editor-session';
export type { MuscleDisplay };
export type {
  SkinSnapshot,
  FaceStats,
  FaceChange,
  EyeStats,
  FaceEyes,
  TimelineState,
  FaceChangeListener,
} from './face-ports';

/** The controllers a face's handle hands its methods to, one per concern, each owning its state. */
export interface FaceControllers {
  skin: SkinController;
  view: ViewController;
  expression: ExpressionController;
  timeline: TimelineController;
  eyes: EyesController;
  export: ExportController;
  head: HeadController;
  editor: EditorController;
  rig: RigController;
  live: LiveController;
}

/** Makes the controllers of one face over its parts; `ready` is the face's start. */
export function createControllers(parts: FaceParts, ready: Promise<void>): FaceControllers {
  const expression = new ExpressionController(parts);
  const timeline = new TimelineController(parts);
  const editor = new EditorController(parts);
  return {
    skin: new SkinController(parts, ready),
    view: new ViewController(parts),
    expression,
    timeline,
    eyes: new EyesController(parts),
    export: new ExportController(parts, ready, timeline, () => editor.session.applyPreview()),
    head: new HeadController(parts, ready, expression),
    editor,
    rig: new RigController(parts, editor.session),
    live: new LiveController(parts, timeline),
  };
}

/** Which of the handle's methods each controller answers: the handle's public surface, one list per concern. */
const DELEGATED = {
  skin: SKIN_METHODS,
  view: VIEW_METHODS,
  expression: EXPRESSION_METHODS,
  timeline: TIMELINE_METHODS,
  eyes: EYES_METHODS,
  export: EXPORT_METHODS,
  head: HEAD_METHODS,
  editor: EDITOR_METHODS,
  rig: RIG_METHODS,
  live: LIVE_METHODS,
} as const satisfies { [K in keyof FaceControllers]: readonly (keyof FaceControllers[K])[] };

type Delegated<K extends keyof FaceControllers> = Pick<
  FaceControllers[K],
  Extract<(typeof DELEGATED)[K][number], keyof FaceControllers[K]>
>;

/**
 * A face on the page: what `createFace` resolves to (and a `<soft-face>` element's `face`). Its methods set the
 * expression, the view, the timeline, the eyes and the head, export what it shows, and edit its rig.
 */
// The methods the handle hands to its controllers (their documentation is on the controllers' methods). They are put
// on the class's prototype by its static block, from the same lists.
export interface FaceHandle
  extends Delegated<'skin'>,
    Delegated<'view'>,
    Delegated<'expression'>,
    Delegated<'timeline'>,
    Delegated<'eyes'>,
    Delegated<'export'>,
    Delegated<'head'>,
    Delegated<'editor'>,
    Delegated<'rig'>,
    Delegated<'live'> {}

/**
 * A face on the page, as scripts (and the tests) drive it: what `createFace` resolves to, and `window.face` in the
 * app. Vertices are simulation vertex indices, the order of `getSkin().rest`. Its methods are answered by one
 * controller per concern (skin, view, expression, timeline, eyes, export, head, editor, rig); the handle itself
 * keeps the face's life: `ready`, `onChange`, `dispose`.
 */
export class FaceHandle {
  /** Resolves once the head is shown and its skin solver runs; rejects if it fails to start. */
  readonly ready: Promise<void>;

  static {
    for (const [part, names] of Object.entries(DELEGATED) as [keyof FaceControllers, readonly string[]][]) {
      for (const name of names) {
        Object.defineProperty(FaceHandle.prototype, name, {
          configurable: true,
          writable: true,
          value: function delegated(this: FaceHandle, ...args: unknown[]): unknown {
            const controller = this.controllers[part] as unknown as Record<string, (...a: unknown[]) => unknown>;
            return controller[name](...args);
          },
        });
      }
    }
  }

  /**
   * `ready` is the face's start; `teardown` stops and frees everything the face is made of, and `dispose` calls it once.
   * @internal the face's own wiring, left out of the library's type declarations
   */
  constructor(
    private readonly parts: FaceParts,
    private readonly controllers: FaceControllers,
    ready: Promise<void>,
    private readonly teardown: () => void = () => {},
  ) {
    this.ready = ready;
    // The page reports a failed start itself; this keeps an unobserved rejection from being logged a second time.
    this.ready.catch(() => {});
  }

  /** Calls `listener` after every change made through the handle; returns the function that stops it. */
  onChange(listener: FaceChangeListener): () => void {
    return this.parts.listen(listener);
  }

  /**
   * Stops the face: its solver (and worker), render loop, panels and listeners end, its canvas and panels leave the
   * page and its GPU resources are freed. The other methods throw from then on; a second call does nothing.
   */
  dispose(): void {
    if (this.parts.disposed) return;
    this.parts.dispose();
    this.teardown();
  }

  /** Whether `dispose` was called. */
  isDisposed(): boolean {
    return this.parts.disposed;
  }
}
