/** The package's entry: `import { createFace } from 'softface'`. The `<soft-face>` element is in `softface/element`. */
export { createFace, type Face } from './create-face';
export { FACE_DEFAULTS, RESOLUTIONS, SOLVER_CHOICES, type FaceOptions, type Resolution, type SolverChoice } from '../face/face-options';
export type { ExpressionEntries } from '../face/expression-hash';
export type { GLTFExportOptions, GLTFExportProgress } from '../face/gltf-export-options';
export type { EyeStats, FaceChange, FaceChangeListener, FaceStats, MuscleDisplay, SkinSnapshot, TimelineState } from '../face/face-handle';
export type { Easing, Timeline, TimelineAction, TimelineKey, TimelineTrack } from '../core/timeline/timeline';
export type { TimelineError } from '../core/timeline/timeline-schema';
export type { ActionUnitListing, PresetListing } from '../core/expression/facs';
export { EYE_SIMULATION_DEFAULTS, type EyeSimulationOptions } from '../core/expression/eye-simulation';
export type { SkinParameters } from '../core/solver/skin-parameters';
export type { Rig } from '../core/rig/rig-types';
export type { RenderTiming } from '../render/render-timing';
export type { HairPartSnapshot, HairSnapshot } from '../render/hair-view';
export type { AppearanceOptions, CameraOptions, LightOptions, RenderOptions } from '../render/view-options';
export { VIDEO_DEFAULTS, type VideoFormat, type VideoOptions } from '../face/video-options';
export type { HeadDescription, HeadFile, HeadSource, LoadHeadOptions } from '../face/head-loader';
export { LANDMARK_NAMES, type LandmarkName, type Landmarks } from '../core/head/landmarks';
