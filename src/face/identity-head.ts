import type { HeadLevel } from '../core/head/head-levels';
import type { NamedIdentity } from '../core/head/identity';
import { fitIdentityWarp } from '../core/head/identity-warp';
import { identityLook } from '../core/head/identity-look';
import { DEFAULT_LANDMARKS, LANDMARK_NAMES, type Landmarks } from '../core/head/landmarks';
import { warpPoint } from '../core/head/thin-plate';
import { parseRig } from '../core/rig/rig-schema';
import type { Rig } from '../core/rig/rig-types';
import { warpRig } from '../core/rig/rig-warp';
import { headSceneFromSpec } from '../render/head-from-spec';
import { headModelOf } from '../render/head-model';
import type { IdentityBuild } from '../sim/main/identity-builder';
import { jawOnLips, LOAD_HEAD_DEFAULTS, type PreparedHead } from './head-loader';

/**
 * An identity's head ready to show: the built head as three.js objects, and the rig and landmarks of the default head
 * carried over by the warp fitted on the two heads' matching vertices (the heads share their vertices, so the fit
 * follows the new shape everywhere, not only at a dozen landmarks).
 */
export function prepareIdentityHead(build: IdentityBuild, named: NamedIdentity, original: Rig, level: HeadLevel): PreparedHead {
  const warp = fitIdentityWarp(build.base, build.moved);
  const carried = parseRig(warpRig(original, warp), `identity ${named.name}: the rig carried over`);
  const landmarks = Object.fromEntries(LANDMARK_NAMES.map((n) => [n, warpPoint(warp, DEFAULT_LANDMARKS[n])])) as Landmarks;
  const head = headModelOf(
    headSceneFromSpec(build.head.root, build.head.sceneExtras),
    `identity ${named.name}`,
    identityLook(named.identity),
  );
  const rig = jawOnLips(carried, head.skin, landmarks);
  return {
    head,
    level,
    sources: { eyes: 'file', teeth: 'file', jaw: 'file' },
    rig,
    landmarks,
    transform: { scale: 1, units: 'm', up: '+y', forward: '+z', rotation: [1, 0, 0, 0, 1, 0, 0, 0, 1], offset: [0, 0, 0] },
    files: [],
    options: { ...LOAD_HEAD_DEFAULTS },
    identity: { ...named, identity: structuredClone(named.identity) },
  };
}
