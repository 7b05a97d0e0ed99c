/** What the webcam tracker reports, apart from the tracker (which the face loads only when tracking starts). */

/** What the tracker is doing (`face.trackingState()`). */
export interface TrackingState {
  /** Whether it runs. */
  on: boolean;
  /** Frames it read in the last second. */
  fps: number;
  /** Frames it read since it started (a reader of its Action Units can tell a new frame by this). */
  frames: number;
  /** From a frame's capture to its Action Units in the overlay, milliseconds (smoothed; 0 before the first). */
  latencyMs: number;
  /**
   * When the camera frame the Action Units come from was captured, on the page's clock (`performance.now()`; the
   * time it was shown where the browser does not say): for matching them with what the camera saw.
   */
  capturedAt: number;
  /** The face mesh's own time per frame, from handing it the frame to its landmarks, milliseconds (smoothed). */
  processMs: number;
  /** Whether the viewer's neutral face is known. */
  calibrated: boolean;
  /** Whether the last frame had a face in it. */
  face: boolean;
  /** What went wrong last, or what to do ("no face in view"); empty when all is well. */
  message: string;
}

/** The state of a tracker that is off and has read nothing. */
export function idleTrackingState(): TrackingState {
  return { on: false, fps: 0, frames: 0, latencyMs: 0, processMs: 0, capturedAt: 0, calibrated: false, face: false, message: '' };
}
