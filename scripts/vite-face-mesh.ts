/**
 * MediaPipe Face Mesh's files (its script, WebAssembly and model data, Apache-2.0, from the `@mediapipe/face_mesh`
 * package) served under `mediapipe/face_mesh/` by the dev server and written there by a build, so that the tracker
 * (src/face/face-tracker.ts) loads them from the site or the package, never from a CDN.
 */
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import type { Plugin } from 'vite';

/** The package's files the tracker loads, by name. */
export const FACE_MESH_FILES = [
  'face_mesh.js',
  'face_mesh.binarypb',
  'face_mesh_solution_packed_assets_loader.js',
  'face_mesh_solution_packed_assets.data',
  'face_mesh_solution_simd_wasm_bin.js',
  'face_mesh_solution_simd_wasm_bin.wasm',
  'face_mesh_solution_simd_wasm_bin.data',
  'face_mesh_solution_wasm_bin.js',
  'face_mesh_solution_wasm_bin.wasm',
] as const;

const FOLDER = 'mediapipe/face_mesh';

function packageFolder(): string {
  return dirname(createRequire(import.meta.url).resolve('@mediapipe/face_mesh/package.json'));
}

/** Serves the files in development and emits them into a build's output. */
export function faceMeshFiles(): Plugin {
  return {
    name: 'softface-face-mesh-files',
    configureServer(server) {
      server.middlewares.use((request, response, next) => {
        const match = /\/mediapipe\/face_mesh\/([\w.]+)$/.exec((request.url ?? '').split('?')[0]);
        const name = match?.[1] as (typeof FACE_MESH_FILES)[number] | undefined;
        if (!name || !FACE_MESH_FILES.includes(name)) return next();
        const type = name.endsWith('.js') ? 'text/javascript' : name.endsWith('.wasm') ? 'application/wasm' : 'application/octet-stream';
        response.setHeader('Content-Type', type);
        response.end(readFileSync(join(packageFolder(), name)));
      });
    },
    generateBundle() {
      for (const name of FACE_MESH_FILES) {
        this.emitFile({ type: 'asset', fileName: `${FOLDER}/${name}`, source: readFileSync(join(packageFolder(), name)) });
      }
    },
  };
}
