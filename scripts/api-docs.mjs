/**
 * The API reference (`npm run docs`): TypeDoc reads the package's entries (`softface`, `softface/element`,
 * `softface/standalone`) and their TSDoc comments and writes Markdown pages to docs/api/, and docs/handle.md lists the
 * handle's methods by concern with their summaries. `--check` (run by `npm test`) writes both to a temporary folder
 * instead and fails on any TypeDoc warning (an undocumented public item, a type the reference names but does not
 * include, a broken link), on a method of the handle in no concern, or when docs/ is not what the sources make.
 *
 * TypeDoc runs in tools/typedoc/ with its own TypeScript 6: it reads sources through TypeScript's compiler API, which
 * TypeScript 7, the project's compiler, does not have. The first run installs it there (`npm ci`).
 */
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';

const project = fileURLToPath(new URL('..', import.meta.url));
const tools = join(project, 'tools', 'typedoc');
const reference = join(project, 'docs', 'api');
const check = process.argv.includes('--check');

/** The handle's concerns in the order the page gives them: each controller's file stem and the page's heading. */
const CONCERNS = [
  ['expression', 'Expression: Action Units, presets, the overlay'],
  ['skin', 'The skin and its solver'],
  ['view', 'View: panels, camera, light, look, pictures'],
  ['timeline', 'Timeline'],
  ['live', 'Live input: blendshape streams and OpenFace files'],
  ['eyes', 'Eye simulation'],
  ['export', 'Video and glTF'],
  ['head', 'Heads and people'],
  ['editor', 'The muscle editor'],
  ['rig', 'The rig document'],
];

const HANDLE_INTRO = `# The handle

\`createFace(container, options)\` resolves to a face's handle (\`<soft-face>\` has it as \`element.face\`). Here are all its
methods by concern, each with its summary; the names link to the [API reference](api/README.md), which has each one's
arguments and types. This page is made from the sources by \`npm run docs\`.

What every method does with bad input: a setter refuses a value it cannot use (an unknown id or option, a value that
is not a finite number, out of its range or of the wrong type) by throwing an \`Error\` whose message starts with the
method's name and says what it expected and what it got (\`setActionUnit: expected an Action Unit id like "AU12", ...,
got "AU99"\`), and nothing changes; a method that returns a promise rejects instead. Intensities and weights are
clamped to 0..1 rather than refused. After \`dispose()\` every method throws.`;

// npm writes the lock of what it installed into node_modules (without the folder's own entry, ""); a different one
// means the folder's lock changed since.
const installed = join(tools, 'node_modules', '.package-lock.json');
const lock = (file) => {
  const { '': _, ...packages } = JSON.parse(readFileSync(file, 'utf8')).packages;
  return JSON.stringify(packages);
};
if (!existsSync(installed) || lock(installed) !== lock(join(tools, 'package-lock.json'))) {
  execFileSync('npm', ['ci', '--no-audit', '--no-fund', '--loglevel', 'error'], { cwd: tools, stdio: 'inherit' });
}

const scratch = mkdtempSync(join(tmpdir(), 'softface-api-'));
const out = check ? join(scratch, 'api') : reference;
const handlePage = join(project, 'docs', 'handle.md');
try {
  const typedoc = join(tools, 'node_modules', 'typedoc', 'bin', 'typedoc');
  const json = join(scratch, 'api.json');
  try {
    if (!check) rmSync(out, { recursive: true, force: true });
    execFileSync(
      process.execPath,
      [typedoc, '--options', join(tools, 'typedoc.json'), '--out', out, '--json', json, '--logLevel', 'Warn'],
      { cwd: tools, stdio: 'inherit' },
    );
  } catch {
    console.error('api-docs: TypeDoc found the problems above (docs/api is made with warnings treated as errors)');
    process.exit(1);
  }
  const handle = handleMarkdown(JSON.parse(readFileSync(json, 'utf8')));
  if (check) {
    const stale = differences(out, reference);
    if (!existsSync(handlePage) || readFileSync(handlePage, 'utf8') !== handle) stale.push('docs/handle.md');
    if (stale.length > 0) {
      console.error(`api-docs: docs/ is not what the sources make (run npm run docs): ${stale.slice(0, 10).join(', ')}`);
      process.exit(1);
    }
  } else {
    mkdirSync(join(project, 'docs'), { recursive: true });
    writeFileSync(handlePage, handle);
  }
  console.log(
    `api-docs: ${files(out).length} pages${check ? ', docs/api and docs/handle.md are up to date' : ` in ${relative(project, out)}`}`,
  );
} finally {
  rmSync(scratch, { recursive: true, force: true });
}

/**
 * docs/handle.md: the handle's methods by concern, as the handle delegates them (the `*_METHODS` lists of
 * src/face/*-controller.ts), each with its signature, linked to the reference, and its summary.
 */
function handleMarkdown(api) {
  const find = (node) => (node.name === 'FaceHandle' && node.kind === 256 ? node : (node.children ?? []).map(find).find(Boolean));
  const members = new Map(find(api).children.map((m) => [m.name, m]));
  const concerns = [['The face itself', ['ready', 'onChange', 'dispose', 'isDisposed']]];
  for (const [file, title] of CONCERNS) {
    const list = readFileSync(join(project, 'src', 'face', `${file}-controller.ts`), 'utf8').match(/_METHODS = \[([^\]]*)\]/);
    if (!list) throw new Error(`api-docs: src/face/${file}-controller.ts has no method list`);
    concerns.push([title, [...list[1].matchAll(/'(\w+)'/g)].map((m) => m[1])]);
  }
  const listed = new Set(concerns.flatMap(([, names]) => names));
  const unlisted = [...members.keys()].filter((name) => !listed.has(name));
  if (unlisted.length > 0) throw new Error(`api-docs: the handle's ${unlisted.join(', ')} belong to no concern`);
  const text = (parts) =>
    (parts ?? [])
      .map((p) => p.text)
      .join('')
      .replace(/\s*\n\s*/g, ' ')
      .replace(/\|/g, '\\|');
  const lines = [HANDLE_INTRO];
  for (const [title, names] of concerns) {
    lines.push('', `## ${title}`, '', '| method | what it does |', '| --- | --- |');
    for (const name of names) {
      const member = members.get(name);
      if (!member) throw new Error(`api-docs: the handle lists ${name}, which the reference does not have`);
      const signature = member.signatures?.[0];
      const args = signature
        ? `(${(signature.parameters ?? []).map((p) => (p.flags?.isOptional || p.defaultValue ? `${p.name}?` : p.name)).join(', ')})`
        : '';
      const summary = text((signature ?? member).comment?.summary);
      lines.push(`| [${name}${args}](api/softface/interfaces/FaceHandle.md#${name.toLowerCase()}) | ${summary} |`);
    }
  }
  return `${lines.join('\n')}\n`;
}

/** Every file under `dir`, relative to it. */
function files(dir, under = '') {
  return readdirSync(join(dir, under)).flatMap((name) => {
    const path = join(under, name);
    return statSync(join(dir, path)).isDirectory() ? files(dir, path) : [path];
  });
}

/** The pages that differ between two folders, or are in one only. */
function differences(a, b) {
  if (!existsSync(b)) return ['docs/api is missing'];
  const left = new Set(files(a));
  const right = new Set(files(b));
  const out = [];
  for (const f of left) if (!right.has(f) || readFileSync(join(a, f), 'utf8') !== readFileSync(join(b, f), 'utf8')) out.push(f);
  for (const f of right) if (!left.has(f)) out.push(f);
  return out;
}
