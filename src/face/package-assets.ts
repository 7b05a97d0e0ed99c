/**
 * Where a face fetches the package's own models and rigs from when no `assetBase` is given. The library build puts
 * them beside its modules, so they are found from the module's own URL wherever it is served from (node_modules, a
 * static host, a CDN). This project's own pages, in development and in its app build, serve them from the site's root.
 */
export function packageAssetBase(): string {
  const library = import.meta.env.MODE === 'library' || import.meta.env.MODE === 'standalone';
  if (!library) return new URL(import.meta.env.BASE_URL, location.origin).href;
  // Through a variable: written out as `new URL('./', import.meta.url)`, the build would take './' for a file of its
  // own and put that file's contents in its place.
  const module = import.meta.url;
  return new URL('./', module).href;
}
