import { defineConfig } from 'vite';

/**
 * SharedArrayBuffer exists only on cross-origin isolated pages, so both the dev server and `vite preview` send
 * COOP/COEP. `SOFTFACE_NO_ISOLATION=1` drops them, to check the page as a host that does not send them would serve it.
 */
const isolationHeaders: Record<string, string> = process.env.SOFTFACE_NO_ISOLATION
  ? {}
  : { 'Cross-Origin-Opener-Policy': 'same-origin', 'Cross-Origin-Embedder-Policy': 'require-corp' };

export default defineConfig({
  base: './',
  server: { headers: isolationHeaders },
  preview: { headers: isolationHeaders },
  worker: { format: 'es' },
  build: { target: 'es2022', chunkSizeWarningLimit: 1024 },
});
