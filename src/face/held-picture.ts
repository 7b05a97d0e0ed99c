/**
 * Whether a recording's next picture would be the last one again: the solver solved no frame since (it sleeps), the
 * expression's effective intensities are the same, and nothing else the picture shows (light, camera, appearance,
 * options, head) changed. A held expression then costs the recorder no render: the sink repeats its last picture.
 */
export class HeldPicture {
  private frames = -1;
  private units: Float64Array = new Float64Array(0);
  private changed = true;

  /** Something besides the expression changed what the picture shows: the next one is drawn. */
  invalidate(): void {
    this.changed = true;
  }

  /**
   * Whether the picture for the solver's frame count `frames` and the effective intensities `units` (the same keys,
   * in the same order, each time) is the last one; remembers them either way.
   */
  same(frames: number, units: Readonly<Record<string, number>>): boolean {
    const values = Object.values(units);
    let same = !this.changed && frames === this.frames && values.length === this.units.length;
    if (this.units.length !== values.length) this.units = new Float64Array(values.length);
    for (let i = 0; i < values.length; i++) {
      if (this.units[i] !== values[i]) same = false;
      this.units[i] = values[i];
    }
    this.frames = frames;
    this.changed = false;
    return same;
  }
}
