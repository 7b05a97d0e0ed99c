/**
 * The package's entry: `import { createFace } from 'softface'` makes a face in a container and returns its handle
 * ({@link FaceHandle}). The `<soft-face>` element is in `softface/element`.
 *
 * @module softface
 */
export { createFace, type Face } from './create-face';
export type { FaceHandle } from '../face/face-handle';
export type { SkinSimulationStats } from '../face/face-ports';
export type { SolverMode } from '../face/face-options';
export type { ConstraintCounts } from '../core/solver/solver-buffers';
export type { BrushOptions, EditorState, GizmoMode, GizmoPart } from '../face/editor-session';
export type { LandmarkGuideState } from '../face/landmark-guide';
export type { MaterialDescription, SubsurfaceOptions } from '../render/materials';
export type { UpdateOptions } from '../core/rig/rig-document';
export { FACE_DEFAULTS, RESOLUTIONS, SOLVER_CHOICES, type FaceOptions, type Resolution, type SolverChoice } from '../face/face-options';
export type { ExpressionEntries } from '../face/expression-hash';
/** The URL-hash text form of a face's state (expression, a short timeline, appearance), as the app keeps it in its links. */
export {
  appearanceChanges,
  decodeAppearance,
  decodeExpression,
  decodeFACS,
  decodeIdentity,
  decodeTimeline,
  encodeExpression,
  MAX_HASH_TIMELINE_CHARS,
  type HashAppearance,
  type HashExpression,
} from '../face/expression-hash';
export type { GLTFExportOptions, GLTFExportProgress } from '../face/gltf-export-options';
export type { EyeStats, FaceChange, FaceChangeListener, FaceStats, MuscleDisplay, SkinSnapshot, TimelineState } from '../face/face-handle';
export type { Easing, Timeline, TimelineAction, TimelineKey, TimelineTrack } from '../core/timeline/timeline';
export type { TimelineError } from '../core/timeline/timeline-schema';
export type { ActionUnitListing, PresetListing, SideCode } from '../core/expression/facs';
export type { HeadPose } from '../core/expression/head-pose';
export { EMOTIONS, type Emotion, type EmotionVariant } from '../core/expression/emfacs';
export { ARKIT_BLENDSHAPES, type ARKitBlendshape } from '../core/expression/arkit';
export type { TrackingOptions, TrackingState } from '../face/face-tracker';
export { EYE_SIMULATION_DEFAULTS, type EyeSimulationOptions } from '../core/expression/eye-simulation';
export type { SkinParameters } from '../core/solver/skin-parameters';
export type {
  ActionUnitDefinition,
  ActionUnitMuscle,
  BrushSphere,
  EulerDegrees,
  JawMuscle,
  LidMuscle,
  LinearMuscle,
  Muscle,
  MuscleBrush,
  MuscleSide,
  PresetDefinition,
  Rig,
  SphincterMuscle,
  Vec3,
} from '../core/rig/rig-types';
export type { RigProblem } from '../core/rig/rig-problems';
export { identityText, STOCK_IDENTITIES, type Ancestry, type Identity, type NamedIdentity } from '../core/head/identity';
export type { RenderTiming } from '../render/render-timing';
export type { HairPartSnapshot, HairSnapshot } from '../render/hair-view';
export {
  ANTIALIAS_CHOICES,
  APPEARANCE_DEFAULTS,
  type Antialias,
  type AppearanceOptions,
  type CameraOptions,
  type LightOptions,
  type RenderOptions,
} from '../render/view-options';
export { VIDEO_DEFAULTS, type VideoFormat, type VideoOptions } from '../face/video-options';
export type { HeadDescription, HeadFile, HeadSource, LoadHeadOptions } from '../face/head-loader';
export type { PartSources } from '../render/head-import';
export { LANDMARK_NAMES, type LandmarkName, type Landmarks } from '../core/head/landmarks';
