// Runs the browser tests several times in a row with a CPU-heavy process beside them, as a busy machine would: the
// tests must not depend on how fast the machine is. Usage: node scripts/e2e-under-load.mjs [runs=3] [playwright args]
// (build first: `npx vite build && npm run build:lib`). Prints each run's result and exits non-zero if any failed.
import { spawn, spawnSync } from 'node:child_process';

const runs = Number(process.argv[2] ?? 3);
const extra = process.argv.slice(3);
// One core kept busy the whole time: a loop that never yields.
const load = spawn(process.execPath, ['-e', 'for (;;) {}'], { stdio: 'ignore' });
const results = [];
try {
  for (let run = 1; run <= runs; run++) {
    const started = Date.now();
    const r = spawnSync('npx', ['playwright', 'test', '--reporter=line', ...extra], { stdio: 'inherit' });
    const minutes = ((Date.now() - started) / 60_000).toFixed(1);
    results.push(`run ${run}: ${r.status === 0 ? 'passed' : 'FAILED'} in ${minutes} min`);
    console.log(results[results.length - 1]);
  }
} finally {
  load.kill();
}
console.log(`with a busy core beside them: ${results.join('; ')}`);
process.exit(results.every((r) => r.includes('passed')) ? 0 : 1);
