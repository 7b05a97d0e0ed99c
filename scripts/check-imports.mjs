// Checks the layout's import rules: which folders of src/ each folder's modules may import (docs/contributing.md's layout
// table). A static import of a folder not allowed fails `npm run lint`, naming the file and the import.
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';

/** Folder (under src/) -> the folders it may import from, besides itself. Longest folder prefix wins. */
const MAY_IMPORT = {
  core: [],
  'sim/shared': ['core'],
  'sim/thread': ['core', 'sim/shared'],
  'sim/main': ['core', 'sim/shared'],
  render: ['core'],
  face: ['core', 'sim/main', 'sim/shared', 'render'],
  ui: ['core', 'render', 'face'],
  embed: ['core', 'render', 'face'],
  app: ['embed'],
};
/** Packages a folder may not import (the pure core runs in Node and in workers). */
const FORBIDDEN_PACKAGES = { core: ['three'], 'sim/shared': ['three'], 'sim/thread': ['three'], 'sim/main': ['three'] };
/** Imports that are allowed across the rules: the main thread spawns the workers from their entry modules. */
const WORKER_ENTRY = /\.worker(\.ts)?(\?[\w&]+)?$/;
/** Lazy imports that are allowed across the rules: the face loads its panels on first use. */
const LAZY = { face: ['ui'] };

const root = resolve(import.meta.dirname, '..', 'src');
const folders = Object.keys(MAY_IMPORT).sort((a, b) => b.length - a.length);
const folderOf = (file) => {
  const rel = relative(root, file).replaceAll('\\', '/');
  return folders.find((f) => rel === f || rel.startsWith(`${f}/`));
};

function* files(dir) {
  for (const name of readdirSync(dir)) {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) yield* files(path);
    else if (/\.ts$/.test(name)) yield path;
  }
}

const problems = [];
let count = 0;
for (const file of files(root)) {
  count++;
  const from = folderOf(file);
  if (!from) {
    problems.push(`src/${relative(root, file)}: in no folder of the layout`);
    continue;
  }
  const text = readFileSync(file, 'utf8');
  for (const m of text.matchAll(/(?:^|\n)\s*(?:import|export)\s[^;]*?\sfrom\s+['"]([^'"]+)['"]|import\(\s*['"]([^'"]+)['"]\s*\)/g)) {
    const spec = m[1] ?? m[2];
    const lazy = m[2] !== undefined;
    if (!spec.startsWith('.')) {
      const pkg = spec.split('/')[0];
      if ((FORBIDDEN_PACKAGES[from] ?? []).includes(pkg))
        problems.push(`src/${relative(root, file)}: imports ${spec}, which ${from} may not`);
      continue;
    }
    const target = folderOf(resolve(dirname(file), spec));
    if (!target || target === from || MAY_IMPORT[from].includes(target)) continue;
    if (WORKER_ENTRY.test(spec) && from === 'sim/main' && target === 'sim/thread') continue;
    if (lazy && (LAZY[from] ?? []).includes(target)) continue;
    problems.push(`src/${relative(root, file)}: imports ${spec} (${target}), which ${from} may not`);
  }
}
if (problems.length > 0) {
  console.error(problems.join('\n'));
  process.exit(1);
}
console.log(`${count} modules, each importing only what its folder may`);
