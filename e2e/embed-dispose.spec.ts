import { EMBED_PAGE } from './embed';
import { expect, test } from './fixtures';

/** What the probe counts, as it stands. */
interface Census {
  /** Workers made and not terminated. */
  workers: number;
  /** WebGL contexts made whose context is not lost. */
  contexts: number;
  /** Listeners on window and document, by `type`. */
  listeners: Record<string, number>;
  /** Resize and intersection observers observing something, animation frames asked for and not yet run, intervals running. */
  observers: number;
  frames: number;
  intervals: number;
}

declare global {
  interface Window {
    census: () => Census;
  }
}

/**
 * Runs before the page's own scripts and counts what a face could leave behind: the page's Worker constructor,
 * canvas contexts, listeners on window and document, resize observers, animation frames and intervals are wrapped,
 * each counting what is live. Workers are counted until `terminate()` (the solver's worker never ends itself).
 */
function installProbe(): void {
  const live = { workers: 0, observers: 0, frames: new Set<number>(), intervals: new Set<unknown>() };
  const contexts: WebGLRenderingContext[] = [];
  const listeners = new Map<EventTarget, Set<string>>([
    [window, new Set()],
    [document, new Set()],
  ]);
  const NativeWorker = window.Worker;
  window.Worker = class extends NativeWorker {
    private ended = false;
    constructor(url: string | URL, options?: WorkerOptions) {
      super(url, options);
      live.workers++;
    }
    terminate(): void {
      if (!this.ended) live.workers--;
      this.ended = true;
      super.terminate();
    }
  };
  const getContext = HTMLCanvasElement.prototype.getContext;
  HTMLCanvasElement.prototype.getContext = function (this: HTMLCanvasElement, type: string, ...rest: unknown[]) {
    const context = (getContext as (...a: unknown[]) => RenderingContext | null).call(this, type, ...rest);
    if (context && type.startsWith('webgl') && !contexts.includes(context as WebGLRenderingContext))
      contexts.push(context as WebGLRenderingContext);
    return context;
  } as typeof getContext;
  // A listener is the same one again for the same type, function and capture flag, as the DOM counts them.
  const key = (type: string, listener: unknown, options: unknown): string => {
    const capture = typeof options === 'boolean' ? options : !!(options as AddEventListenerOptions | undefined)?.capture;
    let id = ids.get(listener);
    if (id === undefined) {
      id = ids.size;
      ids.set(listener, id);
    }
    return `${type} ${id} ${capture}`;
  };
  const ids = new Map<unknown, number>();
  const add = EventTarget.prototype.addEventListener;
  const remove = EventTarget.prototype.removeEventListener;
  EventTarget.prototype.addEventListener = function (this: EventTarget, type: string, listener: unknown, options?: unknown) {
    listeners.get(this)?.add(key(type, listener, options));
    return add.call(this, type, listener as EventListener, options as AddEventListenerOptions);
  };
  EventTarget.prototype.removeEventListener = function (this: EventTarget, type: string, listener: unknown, options?: unknown) {
    listeners.get(this)?.delete(key(type, listener, options));
    return remove.call(this, type, listener as EventListener, options as EventListenerOptions);
  };
  // An observer counts from its first observe() to its disconnect().
  // biome-ignore lint/suspicious/noExplicitAny: a mixin's constructor must take any[]
  const counted = <T extends { new (...args: any[]): { observe(...a: never[]): void; disconnect(): void } }>(Native: T): T =>
    class extends Native {
      private observing = false;
      observe(...args: never[]): void {
        if (!this.observing) live.observers++;
        this.observing = true;
        super.observe(...args);
      }
      disconnect(): void {
        if (this.observing) live.observers--;
        this.observing = false;
        super.disconnect();
      }
    };
  window.ResizeObserver = counted(window.ResizeObserver);
  window.IntersectionObserver = counted(window.IntersectionObserver);
  const requestFrame = window.requestAnimationFrame.bind(window);
  const cancelFrame = window.cancelAnimationFrame.bind(window);
  window.requestAnimationFrame = (callback) => {
    const id = requestFrame((now) => {
      live.frames.delete(id);
      callback(now);
    });
    live.frames.add(id);
    return id;
  };
  window.cancelAnimationFrame = (id) => {
    live.frames.delete(id);
    cancelFrame(id);
  };
  const setInterval = window.setInterval.bind(window);
  const clearInterval = window.clearInterval.bind(window);
  window.setInterval = ((handler: TimerHandler, ms?: number, ...args: unknown[]) => {
    const id = setInterval(handler, ms, ...args);
    live.intervals.add(id);
    return id;
  }) as typeof window.setInterval;
  window.clearInterval = (id) => {
    live.intervals.delete(id);
    clearInterval(id);
  };
  window.census = () => {
    const byType: Record<string, number> = {};
    for (const set of listeners.values()) for (const k of set) byType[k.split(' ')[0]] = (byType[k.split(' ')[0]] ?? 0) + 1;
    return {
      workers: live.workers,
      contexts: contexts.filter((c) => !c.isContextLost()).length,
      listeners: byType,
      observers: live.observers,
      frames: live.frames.size,
      intervals: live.intervals.size,
    };
  };
}

const CYCLES = 20;

test(`creating and disposing a face ${CYCLES} times leaves no worker, WebGL context, listener, observer or timer behind`, async ({
  page,
}) => {
  test.setTimeout(240_000);
  const messages: string[] = [];
  page.on('console', (m) => messages.push(m.text()));
  await page.addInitScript(installProbe);
  await page.goto(EMBED_PAGE);
  await expect(page.locator('html')).toHaveAttribute('data-state', 'ready');
  const before = await page.evaluate(() => window.census());

  const r = await page.evaluate(async (cycles) => {
    // Out of view, a face renders nothing: no environment map, no shaders compiled, each seconds of work in software
    // WebGL. The first face is rendered once (measureRender), so that a rendered face is taken back too.
    const container = document.createElement('div');
    Object.assign(container.style, { position: 'absolute', left: '-10000px', width: '320px', height: '240px' });
    document.body.append(container);
    const during: Census[] = [];
    const afterUse: string[] = [];
    const rendered: number[] = [];
    for (let i = 0; i < cycles; i++) {
      // Panels and the eye simulation on: they bring their own listeners, timers and frame hooks.
      const face = await window.softface.createFace(container, { resolution: 'low', panels: true, eyeSimulation: true });
      face.setActionUnit('AU12', 0.5);
      if (i === 0) rendered.push(face.measureRender(1).triangles);
      during.push(window.census());
      face.dispose();
      face.dispose();
      try {
        face.setActionUnit('AU12', 0);
      } catch (error) {
        afterUse.push((error as Error).message);
      }
    }
    return { during, afterUse, rendered, children: container.childElementCount };
  }, CYCLES);

  // While a face lives, the probe sees it: one worker, one context, its two observers (size, and whether it is in
  // view), its animation frame and the panels' interval.
  for (const c of r.during) expect(c).toMatchObject({ workers: 1, contexts: 1, observers: 2, frames: 1, intervals: 1 });
  expect(r.afterUse).toEqual(Array(CYCLES).fill('the face was disposed'));
  // The low head has 8,524 skin triangles, more with eyes and teeth.
  for (const triangles of r.rendered) expect(triangles).toBeGreaterThan(8524);
  expect(r.children).toBe(0);
  expect(await page.evaluate(() => window.census())).toEqual(before);
  // The browser's own view of the page's workers: terminated ones close (asynchronously).
  await expect.poll(() => page.workers().length).toBe(0);
  expect(messages.filter((m) => /webgl|context/i.test(m))).toEqual([]);
});
