// All webpack 5 needs: an entry and an output folder. The package's files (head models, rig, lighting) are asset
// modules to it, found through the library's `new URL('./…', import.meta.url)` and emitted beside main.js.
import { fileURLToPath } from 'node:url';

export default {
  mode: 'production',
  entry: './src/main.js',
  output: { path: fileURLToPath(new URL('./dist/', import.meta.url)), filename: 'main.js' },
  performance: { hints: false },
};
