import type GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import type { FaceChange, FaceHandle } from '../face/face-handle';
import { FileImport } from './file-import';
import { note } from './note';

/** Files that make a head (or come with a `.gltf`): what the picker offers and what a drop is taken as. */
const HEAD_FILE = /\.(glb|gltf|obj|bin|png|jpe?g|webp|ktx2)$/i;
const HEAD_MAIN = /\.(glb|gltf|obj)$/i;

/** Whether dropped files are a head (a `.glb`, `.gltf` or `.obj` among them) rather than a rig. */
export function isHeadDrop(files: ArrayLike<File>): boolean {
  return Array.from(files).some((f) => HEAD_MAIN.test(f.name));
}

/**
 * The Head folder: the head shown (default or loaded, its size and load time), "load head" (a file picker; dropping
 * a `.glb`, `.gltf` with its files, or `.obj` on the face does the same) and "default head". A refused file's message
 * shows here and the current head stays; one refused because its landmarks were not found offers "place landmarks by
 * clicking", which shows its skin and asks for each missing landmark in turn ("click the left mouth corner").
 */
export class HeadPanel {
  readonly folder: GUI;
  private readonly state = {
    load: (): void => this.files.pick(),
    revert: (): void => void this.run('default head', () => this.face.revertHead()),
    guide: (): void => this.guide(),
    cancel: (): void => this.face.cancelLandmarkGuide(),
  };
  private readonly status: HTMLDivElement;
  /** Head files picked or dropped, and the message line. */
  private readonly files: FileImport;
  private readonly message: HTMLDivElement;
  private readonly revertButton: Controller;
  private readonly guideButton: Controller;
  private readonly cancelButton: Controller;
  /** The files of the last head refused for landmarks not found: "place landmarks" guides them. */
  private unplaced: File[] | undefined;
  private readonly unsubscribe: () => void;

  constructor(
    parent: GUI,
    private readonly face: FaceHandle,
    dropTarget?: HTMLElement,
  ) {
    this.folder = parent.addFolder('Head');
    this.status = note('head-status', { opacity: '0.85' });
    this.folder.$children.append(this.status);
    this.folder.add(this.state, 'load').name('load head (.glb, .gltf, .obj, or drop it)').domElement.dataset.control = 'load-head';
    this.revertButton = this.folder.add(this.state, 'revert').name('default head');
    this.revertButton.domElement.dataset.control = 'revert-head';
    this.guideButton = this.folder.add(this.state, 'guide').name('place landmarks by clicking');
    this.guideButton.domElement.dataset.control = 'guide-landmarks';
    this.cancelButton = this.folder.add(this.state, 'cancel').name('cancel placing landmarks');
    this.cancelButton.domElement.dataset.control = 'cancel-landmarks';
    this.files = new FileImport(this.folder, 'head-file', 'head-message')
      .accept('.glb,.gltf,.obj,.bin,image/*', HEAD_FILE)
      .multiple()
      .onFiles((files) => this.load(files))
      .dropOn(dropTarget, isHeadDrop);
    this.message = this.files.message;
    this.refresh();
    this.unsubscribe = face.onChange((change: FaceChange) => {
      if (change === 'head' || change === 'landmarks') this.refresh();
    });
  }

  dispose(): void {
    this.files.dispose();
    this.unsubscribe();
    this.folder.destroy();
  }

  private refresh(): void {
    const h = this.face.describeHead();
    this.status.textContent =
      h.source === 'default'
        ? `default head · ${h.vertices.toLocaleString('en-US')} vertices`
        : `${h.name} · ${h.vertices.toLocaleString('en-US')} vertices, ${h.triangles.toLocaleString('en-US')} triangles`;
    this.revertButton.show(h.source !== 'default');
    const guide = this.face.describeLandmarkGuide();
    this.guideButton.show(!guide && !!this.unplaced);
    this.cancelButton.show(!!guide);
    if (guide) {
      this.message.style.color = '#ffd54f';
      this.message.textContent = `${guide.file}: ${guide.prompt}`;
    }
  }

  /** Places the refused head's missing landmarks by clicking, then loads it. */
  private guide(): void {
    const files = this.unplaced;
    if (!files) return;
    this.unplaced = undefined;
    const main = files.find((f) => HEAD_MAIN.test(f.name)) ?? files[0];
    void this.run(main.name, async () => {
      const h = await this.face.guideLandmarks(files);
      this.message.textContent = `loaded ${h.name} with the landmarks placed`;
    });
  }

  /** Loads the files as a head; the outcome (or the refusal) is shown in the folder. */
  private load(files: File[]): void {
    const main = files.find((f) => HEAD_MAIN.test(f.name));
    this.unplaced = undefined;
    void this.run(main?.name ?? files[0].name, async () => {
      try {
        const h = await this.face.loadHead(files);
        this.message.textContent = `loaded ${h.name} in ${(h.loadMs / 1000).toFixed(1)} s (${h.units}, up ${h.up}, face ${h.forward})`;
      } catch (error) {
        // Landmarks not found: they can be placed by hand.
        if ((error as Error).name === 'MissingLandmarksError') this.unplaced = files;
        throw error;
      }
    });
  }

  private async run(what: string, step: () => Promise<unknown>): Promise<void> {
    this.message.style.color = '';
    this.message.textContent = `${what}…`;
    try {
      await step();
      if (this.message.textContent === `${what}…`) this.message.textContent = '';
    } catch (error) {
      this.message.style.color = '#ff8a80';
      this.files.refused(error);
    }
    this.refresh();
  }
}
