/** A face's downloads, started together before its view is made (see startLoading). */
import type { Rig } from '../core/rig/rig-types';
import { disposeHead, fetchModel, parseHeadModel, type HeadModel } from '../render/head-model';
import { loadEnvironment } from '../render/environment';
import { HeadStore } from './head-store';
import type { FaceOptions } from './face-options';
import { assetUrl, loadRig, pageUrl, rigKey } from './face-assets';

/** What a face downloads before it can show its head, started together as it is created (see startLoading). */
export interface FaceLoads {
  rig: Promise<Rig>;
  /** The prefiltered room light, or null if it could not be had (the view then makes its own). */
  environment: ReturnType<typeof loadEnvironment>;
  /** A head loaded on an earlier visit and kept in the browser (none without autosave). */
  stored: ReturnType<HeadStore['load']>;
  /**
   * The head of the options (`model`, else the default head), once: null, not fetched, where a kept head or a person
   * replaces it.
   */
  takeModel(): Promise<HeadModel | null>;
  /** Frees the model if it was fetched and never taken (a start that failed or was aborted before it). */
  release(): void;
  modelUrl: string;
  partsUrl: string;
  rigKey: string | undefined;
  headStore: HeadStore | undefined;
}

/**
 * Starts every download a face needs before its head shows, at once: the rig, the room light, the kept head and the
 * model used to wait for one another, and the model alone for the view's WebGL context as well.
 */
export function startLoading(o: Required<FaceOptions>): FaceLoads {
  const modelUrl = o.model === null ? assetUrl(`models/head-${o.resolution}.glb`, o.assetBase) : pageUrl(o.model);
  const key = o.autosave === false ? undefined : typeof o.autosave === 'string' ? o.autosave : `softface:rig:${rigKey(o.rig, o.assetBase)}`;
  const headStore = key ? new HeadStore(`${key}:head`) : undefined;
  const stored = headStore ? headStore.load() : Promise.resolve(undefined);
  // A person asked for by the options replaces the default head (checked, with its message, where it is read).
  const person = o.model === null && o.identity !== null;
  // The bytes at once, beside the rest; parsed only if no kept head replaces them (then they were fetched for nothing,
  // on a return visit with a head of one's own, rather than after the kept head was looked for).
  const bytes = person ? null : fetchModel(modelUrl);
  bytes?.catch(() => {});
  const model = stored.then((kept) => (kept || !bytes ? null : headFrom(bytes, modelUrl)));
  const rig = loadRig(o.rig, o.assetBase);
  // Awaited in build; until then a failure must not count as unhandled if something before it fails first.
  rig.catch(() => {});
  model.catch(() => {});
  let taken = false;
  return {
    rig,
    takeModel: () => {
      taken = true;
      return model;
    },
    release: () => {
      if (!taken)
        model.then(
          (head) => head && disposeHead(head),
          () => {},
        );
      taken = true;
    },
    // A failure resolves to null, and the view then makes its own.
    environment: loadEnvironment(assetUrl('environment/room.pmrem', o.assetBase)),
    stored,
    modelUrl,
    // Loaded heads take their eyes and teeth from the lightest default head.
    partsUrl: assetUrl('models/head-low.glb', o.assetBase),
    rigKey: key,
    headStore,
  };
}

/** The head model from its bytes (fetched or being fetched from `url`), its failure naming where from. */
export async function headFrom(bytes: Promise<ArrayBuffer>, url: string): Promise<HeadModel> {
  try {
    return await parseHeadModel(await bytes, url);
  } catch (error) {
    throw new Error(`the head could not be loaded from ${url}: ${(error as Error).message}`);
  }
}
