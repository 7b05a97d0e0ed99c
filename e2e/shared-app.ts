import type { Browser, BrowserContext, BrowserContextOptions, Page, ViewportSize } from '@playwright/test';
import { loadFace, reopeners } from './face';
import { test as base } from './fixtures';

/**
 * The browser tests' `test` with one page of the app kept from test to test in a worker: a page start costs about 6.5
 * CPU-seconds of the two cores in software WebGL (the GPU process 2.6, the page's compilers, main thread and solver
 * 3.5, a third of it the kernel's page faults), more than most tests of the handle and the panels take. `openFace`
 * on it does not load the page again when it is already at that URL: it puts the face back as a new page shows it
 * (the expression, the timeline, the overlays, the options the handle sets; see `restore`) and checks everything a
 * test can read of that state against what it read when the page was new (see `snapshot`), loading the page after
 * all where anything differs. A test that failed leaves its page to no one.
 *
 * For files whose tests use the page only through the handle, the panels, the editor and the pictures: no `context`
 * fixture, no init scripts, routes or exposed functions (which stay with a page), no loaded heads, no reloads (an
 * edited rig's autosave outlives the page). Rig edits are reverted and their undo history cleared.
 * `SOFTFACE_E2E_SHARED_LOG=1` prints, for each `openFace`, whether the page was put back or loaded, and what differed.
 */
export const test = base.extend<object, { appPage: SharedAppPage }>({
  appPage: [
    async ({ browser }, use, workerInfo) => {
      const shared = new SharedAppPage(browser, contextOptions(workerInfo.project.use));
      await use(shared);
      await shared.dispose();
    },
    { scope: 'worker' },
  ],
  page: async ({ appPage, viewport }, use, testInfo) => {
    const page = await appPage.page(viewport);
    await use(page);
    if (testInfo.status !== testInfo.expectedStatus) await appPage.dispose();
  },
});

export { expect } from './fixtures';

/** The project's options that make a context as Playwright's own `context` fixture would (see playwright.config.ts). */
function contextOptions(use: BrowserContextOptions & { baseURL?: string }): BrowserContextOptions {
  const { baseURL, viewport, userAgent, deviceScaleFactor, isMobile, hasTouch, screen } = use;
  return { baseURL, viewport, userAgent, deviceScaleFactor, isMobile, hasTouch, screen };
}

/** What a test can read of the face's state, the URL and the panels (numbers rounded to 1e-6). */
type Snapshot = string;

/** How long the restored state may take to show everywhere (the URL hash is written every 250 ms). */
const SETTLE_MS = 3_000;

/** The worker's kept page of the app: made at its first use, given to each test, dropped after a failed one. */
class SharedAppPage {
  private context: BrowserContext | null = null;
  private current: Page | null = null;
  /** The URL the page was loaded at and its snapshot then; null until a face was opened on it. */
  private opened: { url: string; snapshot: Snapshot } | null = null;

  constructor(
    private readonly browser: Browser,
    private readonly options: BrowserContextOptions,
  ) {}

  /** The page, at the test's viewport size. */
  async page(viewport: ViewportSize | null): Promise<Page> {
    if (!this.current) {
      this.context = await this.browser.newContext(this.options);
      const page = await this.context.newPage();
      reopeners.set(page, (url) => this.open(page, url));
      this.current = page;
    }
    const size = this.current.viewportSize();
    if (viewport && (size?.width !== viewport.width || size.height !== viewport.height)) await this.current.setViewportSize(viewport);
    return this.current;
  }

  /** Closes the page: the next test gets a new one. */
  async dispose(): Promise<void> {
    const context = this.context;
    this.context = null;
    this.current = null;
    this.opened = null;
    await context?.close();
  }

  /** Shows the face as a page newly loaded at `url` does: put back in place if that can be checked, else loaded. */
  private async open(page: Page, url: string): Promise<void> {
    const opened = this.opened;
    // A URL with a hash sets the face from it at load: only a load does that.
    // A test that navigated the page elsewhere left no face to put back: the restore throws, and the page loads.
    if (opened && opened.url === url && !url.includes('#') && (await restore(page, opened.snapshot).catch(() => false))) {
      if (process.env.SOFTFACE_E2E_SHARED_LOG) console.log(`kept page: restored ${url}`);
      return;
    }
    if (process.env.SOFTFACE_E2E_SHARED_LOG) console.log(`kept page: loaded ${url}${opened ? ` (had ${opened.url})` : ''}`);
    this.opened = null;
    await loadFace(page, url);
    this.opened = { url, snapshot: await snapshot(page) };
  }
}

/**
 * Puts the face back as it was when the page was new (`opened` is its snapshot then) and waits until a snapshot shows
 * it so; false if it does not within SETTLE_MS.
 */
async function restore(page: Page, opened: Snapshot): Promise<boolean> {
  const state = JSON.parse(opened) as OpenedOptions;
  await page.evaluate(async (o) => {
    const face = window.face;
    if (face.timelineState().loaded) face.clearTimeline();
    face.reset();
    face.clearOverlay();
    face.clearBlendshapes();
    face.clearMuscleTargets();
    face.setLight(o.light);
    face.setCamera(o.camera);
    face.setRenderOptions(o.render);
    face.setAppearance(o.appearance);
    face.setBackground(o.background);
    face.setSkinParameters(o.skin);
    face.setMuscleDisplay(o.muscles);
    // The editor as it was, and the rig the page started with, with no undo history (reverting is a step itself).
    face.selectMuscle(null);
    face.setPreviewContraction(o.editor.preview);
    face.setGizmoMode(o.editor.mode);
    face.setEditor(o.editor.on);
    face.setMirrorEdits(o.mirror);
    face.setBrush(o.brush);
    if (face.isRigEdited()) face.revertRig();
    face.clearRigHistory();
    if (document.activeElement instanceof HTMLElement) document.activeElement.blur();
    await face.settle(30_000);
  }, state);
  // The panels' folders open or closed as they were (a click, as a user would, so that lil-gui knows); the last
  // first, so that a folder is set while the folder it sits in is still open.
  // Each state is read just before its click: read all at once before the clicks, the panel tests' restores failed
  // on the folders (a click changes more than its own folder's state).
  const folders = page.locator('.softface-panels .lil-gui > .lil-title');
  for (let i = state.folders.length - 1; i >= 0; i--) {
    const closed = state.folders[i];
    const title = folders.nth(i);
    if ((await title.evaluate((e) => e.parentElement!.classList.contains('lil-closed'))) !== closed) await title.click();
  }
  await page.mouse.move(0, 0);
  const until = Date.now() + SETTLE_MS;
  for (;;) {
    const now = await snapshot(page);
    if (now === opened) return true;
    if (Date.now() > until) {
      if (process.env.SOFTFACE_E2E_SHARED_LOG) console.log(`kept page: differs in ${differences(opened, now).join(', ')}`);
      return false;
    }
    await page.waitForTimeout(100);
  }
}

/** The snapshot's top-level entries whose values differ between `a` and `b`. */
function differences(a: Snapshot, b: Snapshot): string[] {
  const x = JSON.parse(a) as Record<string, unknown>;
  const y = JSON.parse(b) as Record<string, unknown>;
  return Object.keys({ ...x, ...y }).filter((k) => JSON.stringify(x[k]) !== JSON.stringify(y[k]));
}

type Face = Window['face'];

/** The options `restore` sets back, as `snapshot` records them. */
interface OpenedOptions {
  light: Parameters<Face['setLight']>[0];
  camera: Parameters<Face['setCamera']>[0];
  render: Parameters<Face['setRenderOptions']>[0];
  appearance: Parameters<Face['setAppearance']>[0];
  background: string;
  skin: Parameters<Face['setSkinParameters']>[0];
  muscles: Parameters<Face['setMuscleDisplay']>[0];
  editor: ReturnType<Face['describeEditor']>;
  mirror: boolean;
  brush: Parameters<Face['setBrush']>[0];
  folders: boolean[];
}

/**
 * Everything a test can read of the face's state through the handle, the URL, the document's structure and the
 * panels' folders, with the skin's largest distance from rest (rounded to 1e-6 m: at rest it is 0), as one string.
 */
async function snapshot(page: Page): Promise<Snapshot> {
  const state = await page.evaluate(() => {
    const face = window.face;
    const { rest, positions } = face.getSkin();
    let moved = 0;
    for (let i = 0; i < rest.length; i++) moved = Math.max(moved, Math.abs(positions[i] - rest[i]));
    const stats = face.stats();
    return {
      light: face.getLight(),
      camera: face.getCamera(),
      render: face.getRenderOptions(),
      appearance: face.getAppearance(),
      background: face.getBackground(),
      skin: face.getSkinParameters(),
      muscles: face.getMuscleDisplay(),
      folders: [...document.querySelectorAll('.softface-panels .lil-gui > .lil-title')].map((e) =>
        e.parentElement!.classList.contains('lil-closed'),
      ),
      actionUnits: face.getActionUnits(),
      presets: face.listPresets(),
      overlay: face.getOverlay(),
      blendshapes: face.getBlendshapes(),
      timeline: face.timelineState(),
      eyes: face.getEyeSimulation(),
      editor: face.describeEditor(),
      mirror: face.getMirrorEdits(),
      brush: face.getBrush(),
      rigEdited: face.isRigEdited(),
      rig: face.exportRig(),
      head: face.describeHead(),
      identity: face.getIdentity(),
      guide: face.describeLandmarkGuide(),
      panels: face.hasPanels(),
      tracking: face.trackingState().on,
      recording: face.isRecording(),
      solver: { mode: stats.mode, workers: stats.workers, vertices: stats.vertices, sleeping: stats.sleeping },
      moved,
      address: location.pathname + location.search + location.hash.replace(/^#$/, ''),
      ready: document.documentElement.dataset.state,
      body: document.body.childElementCount,
      styles: document.styleSheets.length,
    };
  });
  return JSON.stringify(state, (_, v) => (typeof v === 'number' ? Math.round(v * 1e6) / 1e6 : v));
}
