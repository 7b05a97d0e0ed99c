/** Something shown that can be taken back: the face's panels. */
interface Disposable {
  dispose(): void;
}

/**
 * Where a face's panels go: `load` imports their module on first use (so that a page that never shows them never
 * fetches them or lil-gui) and gives the function that makes them; they are taken back when switched off. A call
 * that comes while they load has the last word.
 */
export class PanelSlot {
  private panels: Disposable | undefined;
  private wanted = false;
  private disposed = false;

  constructor(private readonly load: () => Promise<() => Disposable>) {}

  /** Shows or removes the panels; resolves once they are shown or gone. */
  async set(on: boolean): Promise<void> {
    this.wanted = on;
    if (!on) {
      this.panels?.dispose();
      this.panels = undefined;
      return;
    }
    if (this.panels) return;
    const make = await this.load();
    // Switched off, disposed, or made by a later call while the module loaded.
    if (this.disposed || !this.wanted || this.panels) return;
    this.panels = make();
  }

  /** Whether the panels are shown. */
  shown(): boolean {
    return !!this.panels;
  }

  dispose(): void {
    this.disposed = true;
    this.panels?.dispose();
    this.panels = undefined;
  }
}
