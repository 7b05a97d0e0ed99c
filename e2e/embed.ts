import type { Page } from '@playwright/test';
import type { Face } from '../src/embed/create-face';
import { expect } from './fixtures';

declare global {
  interface Window {
    /** The package's entry, on the embedding test page. */
    softface: typeof import('../src/embed/index');
    /** Faces a test made, by name. */
    faces: Record<string, Face>;
  }
}

/** The page the tests embed faces in: nothing on it but the package, as `window.softface`. */
export const EMBED_PAGE = '/e2e/pages/embed.html';

/** Opens the embedding test page (at `origin`, by default the isolated server). */
export async function openEmbedPage(page: Page, origin = ''): Promise<void> {
  await page.goto(`${origin}${EMBED_PAGE}`);
  await expect(page.locator('html')).toHaveAttribute('data-state', 'ready');
}

/** Where a test puts a face: its size in px, and whether it is in view. */
export interface Placement {
  width?: number;
  height?: number;
  /**
   * Out of view, a face renders nothing: tests of state and events save the environment map and the shader compiles,
   * each seconds of work in software WebGL, and the wait for them when the face is disposed.
   */
  inView?: boolean;
}

const PLACEMENT_DEFAULTS: Required<Placement> = { width: 360, height: 360, inView: true };

/** The style of a face's container for a placement. */
function placementStyle(placement: Placement): Record<string, string> {
  const p = { ...PLACEMENT_DEFAULTS, ...placement };
  return { display: 'inline-block', width: `${p.width}px`, height: `${p.height}px`, ...(p.inView ? {} : { position: 'absolute', left: '-10000px' }) };
}

/**
 * Makes faces in new containers (side by side, in order), with the options given for each, and keeps them in
 * `window.faces` by name. Resolves once all are ready.
 */
export async function addFaces(page: Page, faces: Record<string, object>, placement: Placement = {}): Promise<void> {
  await page.evaluate(
    async ({ faces, style }) => {
      window.faces ??= {};
      await Promise.all(
        Object.entries(faces).map(async ([name, options]) => {
          const container = document.createElement('div');
          container.id = name;
          Object.assign(container.style, style);
          document.body.append(container);
          window.faces[name] = await window.softface.createFace(container, options);
        }),
      );
    },
    { faces, style: placementStyle(placement) },
  );
}
