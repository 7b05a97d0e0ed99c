/**
 * The package's own files as the library build finds them: beside its modules, each named by a literal
 * `new URL('./…', import.meta.url)`. A bundler that builds an app importing the package (Vite, webpack 5, Rollup,
 * esbuild with its plugin) sees these and copies each file into the app's output; served without a bundler, the
 * module's own URL finds them in the package's folder. vite.lib.config.ts puts this module in place of
 * package-assets.ts.
 */
// A type only (erased): the library build resolves './package-assets' to this module.
import type { PackageFile } from './package-assets';

// Each written out whole: bundlers only follow a literal path.
const FILES: Readonly<Record<PackageFile, () => URL>> = {
  'models/head-low.glb': () => new URL(/* @vite-ignore */ './models/head-low.glb', import.meta.url),
  'models/head-medium.glb': () => new URL(/* @vite-ignore */ './models/head-medium.glb', import.meta.url),
  'models/head-high.glb': () => new URL(/* @vite-ignore */ './models/head-high.glb', import.meta.url),
  'models/identity-source.bin': () => new URL(/* @vite-ignore */ './models/identity-source.bin', import.meta.url),
  'rigs/default.json': () => new URL(/* @vite-ignore */ './rigs/default.json', import.meta.url),
  'environment/room.pmrem': () => new URL(/* @vite-ignore */ './environment/room.pmrem', import.meta.url),
  'mediapipe/face_mesh/face_mesh.js': () => new URL(/* @vite-ignore */ './mediapipe/face_mesh/face_mesh.js', import.meta.url),
  'mediapipe/face_mesh/face_mesh.binarypb': () => new URL(/* @vite-ignore */ './mediapipe/face_mesh/face_mesh.binarypb', import.meta.url),
  'mediapipe/face_mesh/face_mesh_solution_packed_assets_loader.js': () =>
    new URL(/* @vite-ignore */ './mediapipe/face_mesh/face_mesh_solution_packed_assets_loader.js', import.meta.url),
  'mediapipe/face_mesh/face_mesh_solution_packed_assets.data': () =>
    new URL(/* @vite-ignore */ './mediapipe/face_mesh/face_mesh_solution_packed_assets.data', import.meta.url),
  'mediapipe/face_mesh/face_mesh_solution_simd_wasm_bin.js': () =>
    new URL(/* @vite-ignore */ './mediapipe/face_mesh/face_mesh_solution_simd_wasm_bin.js', import.meta.url),
  'mediapipe/face_mesh/face_mesh_solution_simd_wasm_bin.wasm': () =>
    new URL(/* @vite-ignore */ './mediapipe/face_mesh/face_mesh_solution_simd_wasm_bin.wasm', import.meta.url),
  'mediapipe/face_mesh/face_mesh_solution_simd_wasm_bin.data': () =>
    new URL(/* @vite-ignore */ './mediapipe/face_mesh/face_mesh_solution_simd_wasm_bin.data', import.meta.url),
  'mediapipe/face_mesh/face_mesh_solution_wasm_bin.js': () =>
    new URL(/* @vite-ignore */ './mediapipe/face_mesh/face_mesh_solution_wasm_bin.js', import.meta.url),
  'mediapipe/face_mesh/face_mesh_solution_wasm_bin.wasm': () =>
    new URL(/* @vite-ignore */ './mediapipe/face_mesh/face_mesh_solution_wasm_bin.wasm', import.meta.url),
};

/** Where the package's file is served from (absolute). */
export function packageFileUrl(file: PackageFile): string {
  return FILES[file]().href;
}
