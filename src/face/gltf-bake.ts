import { planTargets, timelineWeights } from '../core/expression/morph-export';
import type { MorphShape } from '../render/gltf-export';
import type { SkinSimulation } from '../sim/main/skin-simulation';
import type { FaceExpression } from './face-expression';
import type { FaceEyes, FaceGLTFWriter, FaceTimeline } from './face-ports';
import type { GLTFExportOptions } from './gltf-export-options';

/** What baking a glTF export needs from the face (the handle gives its parts). */
export interface BakePorts {
  expression: FaceExpression;
  simulation: Pick<SkinSimulation, 'settle' | 'readRender'>;
  player: FaceTimeline;
  writer: FaceGLTFWriter;
  eyes: FaceEyes | undefined;
  /** The rig's preset names. */
  presets: readonly string[];
  /** Tells the face's listeners that the expression changed. */
  expressionChanged(): void;
  /** Gives the editor's preview contraction back to its muscle. */
  restorePreview(): void;
  /** Whether the face is still there (an export outlives a `dispose` only to end). */
  alive(): boolean;
  /** Called once the options and targets are known to be good: throws if another export is under way. */
  begin(): void;
  /** Called when the targets are solved or the export failed after `begin`. */
  end(): void;
}

/**
 * Bakes and writes a glTF export (see FaceHandle.exportGLTF): each target asked for is solved from the settled
 * neutral face on its own at 1 and read as a morph shape, the timeline's weights become a clip, and the writer makes
 * the file. Nothing but the target moves the skin meanwhile (the timeline paused, the eye simulation, overlay and
 * preview off); afterwards the face gets all of them back. `o` has been checked (checkExportOptions).
 */
export async function bakeGLTF(ports: BakePorts, o: Required<GLTFExportOptions>): Promise<Blob> {
  const { expression, simulation, player, writer, eyes } = ports;
  const loaded = player.timeline();
  if (o.timeline === true && !loaded)
    throw new Error('exportGLTF: timeline: no timeline is loaded (setTimeline first, or leave timeline out)');
  const timeline = o.timeline === false ? null : loaded;
  const targets = planTargets(o.actionUnits, o.presets, ports.presets, timeline);
  const weights = timeline ? timelineWeights(timeline, targets, o.fps) : null;
  o.signal?.throwIfAborted();
  ports.begin();
  const saved = {
    expression: {
      actionUnits: expression.getActionUnits(),
      presets: Object.fromEntries(expression.listPresets().map((p) => [p.name, p.weight])),
    },
    overlay: expression.getOverlay(),
    eyes: eyes?.enabled() ?? false,
    playing: player.state().playing,
  };
  const settle = async (): Promise<void> => {
    o.signal?.throwIfAborted();
    await simulation.settle(o.settleTimeoutMs);
    o.signal?.throwIfAborted();
  };
  const show = async (target: { kind: string; id: string } | null): Promise<void> => {
    const one = target ? { [target.id]: 1 } : {};
    expression.set(target?.kind === 'preset' ? { actionUnits: {}, presets: one } : { actionUnits: one, presets: {} }, 'exportGLTF');
    ports.expressionChanged();
    await settle();
  };
  const shapes: MorphShape[] = [];
  try {
    // Nothing but the target may move the skin: no timeline frames, blinks, overlay or editor preview.
    if (saved.playing) player.pause();
    eyes?.setEnabled(false);
    expression.clearOverlay();
    expression.setPreview(null);
    await show(null);
    for (const [i, target] of targets.entries()) {
      o.onProgress?.({ done: i, total: targets.length, target: target.name });
      await show(target);
      const positions = new Float32Array(3 * writer.vertexCount);
      const normals = new Float32Array(3 * writer.vertexCount);
      simulation.readRender(positions, normals);
      shapes.push({ name: target.name, positions, normals, jaw: writer.jawPose() });
      // Back to neutral, so that every target starts from the same settled face.
      await show(null);
    }
  } finally {
    ports.end();
    if (ports.alive()) {
      expression.set(saved.expression, 'exportGLTF');
      const ids = Object.keys(saved.overlay);
      expression.setOverlay(
        ids,
        ids.map((id) => saved.overlay[id]),
      );
      ports.restorePreview();
      eyes?.setEnabled(saved.eyes);
      if (saved.playing) player.play();
      ports.expressionChanged();
    }
  }
  o.onProgress?.({ done: targets.length, total: targets.length, target: null });
  const clip = weights ? { name: 'timeline', ...weights } : null;
  const data = await writer.write(shapes, clip, { binary: o.binary });
  return data instanceof ArrayBuffer
    ? new Blob([data], { type: 'model/gltf-binary' })
    : new Blob([JSON.stringify(data)], { type: 'model/gltf+json' });
}
