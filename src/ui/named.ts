import type { Controller } from 'lil-gui';

/** Names a controller by its `data-control` attribute, which tests and scripts find it by; returns it for chaining. */
export function named<T extends Controller>(controller: T, name: string): T {
  controller.domElement.dataset.control = name;
  return controller;
}
