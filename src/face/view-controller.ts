import { checkNumber } from '../core/check';
import type { HairSnapshot } from '../render/hair-view';
import type { RenderTiming } from '../render/render-timing';
import type { MaterialDescription } from '../render/materials';
import type { AppearanceOptions, CameraOptions, LightOptions, RenderOptions } from '../render/view-options';
import type { Vec3 } from '../core/rig/rig-types';
import type { FaceParts } from './face-parts';

/** How the face is shown: light, camera, render options, hair, pictures, and its element's panels and background. */
export class ViewController {
  constructor(private readonly parts: FaceParts) {}

  /**
   * Shows or removes the face's panels. They load on first use (lil-gui with them), so a page that never shows them
   * never fetches them; resolves once they are shown or gone. A value that is not a boolean rejects, naming it.
   */
  async setPanels(on: boolean): Promise<void> {
    return this.parts.element().setPanels(on);
  }

  /** Whether the face shows its panels. */
  hasPanels(): boolean {
    return this.parts.element().hasPanels();
  }

  /** Changes the background: a colour `"#rrggbb"` or `"transparent"`; a bad value throws naming it, and nothing changes. */
  setBackground(background: string): void {
    this.parts.element().setBackground(background);
  }

  /** The background: `"#rrggbb"` or `"transparent"`. */
  getBackground(): string {
    return this.parts.element().getBackground();
  }

  /**
   * Changes some light options (`ambientIntensity`, `keyAzimuth` 0..360, `keyElevation` -90..90, `keyIntensity`,
   * `keyColor` "#rrggbb"); an unknown option or a value of the wrong type or range throws naming it and changes nothing.
   */
  setLight(partial: Partial<LightOptions>): void {
    this.parts.shown().setLight(partial);
    this.parts.emit('light');
  }

  /** The light options as last set. */
  getLight(): LightOptions {
    return this.parts.shown().lightOptions();
  }

  /**
   * Moves the camera relative to the head's framing from the front: `yaw` degrees round it (-180..180, 90 from the
   * subject's left), `pitch` degrees up (-80..80), `distance` as a multiple of the framing distance (0.2..5); bad input
   * throws naming it and changes nothing. The user's orbit drags move the same camera.
   */
  setCamera(partial: Partial<CameraOptions>): void {
    this.parts.shown().setCamera(partial);
    this.parts.emit('camera');
  }

  /** Where the camera is now (the user's orbit drags included). */
  getCamera(): CameraOptions {
    return this.parts.shown().cameraOptions();
  }

  /**
   * Where a point of the head (the skin's model space, metres, as `getSkin` gives them) is on the page, in client
   * pixels, as the camera sees it now (for overlays and tests); null before a head is shown.
   */
  locatePoint(point: Vec3): {
    /** Client pixels from the viewport's left edge, as `MouseEvent.clientX` counts them. */
    x: number;
    /** Client pixels from the viewport's top edge, as `MouseEvent.clientY` counts them. */
    y: number;
  } | null {
    return this.parts.shown().locate(point);
  }

  /** Changes some render options (`wireframe`, `showEyes`, `showTeeth`, booleans); bad input throws and changes nothing. */
  setRenderOptions(partial: Partial<RenderOptions>): void {
    this.parts.shown().setRenderOptions(partial);
    this.parts.emit('render');
  }

  /** The render options as last set. */
  getRenderOptions(): RenderOptions {
    return this.parts.shown().renderOptions();
  }

  /**
   * Changes how the face's hair looks: `brows` and `lashes` (booleans: off for a bare face), `browColor` and
   * `lashColor` (`#rrggbb`), `browDensity` (0..1, the share of brow hairs drawn); bad input throws and changes nothing.
   */
  setAppearance(partial: Partial<AppearanceOptions>): void {
    this.parts.shown().setAppearance(partial);
    this.parts.emit('appearance');
  }

  /** The appearance options as last set. */
  getAppearance(): AppearanceOptions {
    return this.parts.shown().appearanceOptions();
  }

  /**
   * The brows and lashes as drawn now: per kind, the drawn hairs' ribbon vertices (a hair's first two are its root)
   * and each hair's anchor (three skin vertices in simulation order, as `getSkin` gives them, and barycentric weights).
   */
  getHair(): HairSnapshot {
    const rest = this.parts.running().rest;
    const byPosition = new Map<string, number>();
    for (let v = rest.length / 3 - 1; v >= 0; v--) byPosition.set(`${rest[3 * v]},${rest[3 * v + 1]},${rest[3 * v + 2]}`, v);
    const hair = this.parts.shown().describeHair((x, y, z) => {
      const v = byPosition.get(`${Math.fround(x)},${Math.fround(y)},${Math.fround(z)}`);
      if (v === undefined) throw new Error(`getHair: no skin vertex at (${x}, ${y}, ${z})`);
      return v;
    });
    if (!hair) throw new Error('getHair: the head has no hair');
    return hair;
  }

  /** The head's materials as plain data: colours, roughness, sheen, textures, the subsurface look (read-only). */
  describeMaterials(): MaterialDescription[] {
    return this.parts.shown().describeMaterials();
  }

  /** Renders `frames` frames (default 100) back to back and reports their main-thread time (a benchmark: it blocks the page). */
  measureRender(frames = 100): RenderTiming {
    checkNumber('measureRender', 'frames', frames, [1, 10_000], true);
    return this.parts.shown().measureRender(frames);
  }

  /** A PNG of the canvas, rendered just before it is read. */
  savePNG(): Promise<Blob> {
    this.parts.eyes?.showGaze();
    return this.parts.shown().snapshot();
  }
}

/** The handle's methods that ViewController answers. */
export const VIEW_METHODS = [
  'setPanels',
  'hasPanels',
  'setBackground',
  'getBackground',
  'setLight',
  'getLight',
  'setCamera',
  'getCamera',
  'locatePoint',
  'setRenderOptions',
  'getRenderOptions',
  'setAppearance',
  'getAppearance',
  'getHair',
  'describeMaterials',
  'measureRender',
  'savePNG',
] as const;
