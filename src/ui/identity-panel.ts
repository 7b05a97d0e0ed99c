import type GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import { IDENTITY_DEFAULTS, type Identity } from '../core/head/identity';
import type { FaceChange, FaceHandle } from '../face/face-handle';
import { note } from './note';

/** The menu's entry for the default head. */
const DEFAULT_HEAD = '(default head)';
/** The menu's entry while the sliders describe a person of no stock name. */
const CUSTOM = '(custom)';

/**
 * The Identity folder: a person's sex, age and ancestry as sliders, and the stock identities by name. A slider let
 * go, or a name picked, builds that person's head (a second or two; the line under the menu says so) in place of the
 * current one, with the expression kept; "default head" goes back.
 */
export class IdentityPanel {
  readonly folder: GUI;
  private readonly state = {
    stock: DEFAULT_HEAD,
    sex: IDENTITY_DEFAULTS.sex,
    age: IDENTITY_DEFAULTS.age,
    african: IDENTITY_DEFAULTS.ancestry.african,
    asian: IDENTITY_DEFAULTS.ancestry.asian,
    european: IDENTITY_DEFAULTS.ancestry.european,
  };
  private readonly stock: Controller;
  private readonly sliders: Controller[];
  private readonly message: HTMLDivElement;
  private readonly unsubscribe: () => void;
  /** The request last made: an answer to an older one does not overwrite the message. */
  private asked = 0;

  constructor(
    parent: GUI,
    private readonly face: FaceHandle,
  ) {
    this.folder = parent.addFolder('Identity');
    const names = [DEFAULT_HEAD, ...face.listIdentities().map((i) => i.name), CUSTOM];
    this.stock = this.folder
      .add(this.state, 'stock', names)
      .name('person')
      .onChange((name: string) => this.pick(name));
    this.stock.domElement.dataset.control = 'identity-stock';
    const slider = (key: keyof Omit<typeof this.state, 'stock'>, min: number, max: number, step: number, label: string): Controller => {
      const c = this.folder
        .add(this.state, key, min, max, step)
        .name(label)
        .onFinishChange(() => this.build());
      c.domElement.dataset.control = `identity-${key}`;
      return c;
    };
    this.sliders = [
      slider('sex', 0, 1, 0.01, 'sex (0 female, 1 male)'),
      slider('age', 1, 90, 1, 'age (years)'),
      slider('african', 0, 1, 0.01, 'african'),
      slider('asian', 0, 1, 0.01, 'asian'),
      slider('european', 0, 1, 0.01, 'european'),
    ];
    this.message = note('identity-message', { opacity: '0.85' });
    this.folder.$children.append(this.message);
    this.refresh();
    this.unsubscribe = face.onChange((change: FaceChange) => {
      if (change === 'head') this.refresh();
    });
  }

  dispose(): void {
    this.unsubscribe();
    this.folder.destroy();
  }

  /** Shows the face's person in the controls. */
  private refresh(): void {
    const head = this.face.describeHead();
    const identity = head.identity;
    if (identity) {
      Object.assign(this.state, { sex: identity.sex, age: identity.age, ...identity.ancestry });
      this.state.stock = this.face.listIdentities().some((i) => i.name === head.name) ? head.name : CUSTOM;
    } else this.state.stock = DEFAULT_HEAD;
    this.stock.updateDisplay();
    for (const c of this.sliders) c.updateDisplay();
  }

  private pick(name: string): void {
    if (name === CUSTOM) return;
    void this.show(name === DEFAULT_HEAD ? null : name, name);
  }

  private build(): void {
    const s = this.state;
    const identity: Identity = { sex: s.sex, age: s.age, ancestry: { african: s.african, asian: s.asian, european: s.european } };
    void this.show(identity, 'the person');
  }

  private async show(identity: Identity | string | null, what: string): Promise<void> {
    const ask = ++this.asked;
    this.message.style.color = '';
    this.message.textContent = `building ${what}…`;
    try {
      const head = await this.face.setIdentity(identity);
      if (ask === this.asked) this.message.textContent = identity === null ? '' : `${head.name} in ${(head.loadMs / 1000).toFixed(1)} s`;
    } catch (error) {
      if (ask !== this.asked) return;
      this.message.style.color = '#ff8a80';
      this.message.textContent = (error as Error).message;
      this.refresh();
    }
  }
}
