/** The light and render options a view takes from scripts and panels, their defaults, ranges and checks. */

/** The view's lights: a hemisphere fill and a directional key light placed by two angles around the head. */
export interface LightOptions {
  /** Hemisphere (sky and ground fill) intensity. */
  ambientIntensity: number;
  /** Key light's horizontal angle in degrees, 0..360: 0 in front of the face, 90 from the subject's left (+x). */
  keyAzimuth: number;
  /** Key light's vertical angle in degrees: -90 from straight below, 0 level with the head's centre, 90 from above. */
  keyElevation: number;
  /** Key light's intensity (a three.js directional light's), 0..10. */
  keyIntensity: number;
  /** Key light colour, sRGB `#rrggbb`. */
  keyColor: string;
}

/** What the view shows, and how. */
export interface RenderOptions {
  /** Draw every mesh of the head as its triangle edges. */
  wireframe: boolean;
  /** Draw the eyeballs. */
  showEyes: boolean;
  /** Teeth and tongue. */
  showTeeth: boolean;
}

/**
 * The look the app had before the light became adjustable: the key light up and to the subject's left of the face
 * (its old fixed direction (0.55, 0.65, 1) is 28.8 degrees round and 29.7 up; whole degrees keep sliders tidy).
 */
export const LIGHT_DEFAULTS: Readonly<Required<LightOptions>> = Object.freeze({
  ambientIntensity: 0.3,
  keyAzimuth: 29,
  keyElevation: 30,
  keyIntensity: 2.4,
  keyColor: '#fff3e6',
});

/** Allowed range of each numeric light option (inclusive); panels use the same bounds for their sliders. */
export const LIGHT_RANGES: Readonly<
  Record<'ambientIntensity' | 'keyAzimuth' | 'keyElevation' | 'keyIntensity', readonly [number, number]>
> = Object.freeze({ ambientIntensity: [0, 3], keyAzimuth: [0, 360], keyElevation: [-90, 90], keyIntensity: [0, 10] });

/**
 * Where the camera looks from, relative to the framing the view chooses for a head (from the front, the whole head in
 * view): turned about the head's centre and moved nearer or farther. The user's orbit drag changes the same.
 */
export interface CameraOptions {
  /** Degrees round the head's vertical axis, -180..180: 90 looks from the subject's left (+x). */
  yaw: number;
  /** Degrees up (positive) or down, -80..80. */
  pitch: number;
  /** Distance from the head's centre as a multiple of the framing distance, 0.2..5 (0.5 is twice as close). */
  distance: number;
}

export const CAMERA_DEFAULTS: Readonly<Required<CameraOptions>> = Object.freeze({ yaw: 0, pitch: 0, distance: 1 });

export const CAMERA_RANGES: Readonly<Record<keyof CameraOptions, readonly [number, number]>> = Object.freeze({
  yaw: [-180, 180],
  pitch: [-80, 80],
  distance: [0.2, 5],
});

/**
 * How the face looks beyond its shape: the skin's colour, and eyebrows and eyelashes, each with an off switch for
 * studies that want a bare face.
 */
export interface AppearanceOptions {
  /** The skin's base colour, sRGB `#rrggbb`; the lips' tint and the mouth's shading keep their share of it. */
  skinColor: string;
  /** Draw the eyebrows. */
  brows: boolean;
  /** Eyebrow colour, sRGB `#rrggbb`. */
  browColor: string;
  /** Share of the eyebrow hairs drawn, 0..1 (1: a full brow, 0.4: a sparse one). */
  browDensity: number;
  /** Draw the eyelashes. */
  lashes: boolean;
  /** Eyelash colour, sRGB `#rrggbb`. */
  lashColor: string;
}

/** The default head's light skin, dark brown brows and near-black lashes. */
export const APPEARANCE_DEFAULTS: Readonly<Required<AppearanceOptions>> = Object.freeze({
  skinColor: '#cba08b',
  brows: true,
  browColor: '#4a3427',
  browDensity: 1,
  lashes: true,
  lashColor: '#1c1612',
});

export const APPEARANCE_RANGES: Readonly<Partial<Record<keyof AppearanceOptions, readonly [number, number]>>> = Object.freeze({
  browDensity: [0, 1],
});

export const RENDER_DEFAULTS: Readonly<Required<RenderOptions>> = Object.freeze({ wireframe: false, showEyes: true, showTeeth: true });

/** A background colour (sRGB hex), or `transparent` to show the page behind the canvas. */
export type ViewBackground = number | 'transparent';

/**
 * How the view antialiases: `always` multisamples the canvas; `still` draws a moving face without multisampling and
 * draws a face at rest, `savePNG` pictures and video frames multisampled offscreen (the same picture); `auto` is
 * `still` where WebGL runs in software (where multisampling more than doubles a draw) and `always` elsewhere.
 */
export type Antialias = 'auto' | 'always' | 'still';

/** The `Antialias` choices, in the order messages list them. */
export const ANTIALIAS_CHOICES: readonly Antialias[] = ['auto', 'always', 'still'];

/** Options of the view. */
export interface HeadViewOptions {
  background: ViewBackground;
  /** Vertical field of view in degrees. */
  fov: number;
  /** Cap on the device pixel ratio, to bound the cost of fill on dense screens. */
  maxPixelRatio: number;
  /**
   * Share of the pixel ratio the view draws at while the picture changes and its draws are slow (see `slowDrawMs`):
   * 0.5 draws a quarter of the pixels. Once nothing new has come for MOTION_END_MS (see motion-draw.ts) the picture
   * is drawn again at full resolution. 1 turns this off.
   */
  motionResolution: number;
  /**
   * A draw at full resolution that holds the next animation frame back longer than this (ms) is slow: software WebGL,
   * or a GPU that cannot fill the canvas at 20 frames a second.
   */
  slowDrawMs: number;
  /** How the view antialiases (see Antialias). */
  antialias: Antialias;
}

/** The view's defaults. */
export const HEAD_VIEW_DEFAULTS: Readonly<Required<HeadViewOptions>> = Object.freeze({
  background: 0x1d2024,
  fov: 28,
  maxPixelRatio: 2,
  motionResolution: 0.5,
  slowDrawMs: 50,
  antialias: 'auto',
});
