/**
 * The package's own files (models, rig, environment), and where a face fetches each from when no `assetBase` is
 * given. This project's own pages, in development and in its app build, serve them from the site's root; the library
 * build swaps this module for package-assets-library.ts, which names each file beside its modules by
 * `new URL('./…', import.meta.url)`, so that a bundler copies it into the app that imports the package.
 */

/** The files a face may fetch from the package, by their path under its asset folder. */
const PACKAGE_FILES = [
  'models/head-low.glb',
  'models/head-medium.glb',
  'models/head-high.glb',
  'models/identity-source.bin',
  'rigs/default.json',
  'environment/room.pmrem',
  // MediaPipe Face Mesh (the webcam tracker): written beside the others by the builds (scripts/vite-face-mesh.ts).
  'mediapipe/face_mesh/face_mesh.js',
  'mediapipe/face_mesh/face_mesh.binarypb',
  'mediapipe/face_mesh/face_mesh_solution_packed_assets_loader.js',
  'mediapipe/face_mesh/face_mesh_solution_packed_assets.data',
  'mediapipe/face_mesh/face_mesh_solution_simd_wasm_bin.js',
  'mediapipe/face_mesh/face_mesh_solution_simd_wasm_bin.wasm',
  'mediapipe/face_mesh/face_mesh_solution_simd_wasm_bin.data',
  'mediapipe/face_mesh/face_mesh_solution_wasm_bin.js',
  'mediapipe/face_mesh/face_mesh_solution_wasm_bin.wasm',
] as const;
export type PackageFile = (typeof PACKAGE_FILES)[number];

/** Where the package's file is served from (absolute). */
export function packageFileUrl(file: PackageFile): string {
  return new URL(file, new URL(import.meta.env.BASE_URL, location.origin)).href;
}
