import { checkNumber, refusal } from '../core/check';
import type { Timeline } from '../core/timeline/timeline';
import { parseTimeline, parseTimelineText } from '../core/timeline/timeline-schema';
import type { FaceParts } from './face-parts';
import type { TimelineState } from './face-ports';

/** The face's timeline as a media player: load, play, pause, seek. */
export class TimelineController {
  constructor(private readonly parts: FaceParts) {}

  /**
   * Loads a timeline (a timeline document as JSON text or an object; see docs/timeline.md), paused at 0 with
   * the face set to its start. It is checked whole first: a problem throws a `TimelineError` naming its path
   * (`setTimeline: tracks.AU12L.keys[2].time: ...`; `source`, such as a file's name, replaces `setTimeline` there)
   * and changes nothing. While it plays or is sought it sets the sliders and presets it names; the rest stay.
   */
  setTimeline(timeline: string | object, source = 'setTimeline'): void {
    if (typeof source !== 'string') throw refusal('setTimeline', 'source', 'a string', source);
    const player = this.parts.timeline();
    const options = {
      presets: this.parts
        .expressed()
        .listPresets()
        .map((p) => p.name),
    };
    const parsed = typeof timeline === 'string' ? parseTimelineText(timeline, source, options) : parseTimeline(timeline, source, options);
    player.set(parsed);
    this.parts.emit('timeline');
  }

  /** A copy of the loaded timeline document, or null. */
  getTimeline(): Timeline | null {
    const t = this.parts.timeline().timeline();
    return t ? structuredClone(t) : null;
  }

  /** Unloads the timeline; the face keeps the values it had last. */
  clearTimeline(): void {
    this.parts.timeline().set(null);
    this.parts.emit('timeline');
  }

  /** Plays the timeline from its clock (from the start again after a timeline without loop has ended). */
  play(): void {
    const player = this.parts.timeline();
    if (!player.timeline()) throw new Error('play: no timeline is loaded (setTimeline first)');
    player.play();
    this.parts.emit('timeline');
  }

  /** Pauses the timeline: the face holds, and the sliders are the user's again until the next play or seek. */
  pause(): void {
    this.parts.timeline().pause();
    this.parts.emit('timeline');
  }

  /**
   * Moves the timeline's clock to `seconds` (wrapped with loop, clamped to 0..duration without) and sets the face to
   * the values there, playing or not. A non-finite time throws and changes nothing.
   */
  seek(seconds: number): void {
    const player = this.parts.timeline();
    checkNumber('seek', '', seconds);
    if (!player.timeline()) throw new Error('seek: no timeline is loaded (setTimeline first)');
    player.seek(seconds);
    this.parts.emit('timeline');
  }

  /** Whether a timeline is loaded and plays, its clock and duration (seconds) and loop flag. */
  timelineState(): TimelineState {
    return this.parts.timeline().state();
  }
}

/** The handle's methods that TimelineController answers. */
export const TIMELINE_METHODS = ['setTimeline', 'getTimeline', 'clearTimeline', 'play', 'pause', 'seek', 'timelineState'] as const;
