import type { NamedIdentity } from '../core/head/identity';
import type { Landmarks } from '../core/head/landmarks';
import type { Rig } from '../core/rig/rig-types';
import type { HeadView } from '../render/head-view';
import { loadHeadModel, type HeadModel } from '../render/head-model';
import { IdentityBuilder } from '../sim/main/identity-builder';
import { assetUrl } from './face-assets';
import type { FaceChange } from './face-handle';
import type { FaceOptions } from './face-options';
import type { FaceHeads } from './face-ports';
import {
  checkLoadHeadOptions,
  MissingLandmarksError,
  prepareHead,
  readHeadFiles,
  type HeadDescription,
  type HeadSource,
  type LoadHeadOptions,
  type PreparedHead,
} from './head-loader';
import type { HeadStore } from './head-store';
import { prepareIdentityHead } from './identity-head';
import { LandmarkGuide } from './landmark-guide';

/** What a face lends its head switch: its options and rig, where its heads come from, and how it shows one. */
export interface HeadHost {
  readonly options: Required<FaceOptions>;
  readonly view: HeadView;
  original(): Rig;
  /** The default head's model file, and the one whose eyes and teeth a loaded head borrows. */
  modelUrl(): string;
  partsUrl(): string;
  headStore(): HeadStore | undefined;
  shownHead(): HeadModel | undefined;
  describeHead(): HeadDescription;
  /** Shows a head in place of the current one (see EmbeddedFace.mount). */
  mount(head: HeadModel, prepared: PreparedHead | undefined, how: { started?: number; fresh?: boolean }): Promise<void>;
  emit(change: FaceChange): void;
  stopEditing(): void;
  alive(): void;
  disposed(): boolean;
}

/**
 * Which head a face shows, one change at a time in the order asked: a loaded head (with the landmark guide where its
 * landmarks are not found), a person's, or the default head again. Each is read, built and fitted before the current
 * head is touched.
 */
export class HeadSwitch implements FaceHeads {
  private loading: Promise<unknown> = Promise.resolve();
  private guide: LandmarkGuide | undefined;
  /** Builds people's heads, from the first `setIdentity` on. */
  private identities: IdentityBuilder | undefined;

  constructor(private readonly host: HeadHost) {}

  /**
   * Loads a head from a file or URL, carries the rig over to it and shows it in place of the current one. Everything is
   * read, checked and fitted before the current head is touched: a refused file changes nothing.
   */
  async loadHead(source: HeadSource, options?: LoadHeadOptions): Promise<HeadDescription> {
    this.host.alive();
    const o = checkLoadHeadOptions(options);
    // Another head asked for: a landmark guide under way is given up.
    this.guide?.cancel();
    const run = async (): Promise<HeadDescription> => {
      const started = performance.now();
      const files = await readHeadFiles(source);
      const prepared = await prepareHead(
        files,
        o,
        this.host.partsUrl(),
        this.host.original(),
        o.resolution ?? this.host.options.resolution,
      );
      this.host.alive();
      await this.host.mount(prepared.head, prepared, { started, fresh: true });
      await this.host.headStore()?.save({
        files: prepared.files,
        options: { ...prepared.options, landmarks: null },
        landmarks: prepared.landmarks,
      });
      return this.host.describeHead();
    };
    return this.queue(run);
  }

  /**
   * Loads a head as `loadHead` does, but where landmarks cannot be found, shows its skin alone and has them placed by
   * clicking on it (or `placeLandmark`), in the order of `LANDMARK_NAMES`; once the last is placed the head loads with
   * them. Resolves when it is shown; rejects if the guide is cancelled or the file is refused for another reason.
   */
  async guideLandmarks(source: HeadSource, options?: LoadHeadOptions): Promise<HeadDescription> {
    this.host.alive();
    const o = checkLoadHeadOptions(options);
    const files = await readHeadFiles(source);
    try {
      return await this.loadHead(files, o);
    } catch (error) {
      if (!(error instanceof MissingLandmarksError)) throw error;
      this.guide?.cancel();
      const guide = new LandmarkGuide(this.host.view, error, this.host.shownHead()?.root, () => this.host.emit('landmarks'));
      this.guide = guide;
      this.host.stopEditing();
      this.host.emit('landmarks');
      let landmarks: Partial<Landmarks>;
      try {
        landmarks = await guide.done;
      } finally {
        guide.dispose();
        if (this.guide === guide) this.guide = undefined;
        const shown = this.host.shownHead();
        if (!this.host.disposed() && shown) this.host.view.frameBounds(shown.bounds);
        this.host.emit('landmarks');
      }
      return this.loadHead(files, { ...o, landmarks: { ...(o.landmarks ?? {}), ...landmarks } });
    }
  }

  /** The landmark guide under way, if any. */
  landmarkGuide(): LandmarkGuide | undefined {
    return this.guide;
  }

  /** Shows the default head again with the face's own rig, and forgets a kept loaded head. */
  async revertHead(): Promise<void> {
    this.host.alive();
    this.guide?.cancel();
    const run = async (): Promise<void> => {
      const head = await loadHeadModel(this.host.modelUrl());
      this.host.alive();
      await this.host.mount(head, undefined, {});
      await this.host.headStore()?.clear();
    };
    return this.queue(run);
  }

  /**
   * Shows the head of a person (built in a worker from the base mesh and MakeHuman's targets) with the face's rig
   * carried over, or the default head again for null. Built and fitted before the current head is touched.
   */
  async showIdentity(named: NamedIdentity | null): Promise<HeadDescription> {
    this.host.alive();
    this.guide?.cancel();
    if (named === null) {
      await this.revertHead();
      return this.host.describeHead();
    }
    const run = async (): Promise<HeadDescription> => {
      const started = performance.now();
      const prepared = await this.identityHead(named);
      await this.host.mount(prepared.head, prepared, { started });
      // A loaded head kept from before would come back on the next visit instead of the person asked for.
      await this.host.headStore()?.clear();
      return this.host.describeHead();
    };
    return this.queue(run);
  }

  /** Builds a person's head (in the identity worker) at the face's resolution and carries the rig over to it. */
  async identityHead(named: NamedIdentity): Promise<PreparedHead> {
    const level = this.host.options.resolution;
    this.identities ??= new IdentityBuilder(assetUrl('models/identity-source.bin', this.host.options.assetBase));
    const build = await this.identities.generate(named.identity, level);
    this.host.alive();
    return prepareIdentityHead(build, named, this.host.original(), level);
  }

  /** What the face shows now. */
  describeHead(): HeadDescription {
    return this.host.describeHead();
  }

  /** Gives up a landmark guide under way and stops the identity worker. */
  dispose(): void {
    this.guide?.cancel();
    this.identities?.dispose();
  }

  /** Runs `run` after the changes asked before it (a failed one does not stop the next). */
  private queue<T>(run: () => Promise<T>): Promise<T> {
    const next = this.loading.then(run, run);
    this.loading = next.catch(() => {});
    return next;
  }
}
