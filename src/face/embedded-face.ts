import { RigDocument } from '../core/rig/rig-document';
import type { Rig } from '../core/rig/rig-types';
import { HEAD_NODES } from '../core/head/head-nodes';
import { headColliders } from '../render/head-colliders';
import { DEFAULT_LANDMARKS } from '../core/head/landmarks';
import { disposeHead, fetchModel, type HeadModel } from '../render/head-model';
import { HeadView } from '../render/head-view';
import { MuscleView } from '../render/muscle-view';
import { HairView } from '../render/hair-view';
import { MouthShade } from '../render/mouth-shade';
import { SkinView } from '../render/skin-view';
import { HeadExporter } from '../render/gltf-export';
import { SkinSimulation } from '../sim/main/skin-simulation';
import { readIdentity } from '../core/head/identity';
import { agedSkin } from '../core/head/identity-skin';
import { SKIN_DEFAULTS } from '../core/solver/skin-parameters';
import { EyeDriver } from './eye-driver';
import { TimelinePlayer } from './timeline-player';
import { VideoRecorder } from './video-recorder';
import { FaceEditor } from './face-editor';
import { RigAutosave } from './rig-autosave';
import { RigBinding } from './rig-binding';
import { readExpression } from './expression-hash';
import { facsIntensities } from '../core/expression/facs-code';
import { FaceExpression } from './face-expression';
import { createControllers, FaceHandle, type FaceControllers } from './face-handle';
import { FaceParts } from './face-parts';
import { describeShownHead, prepareHead, type HeadDescription, type PreparedHead } from './head-loader';
import type { HeadStore } from './head-store';
import { HeadSwitch } from './head-switch';
import { checkFaceOption, checkFaceOptions, solverMode, viewBackground, type FaceOptions } from './face-options';
import { rigName } from './face-assets';
import { headFrom, startLoading, type FaceLoads } from './face-loads';
import { jawHinge, jawTurner } from './jaw-turner';
import { HeadTurner } from './head-turner';
import { findNeck } from '../core/rig/neck-carry';
import { PanelSlot } from './panel-slot';
import { takeBack } from './take-back';

/**
 * One face in a container: its element (canvas and panels), view, head, solver, muscles, eyes and handle, built
 * together and torn down together. `createFace` hands out its handle; `<soft-face>` also switches its panels and
 * background.
 */
export class EmbeddedFace {
  readonly handle: FaceHandle;
  /** The parts the handle's controllers reach, connected here as the face is built and its head swapped. */
  private readonly parts = new FaceParts();
  private readonly controllers: FaceControllers;
  private started!: () => void;
  private failed!: (error: Error) => void;
  /** The face's own element in the container; the canvas and the panels are in it. */
  readonly element: HTMLDivElement;
  private readonly view: HeadView;
  /** How to take back each part built so far, run last first by `dispose`. */
  private readonly undo: (() => void)[] = [];
  /** The panels (src/ui/Panels), imported when first shown: the library's entry imports nothing from src/ui/. */
  private readonly panels = new PanelSlot(async () => {
    const { Panels } = await import('../ui/panels');
    const o = this.options;
    return () =>
      new Panels(this.handle, { container: this.element, frames: this.view, resolution: o.resolution, onResolution: o.onResolution });
  });
  private background: string;
  private disposed = false;
  /** How to take back the shown head and what runs it (solver, glyphs, editor, eyes), last first. */
  private mounted: (() => void)[] = [];
  private expression: FaceExpression | undefined;
  /** The face's own rig, made on the default head: a loaded head gets it carried over. */
  private original!: Rig;
  private modelUrl = '';
  private partsUrl = '';
  private rigKey: string | undefined;
  private headStore: HeadStore | undefined;
  /** Whether the head shown has a person's aged skin parameters (see mount). */
  private agedSkinShown = false;
  /** Which head is shown, and the changes to it (loaded heads, people, the default head, the landmark guide). */
  private readonly heads: HeadSwitch;
  private head!: HeadDescription;
  private shownHead: HeadModel | undefined;

  private constructor(
    container: HTMLElement,
    private readonly options: Required<FaceOptions>,
  ) {
    const ready = new Promise<void>((resolve, reject) => {
      this.started = resolve;
      this.failed = reject;
    });
    this.controllers = createControllers(this.parts, ready);
    this.handle = new FaceHandle(this.parts, this.controllers, ready, () => this.dispose());
    this.element = container.ownerDocument.createElement('div');
    this.element.className = 'softface';
    // Through the style object, not a style attribute, so that a content security policy without 'unsafe-inline'
    // styles allows it. The canvas fills the element; the panels are placed over its corner.
    Object.assign(this.element.style, { position: 'relative', width: '100%', height: '100%', overflow: 'hidden' });
    container.append(this.element);
    this.view = new HeadView(this.element, {
      background: viewBackground(options.background),
      motionResolution: options.motionResolution,
      slowDrawMs: options.slowDrawMs,
      antialias: options.antialias,
    });
    Object.assign(this.view.renderer.domElement.style, { display: 'block', width: '100%', height: '100%' });
    this.parts.view = this.view;
    this.heads = new HeadSwitch({
      options,
      view: this.view,
      original: () => this.original,
      modelUrl: () => this.modelUrl,
      partsUrl: () => this.partsUrl,
      headStore: () => this.headStore,
      shownHead: () => this.shownHead,
      describeHead: () => this.describeHead(),
      mount: (head, prepared, how) => this.mount(head, prepared, how),
      emit: (change) => this.parts.emit(change),
      stopEditing: () => this.handle.setEditor(false),
      alive: () => this.alive(),
      disposed: () => this.disposed,
    });
    this.parts.heads = this.heads;
    this.parts.shell = this;
    this.background = options.background;
    // One player for the face's life: a timeline keeps playing across a head change.
    const player = new TimelinePlayer(
      {
        applyFrame: (ids, values, presets, weights) => this.controllers.expression.applyFrame(ids, values, presets, weights),
        clockMoved: () => this.parts.emit('timeline'),
      },
      this.view,
    );
    this.parts.player = player;
    this.undo.push(() => player.dispose());
    this.view.start();
  }

  /**
   * Builds a face in `container` and resolves once its head is shown and its solver runs. Bad options reject, naming
   * the option, before anything is built; a failed or aborted start takes back whatever it had built.
   */
  static async create(container: HTMLElement, options?: FaceOptions, signal?: AbortSignal): Promise<EmbeddedFace> {
    if (container?.nodeType !== 1) throw new Error(`createFace: needs a container element, got ${String(container)}`);
    const o = checkFaceOptions(options);
    signal?.throwIfAborted();
    // Before the view: making it (its WebGL context, the first draw's setup) held a start's page for about half a second
    // in a profile in software WebGL; the downloads go on meanwhile.
    const loads = startLoading(o);
    const face = new EmbeddedFace(container, o);
    try {
      await face.build(loads, signal);
    } catch (error) {
      loads.release();
      face.failed(error as Error);
      face.dispose();
      throw error;
    }
    return face;
  }

  /** Shows or removes the face's panels; resolves once they are shown or gone (see FaceHandle.setPanels). */
  async setPanels(on: boolean): Promise<void> {
    checkFaceOption('panels', on, 'setPanels');
    this.alive();
    return this.panels.set(on);
  }

  /** Whether the face shows its panels. */
  hasPanels(): boolean {
    return this.panels.shown();
  }

  /** Changes the background: a colour `"#rrggbb"` or `"transparent"`; a bad value throws naming it. */
  setBackground(background: string): void {
    checkFaceOption('background', background, 'setBackground');
    this.alive();
    this.view.setBackground(viewBackground(background));
    this.background = background;
  }

  /** The background: `"#rrggbb"` or `"transparent"`. */
  getBackground(): string {
    return this.background;
  }

  /** Stops and frees everything the face is made of and removes its element; a second call does nothing. */
  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.failed(new Error('the face was disposed before it was ready'));
    this.handle.dispose();
    this.panels.dispose();
    try {
      takeBack([() => this.view.dispose(), ...this.undo, () => this.unmount(), () => this.heads.dispose()]);
    } finally {
      this.undo.length = 0;
      this.element.remove();
    }
  }

  private async build(loads: FaceLoads, signal: AbortSignal | undefined): Promise<void> {
    const o = this.options;
    this.parts.assetBase = o.assetBase;
    this.modelUrl = loads.modelUrl;
    this.partsUrl = loads.partsUrl;
    this.rigKey = loads.rigKey;
    this.headStore = loads.headStore;
    const original = await loads.rig;
    signal?.throwIfAborted();
    this.original = original;
    // A head loaded on an earlier visit comes back, with its landmarks, so that its rig is the same.
    let prepared: PreparedHead | undefined;
    const stored = await loads.stored;
    signal?.throwIfAborted();
    if (stored) {
      try {
        const options = { ...stored.options, landmarks: stored.landmarks };
        prepared = await prepareHead(stored.files, options, this.partsUrl, original, options.resolution ?? o.resolution);
      } catch (error) {
        console.warn(`the head kept from an earlier visit was not used: ${(error as Error).message}`);
      }
      signal?.throwIfAborted();
    }
    // A person asked for by the options is shown in place of the default head or a kept one.
    const named = o.model === null ? readIdentity(o.identity, 'createFace: identity') : null;
    if (named) {
      prepared = await this.heads.identityHead(named);
      signal?.throwIfAborted();
    }
    let head: HeadModel;
    // A kept head that could not be used falls back to the model, fetched only then.
    if (prepared) head = prepared.head;
    else head = (await loads.takeModel()) ?? (await headFrom(fetchModel(this.modelUrl), this.modelUrl));
    signal?.throwIfAborted();
    const lighting = await loads.environment;
    if (lighting) this.view.setEnvironment(lighting);
    await this.mount(head, prepared, { signal });

    const given = readExpression(o.expression, 'createFace: expression');
    const start = { actionUnits: { ...facsIntensities(o.facs, 'createFace: facs'), ...given.actionUnits }, presets: given.presets };
    if (Object.keys(start.actionUnits).length + Object.keys(start.presets).length > 0)
      this.expression!.set(start, 'createFace: expression');
    if (Object.keys(o.light).length > 0) this.handle.setLight(o.light);
    if (Object.keys(o.appearance).length > 0) this.handle.setAppearance(o.appearance);
    if (o.eyeSimulation) this.handle.setEyeSimulation(true);
    if (o.panels) await this.setPanels(true);
  }

  /** What the face shows now: the default head or a loaded one. */
  describeHead(): HeadDescription {
    return structuredClone(this.head);
  }

  /**
   * Shows `head` with its rig (the face's own for the default head, the carried-over one for a loaded head): the skin
   * solver for it is started first, and only then is the current head's machinery taken back, so a failure leaves
   * the current head as it was. The expression, the eye simulation and the editor's state carry over.
   */
  private async mount(head: HeadModel, prepared: PreparedHead | undefined, how: MountOptions): Promise<void> {
    const { started = 0, signal, fresh = false } = how;
    const o = this.options;
    const original = prepared?.rig ?? this.original;
    const own: (() => void)[] = [];
    // A person's skin ages (its fold spacing, elasticity and resting pull); the default head's does not.
    const aged = prepared?.identity ? agedSkin(prepared.identity.identity.age) : undefined;
    let skinView: SkinView;
    let simulation: SkinSimulation;
    let rig = original;
    let autosave: RigAutosave | undefined;
    try {
      // Before the first render: the skin's attributes become dynamic.
      skinView = new SkinView(head.skin);
      // Brows and lashes, placed from the eye corners on the skin at rest (the lashes' roots clear of the eyeballs),
      // ride every frame the skin shows.
      const colliders = headColliders(head);
      const eyes = colliders
        .filter((c) => (HEAD_NODES.eyes as readonly string[]).includes(c.name))
        .map((c) => ({ centre: c.a, radius: c.radius }));
      const landmarks = prepared?.landmarks ?? DEFAULT_LANDMARKS;
      head.hair = new HairView(head.skin, landmarks, eyes);
      // An edited rig kept from an earlier visit replaces the original, which "revert to default" brings back.
      if (this.rigKey) {
        // An identity's edited rig is kept under its own name, a loaded head's in the loaded head's slot.
        const key = prepared?.identity
          ? `${this.rigKey}:identity:${prepared.identity.name}`
          : prepared && this.headStore
            ? this.headStore.rigKey
            : this.rigKey;
        autosave = new RigAutosave(key, original);
        // A head just loaded starts from its carried-over rig; one kept from an earlier visit from its edited rig.
        if (fresh) await autosave.clear();
        else rig = (await autosave.load()) ?? original;
        signal?.throwIfAborted();
      }
      simulation = await SkinSimulation.create({
        mode: solverMode(o.solver),
        workers: o.workers,
        renderPositions: head.skin.geometry.getAttribute('position').array as Float32Array,
        indices: head.skin.geometry.index!.array as Uint16Array | Uint32Array,
        colliders,
        mouth: { left: landmarks['mouth-l'], right: landmarks['mouth-r'] },
        muscles: rig.muscles,
        parameters: aged?.parameters,
      });
    } catch (error) {
      autosave?.dispose();
      disposeHead(head);
      throw error;
    }
    own.push(() => simulation.dispose());
    // From here on nothing waits: the current head goes and the new one takes its place in one step.
    const carried = this.expression ? this.controllers.head.carried() : undefined;
    // The camera stays where it was relative to the framing: another person is seen from the same place.
    const camera = this.shownHead ? this.view.cameraOptions() : undefined;
    this.unmount();
    this.view.setHead(head);
    if (camera) this.view.setCamera(camera);
    this.shownHead = head;
    own.push(() => {
      this.view.removeHead(head);
      disposeHead(head);
    });
    const geometry = head.skin.geometry;
    // The skin at rest, render order: the vertex brush stores what it paints at rest, the glTF export writes it.
    const restRender = (geometry.getAttribute('position').array as Float32Array).slice();
    const restNormals = (geometry.getAttribute('normal').array as Float32Array).slice();
    // Made before the first frame moves the skin, and while the jaw and eyes are still at rest.
    const exporter = new HeadExporter(head, restRender, restNormals);
    skinView.connect(simulation);
    const hair = head.hair;
    if (hair) own.push(skinView.follow(hair));
    // The teeth, gums and tongue are lit through the lips' opening.
    const landmarks = prepared?.landmarks ?? DEFAULT_LANDMARKS;
    const parts = head.tongue ? [...head.teeth, head.tongue] : head.teeth;
    const mouth = new MouthShade(head.skin, landmarks['mouth-l'], landmarks['mouth-r'], parts);
    own.push(skinView.follow(mouth), () => mouth.dispose());
    own.push(
      this.view.onFrame(() => {
        simulation.advance();
        if (skinView.update()) return simulation.moving() ? 'solving' : true;
        if (simulation.awaitsAnswer()) return 'hold';
        return simulation.moving() ? 'moving' : false;
      }),
    );
    // Whatever the handle changes (expression, jaw, glyphs, editor, light, head) is drawn.
    own.push(this.handle.onChange(this.view.invalidate));

    // The rig is in the model's frame, which the solver treats as the skin's own: the glyphs take the skin's transform.
    head.root.updateMatrixWorld(true);
    const muscles = new MuscleView(rig.muscles, head.skin.matrixWorld);
    this.view.scene.add(muscles.group);
    own.push(() => muscles.dispose());
    // The jaw node's rest pose and the loaded rig's hinge, taken once: an edited jaw muscle turns it from there.
    const jawRest = head.jaw
      ? { quaternion: head.jaw.quaternion.clone(), position: head.jaw.position.clone(), hinge: jawHinge(rig) }
      : undefined;
    let jaw = jawTurner(head, rig, jawRest);
    // The head positions turn the whole head about the neck's pivot, and the solver carries the neck under it.
    const neck = findNeck(simulation.rest, simulation.triangles);
    const turner = new HeadTurner(head.root, head.skin, neck?.pivot ?? null);
    turner.follow((frame) => muscles.setFrame(frame));
    const expression = new FaceExpression(
      rig,
      (contractions) => {
        simulation.setContractions(contractions);
        jaw?.(contractions);
        muscles.setContractions(contractions);
      },
      (pose) => {
        simulation.setHeadPose(pose);
        turner.set(pose);
      },
    );
    this.expression = expression;
    const document = new RigDocument(rig);
    const binding = new RigBinding(document, {
      simulation,
      muscles,
      expression,
      jawChanged: (edited) => {
        if (head.jaw && jawRest) {
          head.jaw.quaternion.copy(jawRest.quaternion);
          head.jaw.position.copy(jawRest.position);
        }
        jaw = jawTurner(head, edited, jawRest);
      },
    });
    own.push(() => binding.dispose());
    this.parts.simulation = simulation;
    this.parts.expression = expression;
    this.started();
    this.parts.gltfWriter = exporter;
    this.parts.muscles = muscles;
    this.controllers.editor.showMuscles();
    // After the binding: listeners of the handle's 'rig' change see a face that already shows the edit.
    const name = prepared?.identity?.name ?? (prepared ? prepared.files[0].name.replace(/\.(glb|gltf|obj)$/i, '') : rigName(o.rig));
    this.controllers.editor.attachRig(document, original, name);
    if (autosave) {
      const saver = autosave;
      saver.watch(document);
      saver.onStatus = this.controllers.editor.attachAutosave(() => saver.status);
      // A reload right after an edit would otherwise lose it.
      const leave = (): void => saver.flush();
      window.addEventListener('pagehide', leave);
      own.push(() => {
        window.removeEventListener('pagehide', leave);
        saver.dispose();
      });
    }
    const editor = new FaceEditor(this.handle, this.view, muscles, document, () => this.handle.getMirrorEdits(), head.skin, restRender);
    own.push(() => editor.dispose());
    this.controllers.editor.session.attachView(editor);
    // Seeded from the clock and a random number: every face blinks differently, even two made in the same
    // millisecond; the state machine takes a seed for its tests.
    const eyes = new EyeDriver(this.handle, this.view, head.eyes, (id) => expression.effectiveOf(id), {
      simulation: { seed: (Date.now() ^ (Math.random() * 0x7fffffff)) >>> 0 },
    });
    own.push(() => eyes.dispose());
    this.parts.eyes = eyes;
    this.parts.recorder = new VideoRecorder({ handle: this.handle, simulation, view: this.view, skin: skinView, eyes });
    this.mounted = own;
    this.head = describeShownHead(prepared, {
      level: o.resolution,
      file: this.modelUrl.split('/').pop() ?? '',
      vertices: simulation.stats().vertices,
      triangles: geometry.index!.count / 3,
      loadMs: started > 0 ? Math.round(performance.now() - started) : 0,
    });
    if (carried) this.controllers.head.restore(carried);
    // The skin's age-given parameters over what was carried; back to the defaults after a person's head.
    if (aged) simulation.setParameters(aged.parameters);
    else if (this.agedSkinShown)
      simulation.setParameters({
        wrinkleSpacing: SKIN_DEFAULTS.wrinkleSpacing,
        positionStiffness: SKIN_DEFAULTS.positionStiffness,
        pretension: SKIN_DEFAULTS.pretension,
      });
    this.agedSkinShown = aged !== undefined;
    if (aged) expression.setResting(aged.tone);
    this.parts.emit('head');
  }

  /** Takes back the shown head's solver, glyphs, editor, eyes and autosave (the view and panels stay). */
  private unmount(): void {
    const steps = this.mounted;
    this.mounted = [];
    takeBack(steps);
  }

  private alive(): void {
    if (this.disposed) throw new Error('the face was disposed');
  }
}

/** How a head is shown: when its load started (for `loadMs`), what may abort it, and whether it was loaded just now. */
interface MountOptions {
  started?: number;
  signal?: AbortSignal;
  /** A head loaded now: its rig starts as carried over (an edited rig kept for an earlier loaded head is dropped). */
  fresh?: boolean;
}
