import { EmbeddedFace } from '../face/embedded-face';
import type { FaceHandle } from '../face/face-handle';
import type { FaceOptions } from '../face/face-options';

/** A face on a page: the handle `createFace` resolves to (`window.face` in the app). */
export type Face = FaceHandle;

/**
 * Shows a face in `container` and resolves to its handle once the head is shown and its skin solver runs. The canvas
 * follows the container's size. Each face has its own worker and state; `face.dispose()` takes it all back. Bad
 * options reject with an error naming the option, before anything is built.
 */
export async function createFace(container: HTMLElement, options: FaceOptions = {}): Promise<Face> {
  return (await EmbeddedFace.create(container, options)).handle;
}
