import type GUI from 'lil-gui';
import { note } from './note';

/**
 * A folder's file import: a hidden file picker, optionally files dropped on an element, and the folder's message line,
 * where a refused change shows its message (and opens the folder). The panel says what the picked or dropped files
 * become, with `onFiles` (the files as they are) or `onText` (one file read as text, refusals shown).
 *
 * ```ts
 * const files = new FileImport(folder, 'import-file', 'editor-message', { color: '#ff8a80' })
 *   .accept('.json,application/json')
 *   .onText((text, file) => face.setRig(text, file.name), (file) => `imported ${file.name}`);
 * ```
 */
export class FileImport {
  /** The hidden picker, found by its `data-control` name. */
  readonly input: HTMLInputElement;
  /** The folder's message line, found by its `data-control` name. */
  readonly message: HTMLDivElement;
  /** File names the picker takes: its `accept` attribute is only a hint to the browser's dialog. */
  private names: RegExp | undefined;
  private take: (files: File[]) => void = () => undefined;
  private dropTarget: HTMLElement | undefined;
  private drops: (files: FileList) => boolean = () => false;

  /** Appends the picker (named `inputName`) and the message line (named `messageName`, styled with `style`) to the folder. */
  constructor(
    private readonly folder: GUI,
    inputName: string,
    messageName: string,
    style: Partial<CSSStyleDeclaration> = {},
  ) {
    this.input = document.createElement('input');
    Object.assign(this.input, { type: 'file', hidden: true });
    this.input.dataset.control = inputName;
    this.input.addEventListener('change', this.onChange);
    this.folder.$children.append(this.input);
    this.message = note(messageName, { ...style, whiteSpace: 'pre-wrap' });
    this.folder.$children.append(this.message);
  }

  /** What the picker offers (its `accept` attribute) and, with `names`, the only file names it passes on. */
  accept(types: string, names?: RegExp): this {
    this.input.accept = types;
    this.names = names;
    return this;
  }

  /** Lets the picker take several files at once. */
  multiple(on = true): this {
    this.input.multiple = on;
    return this;
  }

  /** Hands the picked (or dropped) files to `handle`; the picker calls it only with at least one file. */
  onFiles(handle: (files: File[]) => void): this {
    this.take = handle;
    return this;
  }

  /**
   * Reads the first picked (or dropped) file as text and hands it to `handle`: a refusal (a throw) shows its message
   * and changes nothing, success shows `done(file)`.
   */
  onText(handle: (text: string, file: File) => void, done: (file: File) => string): this {
    return this.onFiles((files) => void this.read(files[0], handle, done));
  }

  /** Takes files dropped on `target` too, when `accepts` says they are for this folder (other folders may share it). */
  dropOn(target: HTMLElement | undefined, accepts: (files: FileList) => boolean): this {
    this.removeDrop();
    this.dropTarget = target;
    this.drops = accepts;
    target?.addEventListener('dragover', this.onDragOver);
    target?.addEventListener('drop', this.onDrop);
    return this;
  }

  /** Opens the browser's file dialog. */
  pick(): void {
    this.input.click();
  }

  /** Runs a change; a refusal's message is shown and the folder opened. Returns whether it went through. */
  attempt(change: () => void): boolean {
    try {
      change();
      this.message.textContent = '';
      return true;
    } catch (error) {
      this.refused(error);
      return false;
    }
  }

  /** Shows a refusal's message and opens the folder, so it is seen. */
  refused(error: unknown): void {
    this.message.textContent = (error as Error).message;
    this.folder.open();
  }

  /** Removes the picker, the message line and every listener added. */
  dispose(): void {
    this.removeDrop();
    this.input.removeEventListener('change', this.onChange);
    this.input.remove();
    this.message.remove();
  }

  private async read(file: File, handle: (text: string, file: File) => void, done: (file: File) => string): Promise<void> {
    const text = await file.text();
    if (this.attempt(() => handle(text, file))) this.message.textContent = done(file);
  }

  private removeDrop(): void {
    this.dropTarget?.removeEventListener('dragover', this.onDragOver);
    this.dropTarget?.removeEventListener('drop', this.onDrop);
    this.dropTarget = undefined;
  }

  private readonly onChange = (): void => {
    const names = this.names;
    const picked = Array.from(this.input.files ?? []);
    const files = names ? picked.filter((f) => names.test(f.name)) : picked;
    // Emptied, so that picking the same file again is a change too.
    this.input.value = '';
    if (files.length > 0) this.take(files);
  };

  private readonly onDragOver = (event: DragEvent): void => {
    if (event.dataTransfer?.types.includes('Files')) event.preventDefault();
  };

  private readonly onDrop = (event: DragEvent): void => {
    const files = event.dataTransfer?.files;
    if (!files || !this.drops(files)) return;
    event.preventDefault();
    this.take(Array.from(files));
  };
}
