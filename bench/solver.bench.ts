/**
 * Solver benchmark: `npm run bench`. Prints three tables and writes bench-results/solver.json.
 *
 * 1. The loops: for each head resolution, length-iteration count and thread count, solves frames of a held
 *    expression (brows raised, one mouth corner pulled) over the whole mesh and reports the median and 90th-percentile frame time, the
 *    nanoseconds per edge projection and the milliseconds for normals, bending and orientation.
 * 2. The rig: the head as the page simulates it (solver host, colliders, default rig; see
 *    tests/fixtures/head-simulation.ts) from rest to a held expression, with the active region: its size, the median
 *    frame time and nanoseconds per edge projection, and the frames and milliseconds until the shape is within 2 % of
 *    its final shape and until the solver sleeps.
 * 3. A slider dragged: the same head from rest to an expression over DRAG_FRAMES frames, an input before each (as a
 *    page applies the newest input before each frame while a slider moves): the median time an input takes to apply
 *    (the rig's targets and the constraint lists) and a frame to solve.
 */
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { cpus, platform } from 'node:os';
import { NodeIO } from '@gltf-transform/core';
import { SkinSolver } from '../src/core/solver/solver';
import { createSolverBuffers } from '../src/core/solver/solver-buffers';
import { buildTopology, type SkinTopology } from '../src/core/solver/topology';
import { loadHeadSimulation, type Resolution } from '../tests/fixtures/head-simulation';
import { startPartnerThread } from '../tests/fixtures/partner';
import { largestDistance, median, NEAR_FINAL, quantile } from './shape-measures';

const RESOLUTIONS = [
  { name: 'low', frames: 120 },
  { name: 'medium', frames: 60 },
  { name: 'high', frames: 20 },
] as const;
/**
 * Length iterations, solver threads (two: a partner thread, see SolverPartner) and the edges' loops (the WebAssembly
 * kernel, wasm-lengths.ts, or the JavaScript loops it stands in for) of the loop rows.
 */
const LOOP_CASES = [
  { lengthIterations: 3, workers: 1, lengths: 'wasm' },
  { lengthIterations: 3, workers: 1, lengths: 'js' },
  { lengthIterations: 3, workers: 2, lengths: 'wasm' },
  { lengthIterations: 3, workers: 2, lengths: 'js' },
  { lengthIterations: 10, workers: 1, lengths: 'wasm' },
] as const;
const WARMUP_FRAMES = 5;

async function loadSkin(name: string): Promise<SkinTopology> {
  const doc = await new NodeIO().readBinary(new Uint8Array(readFileSync(`public/models/head-${name}.glb`)));
  const prim = doc
    .getRoot()
    .listMeshes()
    .find((m) => m.getName() === 'skin')!
    .listPrimitives()[0];
  return buildTopology(prim.getAttribute('POSITION')!.getArray()!, prim.getIndices()!.getArray()!);
}

/** Muscle targets of a typical expression: forehead pulled toward the brows, the left mouth corner up and out. */
function expression(t: SkinTopology): { vertices: number[]; targets: number[] } {
  const vertices: number[] = [];
  const targets: number[] = [];
  for (let v = 0; v < t.vertexCount; v++) {
    const [x, y, z] = [t.rest[3 * v], t.rest[3 * v + 1], t.rest[3 * v + 2]];
    if (y > 0.735 && y < 0.815 && Math.abs(x) < 0.045 && t.restNormals[3 * v + 2] > 0.5) {
      vertices.push(v);
      targets.push(x, 0.745 + (y - 0.745) * 0.88, z);
    } else if (Math.hypot(x - 0.025, y - 0.668, z - 0.135) < 0.012) {
      vertices.push(v);
      targets.push(x + 0.004, y + 0.006, z - 0.002);
    }
  }
  return { vertices, targets };
}

interface Row {
  resolution: string;
  vertices: number;
  edges: number;
  lengthIterations: number;
  positionIterations: number;
  workers: number;
  /** What projects the edges: the WebAssembly kernel or the JavaScript loops. */
  lengths: string;
  frames: number;
  medianFrameMs: number;
  p90FrameMs: number;
  nsPerEdgeProjection: number;
  medianNormalsMs: number;
  medianBendingMs: number;
  medianOrientationMs: number;
}

const rows: Row[] = [];
for (const { name, frames } of RESOLUTIONS) {
  const topology = await loadSkin(name);
  const { vertices, targets } = expression(topology);
  for (const { lengthIterations, workers, lengths: kernel } of LOOP_CASES) {
    // The whole mesh, as before the active region: these rows measure the loops.
    const buffers = createSolverBuffers(topology, 'shared', kernel === 'wasm');
    const solver = new SkinSolver(topology, { parameters: { lengthIterations }, buffers, activeRegion: false, memory: 'shared' });
    const partner = workers === 2 ? await startPartnerThread(solver) : null;
    solver.setMuscleTargets(vertices, targets, 1, 0);
    const total: number[] = [];
    const lengths: number[] = [];
    const normals: number[] = [];
    const bending: number[] = [];
    const orientation: number[] = [];
    for (let f = 0; f < WARMUP_FRAMES + frames; f++) {
      solver.wake(); // keep solving: measure the cost of a frame, not of a sleeping solver
      solver.step();
      if (f < WARMUP_FRAMES) continue;
      total.push(solver.timings.total);
      lengths.push(solver.timings.lengths);
      normals.push(solver.timings.normals);
      bending.push(solver.timings.bending);
      orientation.push(solver.timings.orientation);
    }
    await partner?.stop();
    const p = solver.parameters();
    const sorted = [...total].sort((a, b) => a - b);
    const projections = topology.restLength.length * p.lengthIterations * p.positionIterations;
    rows.push({
      resolution: name,
      vertices: topology.vertexCount,
      edges: topology.restLength.length,
      lengthIterations,
      positionIterations: p.positionIterations,
      workers,
      lengths: kernel,
      frames,
      medianFrameMs: quantile(sorted, 0.5),
      p90FrameMs: quantile(sorted, 0.9),
      nsPerEdgeProjection: (median(lengths) * 1e6) / projections,
      medianNormalsMs: median(normals),
      medianBendingMs: median(bending),
      medianOrientationMs: median(orientation),
    });
  }
}

/** The rig rows: an Action Unit or a preset at full intensity, from rest, on a head resolution. */
const RIG_CASES: { resolution: Resolution; expression: string; workers: 1 | 2; maxFrames: number }[] = [
  { resolution: 'low', expression: 'happiness', workers: 1, maxFrames: 1500 },
  { resolution: 'low', expression: 'happiness', workers: 2, maxFrames: 1500 },
  { resolution: 'medium', expression: 'AU12', workers: 1, maxFrames: 1500 },
  { resolution: 'medium', expression: 'AU12', workers: 2, maxFrames: 1500 },
  { resolution: 'medium', expression: 'happiness', workers: 1, maxFrames: 1500 },
  { resolution: 'medium', expression: 'happiness', workers: 2, maxFrames: 1500 },
  { resolution: 'high', expression: 'happiness', workers: 1, maxFrames: 1500 },
  { resolution: 'high', expression: 'happiness', workers: 2, maxFrames: 1500 },
];
/** The dragged sliders: an Action Unit or a preset moved from 0 to full intensity, one input per frame. */
const DRAG_CASES: { resolution: Resolution; expression: string }[] = [
  { resolution: 'medium', expression: 'AU12' },
  { resolution: 'medium', expression: 'happiness' },
  { resolution: 'medium', expression: 'thesis-laughing' },
];
/** Frames (and inputs) a drag takes from 0 to full intensity; the first two drags warm up, the third is timed. */
const DRAG_FRAMES = 60;
const DRAG_RUNS = 3;

interface RigRow {
  resolution: string;
  expression: string;
  workers: number;
  vertices: number;
  /** Vertices in the active region at the end, and at most during the run. */
  activeVertices: number;
  peakActiveVertices: number;
  framesSolved: number;
  medianFrameMs: number;
  p90FrameMs: number;
  nsPerEdgeProjection: number;
  framesToNearFinal: number;
  msToNearFinal: number;
  /** Frames and milliseconds until the solver slept; null if it still solved after `maxFrames`. */
  framesToSleep: number | null;
  msToSleep: number | null;
  maxFrames: number;
}

/**
 * Starts `expression` at full intensity from rest on a fresh head simulation, with a partner thread if `workers` is 2,
 * after the host's warm-up (which the partner serves too), as the page's worker runs it before the first input.
 */
async function startExpression(resolution: Resolution, expression: string, workers: 1 | 2 = 1) {
  const sim = await loadHeadSimulation(resolution, {}, { memory: 'shared' });
  if (workers === 1) for (const _ of sim.host.warmUp());
  const partner = workers === 2 ? await startPartnerThread(sim.host.solver, sim.host) : null;
  if (/^AU\d/.test(expression)) sim.expression.setActionUnit(expression, 1);
  else sim.expression.applyPreset(expression, 1);
  sim.apply();
  return { ...sim, partner };
}

const rigRows: RigRow[] = [];
for (const { resolution, expression: name, workers, maxFrames } of RIG_CASES) {
  // First run: until the solver sleeps (or maxFrames), timing every frame.
  let sim = await startExpression(resolution, name, workers);
  const solver = sim.host.solver;
  const start = Float32Array.from(solver.buffers.positions);
  const p = solver.parameters();
  const total: number[] = [];
  const nsPerEdge: number[] = [];
  let peak = 0;
  while (total.length < maxFrames && sim.host.step()) {
    total.push(solver.timings.total);
    nsPerEdge.push((solver.timings.lengths * 1e6) / (solver.activeEdgeCount * p.lengthIterations * p.positionIterations));
    peak = Math.max(peak, solver.activeVertexCount);
  }
  await sim.partner?.stop();
  const slept = solver.sleeping;
  const final = Float32Array.from(solver.buffers.positions);
  const activeVertices = solver.activeVertexCount;
  // Second run, on one thread (the solver is deterministic, and two threads give its shapes): the first frame within
  // NEAR_FINAL of the final shape; its time is that of the first run's frames.
  const tolerance = NEAR_FINAL * largestDistance(start, final);
  sim = await startExpression(resolution, name);
  let near = 0;
  while (near < total.length && largestDistance(sim.host.solver.buffers.positions, final) > tolerance) {
    sim.host.step();
    near++;
  }
  const sum = (xs: number[], count: number): number => xs.slice(0, count).reduce((a, b) => a + b, 0);
  const sorted = [...total].sort((a, b) => a - b);
  rigRows.push({
    resolution,
    expression: name,
    workers,
    vertices: sim.host.topology.vertexCount,
    activeVertices,
    peakActiveVertices: peak,
    framesSolved: total.length,
    medianFrameMs: quantile(sorted, 0.5),
    p90FrameMs: quantile(sorted, 0.9),
    nsPerEdgeProjection: median(nsPerEdge),
    framesToNearFinal: near,
    msToNearFinal: sum(total, near),
    framesToSleep: slept ? total.length : null,
    msToSleep: slept ? sum(total, total.length) : null,
    maxFrames,
  });
}

/** A slider dragged (see the file's comment): per input, the time to apply it and to solve the frame after it. */
interface DragRow {
  resolution: string;
  expression: string;
  inputs: number;
  medianApplyMs: number;
  medianFrameMs: number;
  /** Frames a second while the slider moves, if the solver did nothing else: 1000 / (apply + frame). */
  framesPerSecond: number;
}
const dragRows: DragRow[] = [];
for (const { resolution, expression: name } of DRAG_CASES) {
  const sim = await loadHeadSimulation(resolution);
  const contractions = new Float32Array(sim.rig.muscles.length);
  let seq = 0;
  const apply: number[] = [];
  const frame: number[] = [];
  for (let run = 0; run < DRAG_RUNS; run++) {
    apply.length = frame.length = 0;
    for (let f = 1; f <= DRAG_FRAMES; f++) {
      if (/^AU\d/.test(name)) sim.expression.setActionUnit(name, f / DRAG_FRAMES);
      else sim.expression.applyPreset(name, f / DRAG_FRAMES);
      sim.expression.muscleContractions(sim.rig, contractions);
      const t0 = performance.now();
      sim.host.apply(++seq, null, null, contractions);
      const t1 = performance.now();
      sim.host.step();
      apply.push(t1 - t0);
      frame.push(performance.now() - t1);
    }
    // Back to rest for the next run.
    sim.expression.reset();
    sim.host.apply(++seq, null, null, sim.expression.muscleContractions(sim.rig, contractions));
    while (sim.host.step());
  }
  const medianApplyMs = median(apply);
  const medianFrameMs = median(frame);
  dragRows.push({
    resolution,
    expression: name,
    inputs: DRAG_FRAMES,
    medianApplyMs,
    medianFrameMs,
    framesPerSecond: 1000 / (medianApplyMs + medianFrameMs),
  });
}

const machine = { cpu: cpus()[0]?.model ?? 'unknown', cores: cpus().length, platform: platform(), node: process.version };
const header =
  '| head | vertices | edges | length iterations | workers | edge loops | median ms/frame | ' +
  'p90 ms/frame | ns/edge projection | normals ms | bending ms | orientation ms |';
const lines = rows.map(
  (r) =>
    `| ${[
      r.resolution,
      r.vertices.toLocaleString('en-US'),
      r.edges.toLocaleString('en-US'),
      r.lengthIterations,
      r.workers,
      r.lengths,
      r.medianFrameMs.toFixed(1),
      r.p90FrameMs.toFixed(1),
      r.nsPerEdgeProjection.toFixed(1),
      r.medianNormalsMs.toFixed(2),
      r.medianBendingMs.toFixed(2),
      r.medianOrientationMs.toFixed(2),
    ].join(' | ')} |`,
);
console.log(
  `Solver benchmark on ${machine.cpu}, ${machine.cores} cores, Node ${machine.node} (${rows[0].positionIterations} position iterations)\n`,
);
console.log('Loops (whole mesh, a held expression):\n');
console.log([header, header.replace(/[^|]+/g, ' --- '), ...lines].join('\n'));
const rigHeader =
  '| head | expression | workers | active vertices | median ms/frame | p90 ms/frame ' +
  '| ns/edge projection | frames to 2 % | ms to 2 % | frames to sleep | ms to sleep |';
const count = (n: number): string => n.toLocaleString('en-US');
const rigLines = rigRows.map(
  (r) =>
    `| ${[
      r.resolution,
      r.expression,
      r.workers,
      `${count(r.activeVertices)} of ${count(r.vertices)}`,
      r.medianFrameMs.toFixed(1),
      r.p90FrameMs.toFixed(1),
      r.nsPerEdgeProjection.toFixed(1),
      r.framesToNearFinal,
      count(Math.round(r.msToNearFinal)),
      r.framesToSleep ?? `> ${r.maxFrames}`,
      r.msToSleep === null ? '-' : count(Math.round(r.msToSleep)),
    ].join(' | ')} |`,
);
console.log('\nThe rig (solver host, colliders, default rig, active region), from rest to an expression at full intensity:\n');
console.log([rigHeader, rigHeader.replace(/[^|]+/g, ' --- '), ...rigLines].join('\n'));
const dragHeader = '| head | expression | inputs | median ms to apply an input | median ms/frame | frames a second |';
const dragLines = dragRows.map(
  (r) =>
    `| ${r.resolution} | ${r.expression} | ${r.inputs} | ${r.medianApplyMs.toFixed(1)} ` +
    `| ${r.medianFrameMs.toFixed(1)} | ${Math.round(r.framesPerSecond)} |`,
);
console.log(`\nA slider dragged from 0 to full intensity over ${DRAG_FRAMES} frames, an input before each:\n`);
console.log([dragHeader, dragHeader.replace(/[^|]+/g, ' --- '), ...dragLines].join('\n'));
mkdirSync('bench-results', { recursive: true });
writeFileSync(
  'bench-results/solver.json',
  `${JSON.stringify({ machine, date: new Date().toISOString(), rows, rigRows, dragRows }, null, 2)}\n`,
);
console.log('\nwrote bench-results/solver.json');
