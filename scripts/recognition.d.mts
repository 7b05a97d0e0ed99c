import type { Browser, BrowserContext, Page } from '@playwright/test';

/** FaceExpressionNet's classes, in its output order. */
export declare const LABELS: readonly ['neutral', 'happy', 'sad', 'angry', 'fearful', 'disgusted', 'surprised'];
export type Label = (typeof LABELS)[number];

/** The class a preset (or `neutral`) is meant to read as; null for contempt and names that say no emotion. */
export declare function meantLabel(preset: string): Label | null;

/** The camera views: front, and turned 30° to the viewer's left and right. */
export declare const VIEWS: readonly { view: 'front' | 'left30' | 'right30'; yaw: number }[];

/** CSS that hides the app's panel column and status bar. */
export declare const HIDE_PANELS_CSS: string;

/** Shows a preset (or `neutral`) at full intensity from the settled neutral face; resolves to whether it settled. */
export declare function showExpression(page: Page, preset: string, timeoutMs?: number): Promise<boolean>;

/** A PNG of the app's canvas with the camera turned `yaw` degrees (pitch 0, default distance). */
export declare function renderView(page: Page, yaw: number): Promise<Buffer>;

/** The installed face-api's version. */
export declare const FACE_API_VERSION: string;

export interface RecognizerSettings {
  detector: 'ssd' | 'tiny';
  minScore: number;
  backend: 'cpu' | 'webgl';
  /** 'aligned': the cut around the 68 landmarks; 'box': the detector's box. */
  crop: 'aligned' | 'box';
}
export declare const DEFAULTS: Readonly<RecognizerSettings>;

export interface Recognition {
  detected: boolean;
  score: number | null;
  box: { x: number; y: number; width: number; height: number } | null;
  top: Label | null;
  probability: number | null;
  expressions: Record<Label, number> | null;
}

export interface Recognizer {
  settings: RecognizerSettings;
  recognize(png: Uint8Array): Promise<Recognition>;
  close(): Promise<void>;
}

/** Opens the recogniser in a new page of `browser` and loads its networks. */
export declare function startRecognizer(browser: Browser | BrowserContext, options?: Partial<RecognizerSettings>): Promise<Recognizer>;

/** The turns (degrees) around a view whose readings recognizeView averages. */
export declare const VIEW_JITTER: readonly number[];

/** One render's own reading in recognizeView: its turn from the view, its top class and probability (null: no face). */
export interface JitterRead {
  turn: number;
  top: Label | null;
  probability: number | null;
}

/** What the recogniser reads of a view: the class probabilities averaged over renders turned by `jitter` around `yaw`. */
export declare function recognizeView(
  page: Page,
  recognizer: Recognizer,
  yaw: number,
  jitter?: readonly number[],
): Promise<Recognition & { png: Buffer | null; reads: JitterRead[] }>;
