// Vite's dev server pre-bundles dependencies into a folder of its own, where the package's files are not: keep
// softface out of it (a production build needs nothing).
export default { optimizeDeps: { exclude: ['softface'] } };
