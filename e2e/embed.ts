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
  return {
    display: 'inline-block',
    width: `${p.width}px`,
    height: `${p.height}px`,
    ...(p.inView ? {} : { position: 'absolute', left: '-10000px' }),
  };
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

/** An event a `<soft-face>` fired, as the tests record it. */
export interface ElementEvent {
  type: string;
  /** `detail.change` of a change event, the message of an error event. */
  what?: string;
}

declare global {
  interface Window {
    /** Events of each `<soft-face>` a test made, by its id, in order. */
    elementEvents: Record<string, ElementEvent[]>;
  }
}

/**
 * Puts a `<soft-face id=name>` with these attributes on the page, records its ready, change and error events in
 * `window.elementEvents[name]` (error events are prevented, so they do not reach the console), and resolves once it
 * is ready.
 */
export async function addElement(page: Page, name: string, attributes: Record<string, string>, placement: Placement = {}): Promise<void> {
  await page.evaluate(
    async ({ name, attributes, style }) => {
      window.elementEvents ??= {};
      const events: ElementEvent[] = [];
      window.elementEvents[name] = events;
      const element = document.createElement('soft-face');
      element.id = name;
      for (const [key, value] of Object.entries(attributes)) element.setAttribute(key, value);
      Object.assign(element.style, style);
      element.addEventListener('ready', () => events.push({ type: 'ready' }));
      // Only the element's own change events have a detail; a native one leaking out of its panels would show as such.
      element.addEventListener('change', (e) =>
        events.push({ type: 'change', what: (e as CustomEvent<{ change: string } | null>).detail?.change ?? 'native' }),
      );
      element.addEventListener('error', (e) => {
        e.preventDefault();
        events.push({ type: 'error', what: (e as ErrorEvent).message });
      });
      const ready = new Promise((resolve) => element.addEventListener('ready', resolve, { once: true }));
      document.body.append(element);
      await ready;
    },
    { name, attributes, style: placementStyle(placement) },
  );
}

/** The events a `<soft-face>` fired since the last call, and forgets them. */
export async function takeEvents(page: Page, name: string): Promise<ElementEvent[]> {
  return page.evaluate((name) => window.elementEvents[name].splice(0), name);
}
