/**
 * Solver benchmark: `npm run bench`. For each head resolution and two length-iteration counts, solves frames of a
 * held expression (brows raised, one mouth corner pulled) and reports the median and 90th-percentile frame time, the
 * nanoseconds per edge projection and the milliseconds for normals, bending and orientation. Prints a table and writes bench-results/solver.json.
 */
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { cpus, platform } from 'node:os';
import { NodeIO } from '@gltf-transform/core';
import { SkinSolver } from '../src/core/solver';
import { buildTopology, type SkinTopology } from '../src/core/topology';

const RESOLUTIONS = [
  { name: 'low', frames: 120 },
  { name: 'medium', frames: 60 },
  { name: 'high', frames: 20 },
] as const;
const LENGTH_ITERATIONS = [3, 10];
const WARMUP_FRAMES = 5;

async function loadSkin(name: string): Promise<SkinTopology> {
  const doc = await new NodeIO().readBinary(new Uint8Array(readFileSync(`public/models/head-${name}.glb`)));
  const prim = doc.getRoot().listMeshes().find((m) => m.getName() === 'skin')!.listPrimitives()[0];
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

const quantile = (sorted: number[], q: number): number => sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))];
const median = (xs: number[]): number => quantile([...xs].sort((a, b) => a - b), 0.5);

interface Row {
  resolution: string;
  vertices: number;
  edges: number;
  lengthIterations: number;
  positionIterations: number;
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
  for (const lengthIterations of LENGTH_ITERATIONS) {
    const solver = new SkinSolver(topology, { parameters: { lengthIterations } });
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
    const p = solver.parameters();
    const sorted = [...total].sort((a, b) => a - b);
    const projections = topology.restLength.length * p.lengthIterations * p.positionIterations;
    rows.push({
      resolution: name,
      vertices: topology.vertexCount,
      edges: topology.restLength.length,
      lengthIterations,
      positionIterations: p.positionIterations,
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

const machine = { cpu: cpus()[0]?.model ?? 'unknown', cores: cpus().length, platform: platform(), node: process.version };
const header = '| head | vertices | edges | length iterations | median ms/frame | p90 ms/frame | ns/edge projection | normals ms | bending ms | orientation ms |';
const lines = rows.map(
  (r) =>
    `| ${r.resolution} | ${r.vertices.toLocaleString('en-US')} | ${r.edges.toLocaleString('en-US')} | ${r.lengthIterations} | ${r.medianFrameMs.toFixed(1)} | ${r.p90FrameMs.toFixed(1)} | ${r.nsPerEdgeProjection.toFixed(1)} | ${r.medianNormalsMs.toFixed(2)} | ${r.medianBendingMs.toFixed(2)} | ${r.medianOrientationMs.toFixed(2)} |`,
);
console.log(`Solver benchmark on ${machine.cpu}, ${machine.cores} cores, Node ${machine.node} (one thread; ${rows[0].positionIterations} position iterations)\n`);
console.log([header, header.replace(/[^|]+/g, ' --- '), ...lines].join('\n'));
mkdirSync('bench-results', { recursive: true });
writeFileSync('bench-results/solver.json', JSON.stringify({ machine, date: new Date().toISOString(), rows }, null, 2) + '\n');
console.log('\nwrote bench-results/solver.json');
