/**
 * Builds the default head models from the MakeHuman hm08 base mesh (CC0):
 *   npm run build:models -- [path/to/makehuman-hm08] [--out public/models]
 *     [--targets path/to/makehuman-targets/macrodetails] [--identity <stock name or identity JSON>]
 * Writes head-low.glb, head-medium.glb, head-high.glb, identity-source.bin (what a head for any identity is built
 * from at run time: src/core/head/build/identity-source.ts) and CREDITS.md. Running it twice gives identical files.
 * With `--identity`, the base mesh is first moved by MakeHuman's macro targets for that person (sex, age, ancestry),
 * and the head is cut where the base mesh's is, so that it has the default head's vertices and faces.
 */
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { gunzipSync } from 'node:zlib';
import {
  applyMacroTargets,
  checkIdentity,
  type MacroTarget,
  macroTargetWeights,
  parseMacroTarget,
  STOCK_IDENTITIES,
} from '../src/core/head/identity';
import { ETHNIC_TARGETS, writeIdentitySource } from '../src/core/head/build/identity-source';
import { writeGlb } from './model/glb';
import { buildHeadLevels, neckCutStart, sourceMesh, type LevelStats } from '../src/core/head/build/head-build';
import { parseObj } from '../src/core/head/build/obj';

/** The identity source's file name in the output folder. */
const IDENTITY_SOURCE_FILE = 'identity-source.bin';

const args = process.argv.slice(2);
const option = (name: string): string | undefined => {
  const i = args.indexOf(name);
  return i >= 0 ? args[i + 1] : undefined;
};
const outDir = resolve(option('--out') ?? 'public/models');
const sourceDir = resolve(args.find((a, i) => !a.startsWith('--') && !args[i - 1]?.startsWith('--')) ?? '../shared/assets/makehuman-hm08');
const identityArg = option('--identity');
const targetsDir = resolve(option('--targets') ?? '../shared/assets/makehuman-targets/macrodetails');

const objPath = join(sourceDir, 'base.obj');
let text: string;
try {
  text = readFileSync(objPath, 'utf8');
} catch {
  console.error(`Cannot read ${objPath}: pass the folder that holds the MakeHuman hm08 base.obj as the first argument.`);
  process.exit(1);
}
const obj = parseObj(text, 'base.obj');
const vertices = obj.positions.length / 3;
const targets = new Map(
  ETHNIC_TARGETS.map((target) => {
    const file = join(targetsDir, `${target}.target.gz`);
    let gz: Uint8Array;
    try {
      gz = readFileSync(file);
    } catch {
      console.error(`Cannot read ${file}: pass the folder of MakeHuman's macro targets with --targets.`);
      process.exit(1);
    }
    return [target, parseMacroTarget(gunzipSync(gz).toString('utf8'), vertices, file)];
  }),
);
// Written before the identity's targets move the base mesh: the source holds the base mesh and the targets.
const identitySource = writeIdentitySource(obj, targets);
let cutStart: number | undefined;
if (identityArg !== undefined) {
  const identity = STOCK_IDENTITIES[identityArg] ?? checkIdentity(JSON.parse(identityArg), '--identity');
  cutStart = neckCutStart(sourceMesh(obj));
  const weights = macroTargetWeights(identity);
  applyMacroTargets(
    obj.positions,
    weights.map(({ target, weight }) => ({ target: targets.get(target) as MacroTarget, weight })),
  );
  console.log(`identity ${JSON.stringify(identity)} from ${weights.map((t) => t.target).join(', ')}`);
}
const levels = buildHeadLevels(obj, cutStart);
mkdirSync(outDir, { recursive: true });
for (const level of levels) {
  const bytes = await writeGlb(level.root, level.sceneExtras);
  const file = join(outDir, `head-${level.stats.name}.glb`);
  writeFileSync(file, bytes);
  const s = level.stats;
  console.log(
    `${file}: ${s.skinVertices} skin vertices, ${s.renderVertices} render ` +
      `vertices, ${s.triangles} triangles, ${(bytes.length / 1e6).toFixed(2)} MB`,
  );
}
const identityFile = join(outDir, IDENTITY_SOURCE_FILE);
writeFileSync(identityFile, identitySource);
console.log(`${identityFile}: ${ETHNIC_TARGETS.length} targets, ${(identitySource.length / 1e6).toFixed(2)} MB`);
writeFileSync(
  join(outDir, 'CREDITS.md'),
  credits(
    levels.map((l) => l.stats),
    identitySource.length,
  ),
);

function credits(stats: LevelStats[], identitySourceBytes: number): string {
  const rows = stats.map(
    (s) =>
      `| \`head-${s.name}.glb\` | ${s.subdivisions} | ${s.skinVertices.toLocaleString('en-US')} | ` +
      `${s.renderVertices.toLocaleString('en-US')} | ${s.quads.toLocaleString('en-US')} | ${s.triangles.toLocaleString('en-US')} |`,
  );
  return `# Head models: credits and how they were made

The head is derived from the **MakeHuman hm08 base mesh**, released under
[CC0 1.0](https://creativecommons.org/publicdomain/zero/1.0/) by the MakeHuman copyright holders
(Data Collection AB, Joel Palmius, Jonas Hauquier; http://www.makehumancommunity.org). CC0 asks for nothing;
we credit MakeHuman because their work made this head possible. The files here are CC0 as well.

## How the files are made

\`npm run build:models -- <folder with base.obj>\` (\`scripts/build-head-model.ts\`) does, deterministically:

1. Reads the body surface (OBJ group \`body\`, all quads, closed) with its UVs.
2. Cuts the head and upper neck off along the quad edge loop that runs around the neck through the front-midline
   vertex nearest (0, 5.78, 0.69) dm: every kept face is a whole quad, the cut is one clean loop.
3. Subdivides the skin with Catmull-Clark (crease rules on the neck boundary, UVs interpolated per face) 0, 1 and 2 times.
4. Builds an eyeball (sclera, iris with pupil, clear cornea) of the base mesh's eye radius at each eye joint.
5. Builds the teeth procedurally (\`src/core/head/build/teeth.ts\`, no outside model): per arch sixteen crowns of typical
   adult sizes along an arch fitted to the base mesh's low-poly teeth, and a pink gum band round their necks, with
   occlusion baked into their vertex colours (darker toward the back of the mouth). The
   tongue is the base mesh's, subdivided once, lowered and narrowed a little. Lower teeth and tongue hang under a
   \`jaw\` node placed at the jaw hinge.
6. Records pivots (eye centres, lid joints, jaw hinge, chin, head, neck) as \`pivot-*\` nodes and in the scene's
   \`extras.softface.pivots\`.
7. Converts decimetres to metres (+y up, the face looks along +z, the subject's left is +x) and writes GLB.

## Resolutions

Skin vertices are distinct positions (what the simulation moves); render vertices also count the copies made
along UV seams.

| file | subdivisions | skin vertices | render vertices | quads | triangles |
| --- | --- | --- | --- | --- | --- |
${rows.join('\n')}

## Identity source

\`${IDENTITY_SOURCE_FILE}\` (${identitySourceBytes.toLocaleString('en-US')} bytes, CC0 as well) is what a head for any
identity (sex, age, ancestry) is built from at run time (\`src/core/head/build/identity-head.ts\`), the same way
\`--identity\` builds one here: of the base mesh \`base.obj\`, the faces, uvs and vertices of the cut head, and the
vertices of the joint cubes, the helper eye, teeth and tongue (with the tongue's faces); and their offsets in
MakeHuman's 24 macro targets \`{african,asian,caucasian}-{female,male}-{baby,child,young,old}.target.gz\` (CC0 1.0,
from MPFB2's \`src/mpfb/data/targets/macrodetails/\`). Its layout is documented in
\`src/core/head/build/identity-source.ts\`; its numbers read back exactly as the source files give them.
`;
}
