import { parseRig, parseRigText } from '../core/rig/rig-schema';
import type { Rig } from '../core/rig/rig-types';
import { packageFileUrl, type PackageFile } from './package-assets';

/** The autosave key's part for a rig: its URL's path (the same rig at any host), or `object` for a rig given as one. */
export function rigKey(rig: string | URL | Rig | null, given: string | URL | null): string {
  if (rig !== null && typeof rig === 'object' && !(rig instanceof URL)) return 'object';
  return new URL(rig === null ? assetUrl('rigs/default.json', given) : pageUrl(rig)).pathname;
}

/** A rig's name for its exported file: its file's name without `.json` (`default`), or `rig`. */
export function rigName(rig: string | URL | Rig | null): string {
  if (rig !== null && typeof rig === 'object' && !(rig instanceof URL)) return 'rig';
  const file = rig === null ? 'default.json' : (new URL(String(rig), document.baseURI).pathname.split('/').pop() ?? '');
  return file.replace(/(\.rig)?\.json$/i, '') || 'rig';
}

/** A URL given by the page, made absolute against the page. */
export function pageUrl(url: string | URL): string {
  return new URL(String(url), document.baseURI).href;
}

/**
 * Where one of the package's files is fetched from: under `given` (the face's `assetBase` option, relative to the
 * page), or where the package's build put it (package-assets.ts).
 */
export function assetUrl(file: PackageFile, given: string | URL | null): string {
  if (given === null) return packageFileUrl(file);
  const base = pageUrl(given);
  return new URL(file, base.endsWith('/') ? base : `${base}/`).href;
}

/** The rig given as an object (checked), at a URL, or the package's default rig. */
export async function loadRig(rig: string | URL | Rig | null, given: string | URL | null): Promise<Rig> {
  if (rig !== null && typeof rig === 'object' && !(rig instanceof URL)) return parseRig(rig, 'createFace: rig');
  const url = rig === null ? assetUrl('rigs/default.json', given) : pageUrl(rig);
  let text: string;
  try {
    const response = await fetch(url);
    if (!response.ok) throw new Error(`${response.status} ${response.statusText}`);
    text = await response.text();
  } catch (error) {
    throw new Error(`the muscle rig could not be loaded from ${url}: ${(error as Error).message}`);
  }
  return parseRigText(text, url);
}
