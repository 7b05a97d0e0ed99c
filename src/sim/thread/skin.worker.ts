/**
 * The skin worker: builds the topology and the solver, then solves a frame whenever the skin is awake and waits for
 * inputs while it sleeps; on the stepped clock (a recorder's) it solves only the frames each `run` message asks for. `shared` mode reads
 * inputs from and writes frames to SharedArrayBuffers; `transfer` mode
 * gets inputs as messages and passes two frame buffers back and forth.
 */
import { touchPages } from '../../core/solver/memory';
import { createBoard, PartnerTimeoutError } from '../../core/solver/partner-board';
import { PartnerLink } from '../../core/solver/partner-link';
import { ControlReader } from '../shared/control-reader';
import { contractionCapacity, controlLayout, controlViews, initControl, slotLayout } from '../shared/layout';
import type { FromWorker, InitMessage, RunMessage, ToWorker } from '../shared/protocol';
import { SharedOutput } from './shared-output';
import { SolverHost, type WarmUpPartner } from '../shared/solver-host';
import type { PartnerInit } from './partner.worker';
import { spawnPartnerWorker } from './spawn-partner-worker';
import { TransferOutput } from './transfer-output';

const scope = self as unknown as DedicatedWorkerGlobalScope;

let host: SolverHost | undefined;
/** `shared` mode. */
let reader: ControlReader | undefined;
let sharedOutput: SharedOutput | undefined;
/** `transfer` mode. */
let transferOutput: TransferOutput | undefined;

// Each frame is its own task (posted through a channel, which unlike setTimeout is not clamped), so messages are
// handled between frames.
const channel = new MessageChannel();
let scheduled = false;
/** `stepped` clock: the worker solves only the frames `run` messages ask for (see ClockMessage). */
let stepped = false;
/** The host's warm-up (see SolverHost.warmUp): a piece a turn while the skin sleeps, dropped once it solves for real. */
let warming: Generator<void, void, void> | null = null;
/** The partner worker, while one takes half of the passes. */
let partnerWorker: Worker | undefined;
/** Hands the partner worker the host's solver; null once done, or with no partner. */
let givePartnerTheSolver: (() => void) | null = null;
channel.port1.onmessage = tick;

scope.addEventListener('message', (event: MessageEvent<ToWorker>) => {
  const m = event.data;
  try {
    if (m.type === 'init') init(m);
    else if (m.type === 'inputs') {
      const muscles =
        m.targets && m.weights && m.normalWeights ? { targets: m.targets, weights: m.weights, normalWeights: m.normalWeights } : null;
      host?.apply(m.seq, muscles, m.parameters ?? null, m.contractions ?? null, m.headPose ?? null);
      schedule();
    } else if (m.type === 'rig') {
      host?.editRig(m.revision, m.edit);
      schedule();
    } else if (m.type === 'frame-buffer') transferOutput?.giveBack(m.buffer);
    else if (m.type === 'clock') {
      stepped = m.clock === 'stepped';
      schedule();
    } else if (m.type === 'run') run(m);
  } catch (error) {
    failed(error);
  }
});

function init(m: InitMessage): void {
  const h = new SolverHost({ ...m, memory: m.workers === 2 ? 'shared' : 'local' });
  const partner = m.workers === 2 ? startPartner(h) : undefined;
  const topology = h.topology;
  const rest = topology.rest.slice();
  const triangles = topology.triangles.slice();
  const base = { type: 'ready', vertexCount: topology.vertexCount, edgeCount: topology.restLength.length, rest, triangles } as const;
  const layout = slotLayout(m.renderPositions.length / 3, topology.vertexCount);
  host = h;
  warming = warmUp(h, partner);
  if (m.mode === 'shared') {
    const cLayout = controlLayout(topology.vertexCount, contractionCapacity(m.muscles.length));
    const control = new SharedArrayBuffer(cLayout.byteLength);
    const views = controlViews(control, cLayout);
    initControl(views, topology.rest, m.parameters);
    reader = new ControlReader(views, h);
    sharedOutput = new SharedOutput(layout);
    sharedOutput.publish(h);
    post({ ...base, control, output: sharedOutput.buffer }, [rest.buffer, triangles.buffer]);
  } else {
    transferOutput = new TransferOutput(layout, h, (buffer) => post({ type: 'frame', buffer }, [buffer]));
    const frame = transferOutput.first();
    post({ ...base, frame }, [rest.buffer, triangles.buffer, frame]);
  }
  schedule();
}

/**
 * Starts the partner worker: it takes the warm-up's throwaway solver first, so that its code is compiled before the
 * first expression, then the host's solver, which from then on hands it half of each heavy pass (the shape stays the
 * same). Should it fail to start, the solver goes on alone.
 */
function startPartner(h: SolverHost): WarmUpPartner {
  const board = createBoard();
  const partner = spawnPartnerWorker();
  partnerWorker = partner;
  const init = (message: PartnerInit): void => partner.postMessage(message);
  partner.addEventListener('message', (event: MessageEvent<PartnerInit['id']>) => {
    if (event.data === 'solver') h.solver.attachPartner(new PartnerLink(board));
  });
  partner.addEventListener('error', (event) => {
    event.preventDefault();
    h.solver.attachPartner(null);
    partnerWorker = undefined;
    givePartnerTheSolver = null;
    console.warn(`the solver's partner worker failed (${event.message || 'it could not be loaded'}); solving on one worker`);
  });
  givePartnerTheSolver = () => {
    givePartnerTheSolver = null;
    init({ id: 'solver', arrays: h.solver.partArrays(), board: board.words.buffer as SharedArrayBuffer });
  };
  return {
    start: (arrays, warmUpBoard) => init({ id: 'warm-up', arrays, board: warmUpBoard.words.buffer as SharedArrayBuffer }),
    finished: () => givePartnerTheSolver?.(),
  };
}

/**
 * The host's warm-up (see SolverHost.warmUp), after a turn that maps the pages of the shared output's slots: the first
 * frame of the first input wrote its fresh slot for 15 to 20 ms on the high head (docs/page-notes.md).
 */
function* warmUp(h: SolverHost, partner: WarmUpPartner | undefined): Generator<void, void, void> {
  if (sharedOutput) touchPages(sharedOutput.buffer);
  yield;
  yield* h.warmUp(partner);
}

/** Ends the warm-up, finished or cut short (its partner then takes the host's solver). */
function endWarmUp(): void {
  warming?.return();
  warming = null;
  givePartnerTheSolver?.();
}

function schedule(): void {
  if (scheduled || !host) return;
  scheduled = true;
  channel.port2.postMessage(null);
}

/** One turn: apply new inputs, solve a frame if awake and publish it, else warm up or wait for inputs. */
function tick(): void {
  scheduled = false;
  // A stepped clock solves in `run` alone; inputs wait there too, so that they land before the frames that follow.
  if (!host || stepped) return;
  try {
    reader?.poll();
    if (host.step()) {
      // A frame of no skin (an input that changed nothing at rest, as a script's reset at the page's start) leaves the
      // warm-up to go on: dropped there, it left the first expression cold (docs/page-notes.md, "Warm-up").
      if ((warming || givePartnerTheSolver) && host.solvedSkin) endWarmUp();
      sharedOutput?.publish(host);
      transferOutput?.publish();
      schedule();
    } else if (warming && !reader?.hasPending()) {
      if (warming.next().done) endWarmUp();
      schedule();
    } else {
      // `transfer` mode: the next inputs message schedules the next turn.
      reader?.waitForInput(schedule);
    }
  } catch (error) {
    failed(error);
  }
}

/**
 * Solves the frames a run asks for, once its input batch is applied. In `shared` mode the batch is read from the
 * control block, which the main thread may be writing again: the run then waits a turn and reads it again.
 */
function run(m: RunMessage): void {
  const h = host;
  if (!h) return;
  try {
    // The stepped clock leaves no turns for the warm-up: the partner takes the host's solver now.
    if (warming || givePartnerTheSolver) endWarmUp();
    reader?.poll();
    if (h.appliedInput < m.seq) {
      setTimeout(() => run(m), 0);
      return;
    }
    h.run(m.frames);
    sharedOutput?.publish(h);
    const ran = (): void => post({ type: 'ran', id: m.id, frames: h.solver.frames });
    // `transfer` mode: the frame goes first (perhaps once a slot comes back), so it has arrived when `ran` does.
    if (transferOutput) transferOutput.publish(ran);
    else ran();
  } catch (error) {
    failed(error);
  }
}

/**
 * A partner that stopped answering mid-job (it died, or its worker was ended) is ended for good and the solver goes on
 * alone from the skin as it is, which the next frames finish solving; any other error ends the worker's solving.
 */
function failed(error: unknown): void {
  if (!(error instanceof PartnerTimeoutError) || !partnerWorker || !host) {
    fail(error);
    return;
  }
  host.solver.attachPartner(null);
  partnerWorker.terminate();
  partnerWorker = undefined;
  givePartnerTheSolver = null;
  warming = null;
  console.warn(`${error.message}; solving on one worker`);
  schedule();
}

function fail(error: unknown): void {
  host = undefined;
  post({ type: 'error', message: error instanceof Error ? error.message : String(error) });
}

function post(message: FromWorker, transfer: Transferable[] = []): void {
  scope.postMessage(message, { transfer });
}
