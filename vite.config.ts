import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';
import { faceMeshFiles } from './scripts/vite-face-mesh.ts';

/**
 * SharedArrayBuffer exists only on cross-origin isolated pages, so both the dev server and `vite preview` send
 * COOP/COEP. `SOFTFACE_NO_ISOLATION=1` drops them, to check the page as a host that does not send them would serve it.
 */
const isolationHeaders: Record<string, string> = process.env.SOFTFACE_NO_ISOLATION
  ? {}
  : { 'Cross-Origin-Opener-Policy': 'same-origin', 'Cross-Origin-Embedder-Policy': 'require-corp' };

const path = (p: string): string => fileURLToPath(new URL(p, import.meta.url));

export default defineConfig({
  base: './',
  // Pages of this project import the package by its own name, as an embedding page would.
  resolve: {
    alias: [
      { find: /^softface\/element$/, replacement: path('src/embed/element.ts') },
      { find: /^softface$/, replacement: path('src/embed/index.ts') },
    ],
  },
  // The webcam tracker's MediaPipe files, from the site.
  plugins: [faceMeshFiles()],
  server: { headers: isolationHeaders },
  preview: { headers: isolationHeaders },
  worker: { format: 'es' },
  build: {
    target: 'es2022',
    chunkSizeWarningLimit: 1024,
    rollupOptions: {
      // The app, and the page the browser tests embed faces in.
      input: { main: path('index.html'), embed: path('e2e/pages/embed.html') },
    },
  },
});
