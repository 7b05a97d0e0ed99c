/** Messages between the page and the identity worker, which builds a head for a person (see IdentityBuilder). */
import type { BuiltHead } from '../../core/head/build/head-build';
import type { HeadLevel } from '../../core/head/head-levels';
import type { Identity } from '../../core/head/identity';

/** Build the head of `identity` at `level`; the first request carries the identity source's bytes. */
export interface BuildIdentityMessage {
  type: 'build';
  id: number;
  identity: Identity;
  level: HeadLevel;
  source?: ArrayBuffer;
}

/**
 * The built head, and the skin at the lowest level before and after the identity's targets (xyz per vertex, metres):
 * the page fits its warp for the rig and the landmarks on them.
 */
export interface BuiltIdentityMessage {
  type: 'built';
  id: number;
  head: BuiltHead;
  base: Float64Array;
  moved: Float64Array;
  /** Milliseconds the worker spent building. */
  ms: number;
}

export interface IdentityFailedMessage {
  type: 'failed';
  id: number;
  message: string;
}

export type ToIdentityWorker = BuildIdentityMessage;
export type FromIdentityWorker = BuiltIdentityMessage | IdentityFailedMessage;

/** The typed arrays of a built head, to move to the page without copying them. */
export function builtHeadBuffers(head: BuiltHead): ArrayBuffer[] {
  const buffers = new Set<ArrayBuffer>();
  const visit = (node: BuiltHead['root']): void => {
    for (const part of node.parts ?? []) {
      const g = part.geometry;
      for (const array of [g.positions, g.normals, g.uvs, g.colors, g.indices]) if (array) buffers.add(array.buffer as ArrayBuffer);
    }
    for (const child of node.children ?? []) visit(child);
  };
  visit(head.root);
  return [...buffers];
}
