import type { SkinParameters } from '../core/solver/skin-parameters';
import type { AppearanceOptions, LightOptions, RenderOptions } from '../render/view-options';
import type { Face } from './create-face';
import { ATTRIBUTE_DEFAULTS, FACE_ATTRIBUTES, readAttributes, type FaceAttribute, type FaceAttributeValues } from './element-attributes';
import { EmbeddedFace } from '../face/embedded-face';
import { expressionEntries, type HashExpression } from '../face/expression-hash';
import { checkExpression } from '../face/face-expression';
import type { FaceChange, MuscleDisplay } from '../face/face-handle';

/** What a `change` event's detail says: what the handle changed, or which shown part the attributes switched. */
export interface SoftFaceChangeDetail {
  /** What changed: a `FaceChange` the face's handle reported, or `panels` or `background` set by an attribute. */
  change: FaceChange | 'panels' | 'background';
}

/** What a face had that its attributes do not say, carried over when a new resolution or solver rebuilds it. */
interface CarriedState {
  expression: Record<string, number>;
  light: LightOptions;
  render: RenderOptions;
  appearance: AppearanceOptions;
  muscles: MuscleDisplay;
  skin: SkinParameters;
  eyeSimulation: boolean;
}

/**
 * `<soft-face>`: a face in the page's markup. Its attributes (`resolution`, `expression`, `facs`, `preset`, `solver`,
 * `panels`, `eye-simulation`, `background`, `identity`) apply live; `face` is the handle once `ready` has fired (again after a
 * new resolution or solver rebuilt it, keeping what the face had); `change` tells what changed (`detail.change`);
 * `error` tells of a bad attribute value (the face keeps its last good one) or a face that could not start.
 * Removing the element disposes its face.
 */
export class SoftFaceElement extends HTMLElement {
  /**
   * The attributes whose changes the element applies live (the browser reports them to `attributeChangedCallback`):
   * `resolution`, `expression`, `facs`, `preset`, `solver`, `panels`, `eye-simulation`, `background`, `identity`.
   */
  static readonly observedAttributes: readonly string[] = FACE_ATTRIBUTES;
  private embedded: EmbeddedFace | undefined;
  /** Aborts the build under way, if any. */
  private building: AbortController | undefined;
  /** The attributes' last good values: what the face shows, or will once built. */
  private values: FaceAttributeValues = ATTRIBUTE_DEFAULTS;
  private stopChanges: (() => void) | undefined;

  /** The face's handle, once `ready` has fired; undefined while it is being built and once the element is removed. */
  get face(): Face | undefined {
    return this.embedded?.handle;
  }

  /** Starts building the face the attributes ask for, unless it has one or is building it already. */
  connectedCallback(): void {
    if (!this.embedded && !this.building) this.build(undefined);
  }

  /** Disposes the face (or stops its build) unless the element is back in the page at once, as when it is moved. */
  disconnectedCallback(): void {
    // An element moved elsewhere in the page is disconnected and connected again at once: it keeps its face.
    queueMicrotask(() => {
      if (!this.isConnected) this.stop();
    });
  }

  /**
   * Applies a changed attribute to the face: `resolution` and `solver` rebuild it, keeping what it had; the others
   * change it in place (or when it is built). A bad value fires `error` and the face keeps its last good one.
   */
  attributeChangedCallback(name: string, old: string | null, value: string | null): void {
    if (old === value) return;
    const attribute = name as FaceAttribute;
    let next: FaceAttributeValues;
    try {
      next = readAttributes((a) => this.getAttribute(a), this.values, attribute);
      if (this.embedded && (attribute === 'expression' || attribute === 'preset')) this.checkExpressions(next);
    } catch (error) {
      this.report(error as Error);
      return;
    }
    const before = this.values;
    this.values = next;
    if (!this.isConnected) return;
    if (attribute === 'resolution' || attribute === 'solver') {
      // Also after a face that could not start: the new value may be the one that works.
      if (next[attribute] !== before[attribute]) this.rebuild();
      return;
    }
    const face = this.embedded;
    if (!face) return; // applied once the face is built
    if (attribute === 'expression' || attribute === 'preset' || attribute === 'facs') face.handle.setExpression(this.expression());
    else if (attribute === 'eye-simulation') face.handle.setEyeSimulation(next.eyeSimulation);
    else if (attribute === 'panels') {
      face.handle.setPanels(next.panels).then(
        () => this.changed('panels'),
        (error: Error) => this.report(error),
      );
    } else if (attribute === 'background') {
      face.handle.setBackground(next.background);
      this.changed('background');
    } else if (attribute === 'identity') {
      // The face says 'head' once the person is shown.
      face.handle.setIdentity(next.identity).catch((error: Error) => this.report(error));
    }
  }

  /** Builds the face the attributes ask for, carrying `carried` over from a face it replaces. */
  private build(carried: CarriedState | undefined): void {
    const building = new AbortController();
    this.building = building;
    const v = this.values;
    const options = {
      resolution: v.resolution,
      solver: v.solver,
      background: v.background,
      panels: v.panels,
      identity: v.identity,
      ...(carried
        ? { expression: carried.expression, light: carried.light, appearance: carried.appearance, eyeSimulation: carried.eyeSimulation }
        : {}),
    };
    EmbeddedFace.create(this, options, building.signal).then(
      (face) => {
        if (this.building !== building) return face.dispose();
        this.building = undefined;
        this.embedded = face;
        // The panels' own inputs fire native change events; they stay inside, so that `change` is only ever ours.
        face.element.addEventListener('change', (event) => event.stopPropagation());
        if (carried) {
          face.handle.setRenderOptions(carried.render);
          face.handle.setMuscleDisplay(carried.muscles);
          face.handle.setSkinParameters(carried.skin);
        } else this.applyAttributes(face);
        // Shown by the build; an attribute changed meanwhile has the last word.
        if (this.values.panels !== v.panels) face.handle.setPanels(this.values.panels).catch((error: Error) => this.report(error));
        this.stopChanges = face.handle.onChange((change) => this.changed(change));
        this.dispatchEvent(new Event('ready'));
      },
      (error: Error) => {
        if (this.building !== building) return;
        this.building = undefined;
        if (error.name !== 'AbortError') this.report(new Error(`<soft-face>: the face could not start: ${error.message}`), 'error');
      },
    );
  }

  /**
   * The attributes that apply to a built face: the expression, presets and the eye simulation. An expression or
   * preset attribute the rig does not know is reported and left out, as if it were absent.
   */
  private applyAttributes(face: EmbeddedFace): void {
    const presets = face.handle.listPresets().map((p) => p.name);
    for (const attribute of ['expression', 'preset'] as const) {
      try {
        checkExpression(this.values[attribute], presets, `<soft-face> ${attribute}`);
      } catch (error) {
        this.report(error as Error);
        this.values = { ...this.values, [attribute]: ATTRIBUTE_DEFAULTS[attribute] };
      }
    }
    const expression = this.expression();
    if (Object.keys(expression).length > 0) face.handle.setExpression(expression);
    if (this.values.eyeSimulation) face.handle.setEyeSimulation(true);
  }

  /** Replaces the face by one of the resolution and solver asked for, with what the old one had. */
  private rebuild(): void {
    const old = this.embedded;
    const carried = old ? carry(old.handle) : undefined;
    this.stop();
    this.build(carried);
  }

  /** Ends the face, or its build. */
  private stop(): void {
    this.building?.abort();
    this.building = undefined;
    this.stopChanges?.();
    this.stopChanges = undefined;
    this.embedded?.dispose();
    this.embedded = undefined;
  }

  /** Checks the expression and preset attributes' ids and names against the face's rig, naming the attribute. */
  private checkExpressions(values: FaceAttributeValues): void {
    const presets = this.embedded!.handle.listPresets().map((p) => p.name);
    checkExpression(values.expression, presets, '<soft-face> expression');
    checkExpression(values.preset, presets, '<soft-face> preset');
  }

  /** The facs attribute's units, the expression attribute over them and the preset attribute's weights, as entries. */
  private expression(): Record<string, number> {
    const e: HashExpression = {
      actionUnits: { ...this.values.facs, ...this.values.expression.actionUnits },
      presets: { ...this.values.expression.presets, ...this.values.preset.presets },
    };
    return expressionEntries(e);
  }

  private changed(change: SoftFaceChangeDetail['change']): void {
    this.dispatchEvent(new CustomEvent<SoftFaceChangeDetail>('change', { detail: { change } }));
  }

  /**
   * Fires `error`; unless a listener calls `preventDefault()`, the message also goes to the console: a warning for a
   * bad attribute (the face goes on), an error for a face that could not start.
   */
  private report(error: Error, level: 'warn' | 'error' = 'warn'): void {
    const event = new ErrorEvent('error', { message: error.message, error, cancelable: true });
    if (this.dispatchEvent(event)) console[level](error.message);
  }
}

function carry(face: Face): CarriedState {
  const presets = Object.fromEntries(face.listPresets().map((p) => [p.name, p.weight]));
  return {
    expression: expressionEntries({ actionUnits: face.getActionUnits(), presets }),
    light: face.getLight(),
    render: face.getRenderOptions(),
    appearance: face.getAppearance(),
    muscles: face.getMuscleDisplay(),
    skin: face.getSkinParameters(),
    eyeSimulation: face.getEyeSimulation(),
  };
}

declare global {
  interface HTMLElementTagNameMap {
    'soft-face': SoftFaceElement;
  }
}
