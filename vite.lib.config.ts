import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';
import { faceMeshFiles } from './scripts/vite-face-mesh.ts';

/**
 * The library build (`npm run build:lib`), into `dist-lib/`. Mode `library`: ES modules with three.js left to the
 * host (`softface.js`, the entry; `element.js`, which registers `<soft-face>`). Mode `standalone`, built second: one
 * module with three.js inside (`softface.standalone.js`) for a plain `<script type="module">`. The skin worker (and
 * within it the solver's partner worker) is inlined (started from a Blob URL, no eval), and the models and rigs are copied beside the modules, where a face
 * looks for them by default (src/face/package-assets.ts).
 */
const path = (p: string): string => fileURLToPath(new URL(p, import.meta.url));

export default defineConfig(({ mode }) => {
  if (mode !== 'library' && mode !== 'standalone') throw new Error(`vite.lib.config.ts builds in mode library or standalone, not ${mode}`);
  const standalone = mode === 'standalone';
  const entry: Record<string, string> = standalone
    ? { 'softface.standalone': path('src/embed/standalone.ts') }
    : { softface: path('src/embed/index.ts'), element: path('src/embed/element.ts') };
  return {
    base: './',
    resolve: {
      alias: [
        { find: /^\.\/spawn-skin-worker$/, replacement: path('src/sim/main/spawn-skin-worker-inline.ts') },
        { find: /^\.\/spawn-partner-worker$/, replacement: path('src/sim/thread/spawn-partner-worker-inline.ts') },
        { find: /^\.\/spawn-identity-worker$/, replacement: path('src/sim/main/spawn-identity-worker-inline.ts') },
        { find: /^\.\/package-assets$/, replacement: path('src/face/package-assets-library.ts') },
      ],
    },
    plugins: [
      // The webcam tracker's MediaPipe files beside the modules (the standalone build adds to the library's folder).
      ...(standalone ? [] : [faceMeshFiles()]),
      {
        // The package's files are named by `new URL(/* @vite-ignore */ './…', import.meta.url)` in
        // package-assets-library.ts: the comment keeps this build from rewriting them (they are copied beside the
        // modules, not bundled); taken out here, it leaves the plain form an app's bundler follows and copies.
        name: 'softface-package-file-urls',
        enforce: 'post',
        renderChunk: (code: string) => code.replace(/new URL\(\s*\/\* @vite-ignore \*\/\s*/g, 'new URL('),
      },
    ],
    worker: { format: 'es' },
    build: {
      outDir: 'dist-lib',
      // The standalone build runs second and adds its module to the first build's output.
      emptyOutDir: !standalone,
      copyPublicDir: !standalone,
      target: 'es2022',
      // In library mode this mangles names but keeps whitespace (and the pure annotations a host's bundler uses).
      minify: true,
      lib: { entry, formats: ['es'] },
      rollupOptions: {
        external: standalone ? [] : [/^three($|\/)/],
        // Every module at the root, side by side: the default asset base is the folder of the module's own URL. The
        // standalone module's lazily loaded parts (the workers, the panels, video encoding, decimation) are chunks
        // beside it too, fetched when first used; those that are the library's own, byte for byte, share its files.
        output: { chunkFileNames: '[name]-[hash].js' },
      },
    },
  };
});
