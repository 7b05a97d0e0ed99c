/**
 * The active region: the skin a frame solves. An expression moves the skin under its muscles and, fading with
 * distance, the skin around it; the rest of the head stays at rest and need not be solved. The region holds the
 * vertices under a muscle and a few rings around them, grows along the mesh while the motion spreads, and lets
 * vertices go once they are back at rest. Skin outside it costs nothing: its positions are exactly the rest positions,
 * and so are its normals except on the ring just outside the region, whose normals follow the moved triangles.
 *
 * A frame projects the constraints that touch the region, so they also move the ring of vertices just outside it.
 * Before the frame's relaxation, the region grows by ACTIVE_GROW_RINGS rings where a border vertex is farther than
 * ACTIVE_GROW (times the mesh size) from rest, or where the frame moved a ring vertex farther than that; the rest of
 * the ring goes back exactly to rest. So the region ends where the whole-mesh solve moves the skin by less than about
 * that much, and the two solves agree to about that much. The skin's response fades slowly (the tissue under it is
 * soft next to the skin's stretch), so a local expression still reaches several centimetres out at this tolerance.
 */
import type { KernelMemory } from './kernel-memory';
import { allocate, type Memory } from './memory';
import type { SkinTopology } from './topology';

/** Rings of vertices around the muscle-held ones that join the region when the muscle inputs change. */
const ACTIVE_SEED_RINGS = 8;
/**
 * The region grows where its border is farther than this from rest (times the mesh size), or where a frame moved a
 * vertex just outside it farther than that: the tolerance to which it matches the whole-mesh solve. 19 um on the
 * default head, a small fraction of a pixel at any framing of the face; the two solves then differ by a few times
 * that at most. A tenth of it (5e-6) solved 40 % more skin for AU12 (11,461 of the medium head's 17,091 vertices
 * against 8,153), 30 to 35 % more time a frame for AU12 and AU1 + AU2, and came no nearer the whole-mesh solve where
 * the motion is widest (happiness: 33 um either way).
 */
export const ACTIVE_GROW = 5e-5;
/**
 * A vertex no muscle holds leaves the region once it and its neighbours are nearer than this to rest (times the mesh
 * size), with enough others (ACTIVE_LEAVE_SHARE). Well under ACTIVE_GROW, so that a vertex that left is not pulled
 * straight back in.
 */
const ACTIVE_LEAVE = ACTIVE_GROW / 4;
/** Rings a vertex that joins brings along: the motion may spread several rings in a frame. */
const ACTIVE_GROW_RINGS = 4;
/** Frames between looks for vertices that may leave (leaving only saves time; it need not be prompt). */
const ACTIVE_SHRINK_PERIOD = 8;
/**
 * Vertices leave only when at least this share of the region may: each change rebuilds the region's and the
 * constraints' lists over the whole mesh (15 ms on the high head), which a few leavers never pay back (8 of the high
 * head's 47,613 under happiness, every eighth frame). At a thirty-second the saving repays it within about 13 frames.
 */
const ACTIVE_LEAVE_SHARE = 1 / 32;

export class ActiveRegion {
  /** Whether the region follows the motion; when not, it is the whole mesh, always. */
  readonly enabled: boolean;
  /** 1 for each vertex in the region. */
  readonly inside: Uint8Array;
  /** The region's vertices in ascending order: `vertices[0..count]`. */
  readonly vertices: Uint32Array;
  count = 0;
  /** The vertices outside the region with a neighbour inside, ascending: `ring[0..ringCount]`. */
  readonly ring: Uint32Array;
  ringCount = 0;
  /** The region's vertices with a neighbour outside: `border[0..borderCount]`. */
  private readonly border: Uint32Array;
  private borderCount = 0;
  /** Bumped whenever the region changes, so that lists built from it can tell they are stale. */
  revision = 0;
  private readonly topology: SkinTopology;
  private readonly onRing: Uint8Array;
  /** 1 for each vertex whose normal the solver computes: those in the region and on its ring. */
  readonly shaded: Uint8Array;
  /** Those vertices, ascending: `shadedVertices[0..shadedCount]`. */
  readonly shadedVertices: Uint32Array;
  shadedCount = 0;
  /** The other corners of their triangles (the ring's neighbours outside it): `outer[0..outerCount]`. */
  readonly outer: Uint32Array;
  outerCount = 0;
  private readonly onOuter: Uint8Array;
  /** Scratch: a vertex list and flags for the growing and shrinking passes. */
  private readonly scratch: Uint32Array;
  private readonly quiet: Uint8Array;
  private frame = 0;

  /**
   * `memory`: where the vertex list lives (shared, for a partner thread to walk it); in `kernel` where it has room (the
   * second ring's bending kernel walks it there, see wasm-kernels.ts).
   */
  constructor(topology: SkinTopology, enabled: boolean, memory: Memory = 'local', kernel: KernelMemory | null = null) {
    const n = topology.vertexCount;
    this.topology = topology;
    this.enabled = enabled;
    this.inside = new Uint8Array(n);
    this.vertices = allocate(Uint32Array, n, memory, kernel);
    this.ring = new Uint32Array(n);
    this.border = new Uint32Array(n);
    this.onRing = new Uint8Array(n);
    this.shaded = new Uint8Array(n);
    this.shadedVertices = allocate(Uint32Array, n, memory, kernel);
    this.outer = new Uint32Array(n);
    this.onOuter = new Uint8Array(n);
    this.scratch = new Uint32Array(n);
    this.quiet = new Uint8Array(n);
    if (!enabled) {
      this.inside.fill(1);
      this.rebuild(null);
    }
  }

  /** Adds the `count` vertices of `held` and ACTIVE_SEED_RINGS rings around them. */
  seed(held: Uint32Array, count: number): void {
    if (!this.enabled) return;
    const { neighbourStart: start, neighbours } = this.topology;
    const inside = this.inside;
    const mark = this.quiet;
    // Breadth-first, ring by ring; `mark` tells which vertices the search has reached.
    const queue = this.scratch;
    let changed = false;
    let tail = 0;
    for (let h = 0; h < count; h++) {
      const v = held[h];
      if (mark[v] === 0) {
        mark[v] = 1;
        queue[tail++] = v;
      }
    }
    tail = addRings(start, neighbours, mark, queue, tail, ACTIVE_SEED_RINGS);
    for (let k = 0; k < tail; k++) {
      const v = queue[k];
      mark[v] = 0;
      if (inside[v] === 0) {
        inside[v] = 1;
        changed = true;
      }
    }
    // Vertices only joined, so no normal needs resetting.
    if (changed) this.rebuild(null);
  }

  /**
   * Before the frame's relaxation: the region grows around border vertices farther than ACTIVE_GROW from rest, and
   * takes in the ring vertices that the frame moved farther than that, each with ACTIVE_GROW_RINGS - 1 rings around
   * it; the other ring vertices go back exactly to rest, so that their move does not count. Nothing else moves skin
   * outside the region: what a collider that moves reaches joins before the frame (see `join`). Returns whether the
   * region changed.
   */
  grow(x: Float32Array): boolean {
    if (!this.enabled) return false;
    const t = this.topology;
    const X = t.rest;
    const grow = ACTIVE_GROW * t.size;
    const grow2 = grow * grow;
    const inside = this.inside;
    const start = t.neighbourStart;
    const nb = t.neighbours;
    const joining = this.scratch;
    let joins = 0;
    for (let k = 0; k < this.borderCount; k++) {
      const v = this.border[k];
      if (distanceSquared(x, X, 3 * v) <= grow2) continue;
      for (let j = start[v]; j < start[v + 1]; j++) {
        const u = nb[j];
        if (inside[u] === 0) {
          inside[u] = 1;
          joining[joins++] = u;
        }
      }
    }
    for (let k = 0; k < this.ringCount; k++) {
      const v = this.ring[k];
      if (inside[v] === 0 && distanceSquared(x, X, 3 * v) > grow2) {
        inside[v] = 1;
        joining[joins++] = v;
      }
    }
    this.spread(joins);
    this.restRing(x);
    if (joins === 0) return false;
    // Vertices only joined, so no normal needs resetting.
    this.rebuild(null);
    return true;
  }

  /**
   * Between frames, when the inputs change: the `count` vertices of `vertices` (skin at rest that a collider which
   * moved now reaches) join, each with ACTIVE_GROW_RINGS - 1 rings around it, as the vertices `grow` takes in.
   * Returns whether the region changed.
   */
  join(vertices: Uint32Array, count: number): boolean {
    if (!this.enabled) return false;
    const inside = this.inside;
    const joining = this.scratch;
    let joins = 0;
    for (let k = 0; k < count; k++) {
      const v = vertices[k];
      if (inside[v] === 0) {
        inside[v] = 1;
        joining[joins++] = v;
      }
    }
    this.spread(joins);
    if (joins === 0) return false;
    this.rebuild(null);
    return true;
  }

  /** Marks ACTIVE_GROW_RINGS - 1 rings around the `joins` vertices just marked inside, listed in `scratch`. */
  private spread(joins: number): void {
    addRings(this.topology.neighbourStart, this.topology.neighbours, this.inside, this.scratch, joins, ACTIVE_GROW_RINGS - 1);
  }

  /**
   * At the frame's end (after the relaxation, which blends with the frame's start): ring vertices go back exactly to
   * rest again (the last orientation passes may have nudged them), and now and then vertices no muscle holds that are
   * back at rest, with all their neighbours, leave the region; they and their normals go exactly to rest. Returns
   * whether the region changed.
   */
  finish(x: Float32Array, weights: Float32Array, normalWeights: Float32Array, normals: Float32Array): boolean {
    if (!this.enabled) return false;
    this.restRing(x);
    if (++this.frame % ACTIVE_SHRINK_PERIOD !== 0 || !this.shrink(x, weights, normalWeights)) return false;
    this.rebuild(normals);
    return true;
  }

  /** Puts the ring vertices that are still outside the region back exactly at rest. */
  private restRing(x: Float32Array): void {
    const X = this.topology.rest;
    const inside = this.inside;
    for (let k = 0; k < this.ringCount; k++) {
      const v = this.ring[k];
      if (inside[v] === 0) setRest(x, X, 3 * v);
    }
  }

  /** Empties the region: every vertex in it or next to it goes exactly to rest, normals too. */
  clear(x: Float32Array, normals: Float32Array): void {
    // The shrink period starts over too: skin back at rest then moves the same whatever moved it before (a recorder
    // relies on that to give the same frames twice).
    this.frame = 0;
    if (!this.enabled || (this.count === 0 && this.ringCount === 0)) return;
    const X = this.topology.rest;
    for (let k = 0; k < this.count; k++) setRest(x, X, 3 * this.vertices[k]);
    for (let k = 0; k < this.ringCount; k++) setRest(x, X, 3 * this.ring[k]);
    this.inside.fill(0);
    this.rebuild(normals);
  }

  /** Takes the vertices back at rest out of the region (see finish); returns whether any left. */
  private shrink(x: Float32Array, weights: Float32Array, normalWeights: Float32Array): boolean {
    const t = this.topology;
    const X = t.rest;
    const leave = ACTIVE_LEAVE * t.size;
    const leave2 = leave * leave;
    const inside = this.inside;
    const quiet = this.quiet;
    for (let k = 0; k < this.count; k++) {
      const v = this.vertices[k];
      quiet[v] = distanceSquared(x, X, 3 * v) < leave2 ? 1 : 0;
    }
    const leaving = this.scratch;
    let leaves = 0;
    for (let k = 0; k < this.count; k++) {
      const v = this.vertices[k];
      if (quiet[v] === 0 || weights[v] > 0 || normalWeights[v] > 0) continue;
      let still = true;
      for (let j = t.neighbourStart[v]; j < t.neighbourStart[v + 1] && still; j++) {
        const u = t.neighbours[j];
        still = inside[u] === 0 || quiet[u] === 1;
      }
      if (still) leaving[leaves++] = v;
    }
    for (let k = 0; k < this.count; k++) quiet[this.vertices[k]] = 0;
    if (leaves < ACTIVE_LEAVE_SHARE * this.count) return false;
    for (let k = 0; k < leaves; k++) {
      const v = leaving[k];
      inside[v] = 0;
      setRest(x, X, 3 * v);
    }
    return leaves > 0;
  }

  /** Rebuilds the lists from `inside`. */
  private rebuild(normals: Float32Array | null): void {
    const t = this.topology;
    const n = t.vertexCount;
    const inside = this.inside;
    const onRing = this.onRing;
    onRing.fill(0);
    let count = 0;
    let borderCount = 0;
    for (let v = 0; v < n; v++) {
      if (inside[v] === 0) continue;
      this.vertices[count++] = v;
      let onBorder = false;
      for (let j = t.neighbourStart[v]; j < t.neighbourStart[v + 1]; j++) {
        const u = t.neighbours[j];
        if (inside[u] === 0) {
          onRing[u] = 1;
          onBorder = true;
        }
      }
      if (onBorder) this.border[borderCount++] = v;
    }
    this.borderCount = borderCount;
    let ringCount = 0;
    for (let v = 0; v < n; v++) if (onRing[v] === 1) this.ring[ringCount++] = v;
    this.count = count;
    this.ringCount = ringCount;
    // Normals of vertices no longer shaded go back to rest (a vertex only joining needs none: `normals` null).
    const N = t.restNormals;
    let shadedCount = 0;
    for (let v = 0; v < n; v++) {
      const shaded = inside[v] === 1 || onRing[v] === 1;
      if (normals && this.shaded[v] === 1 && !shaded) {
        normals[3 * v] = N[3 * v];
        normals[3 * v + 1] = N[3 * v + 1];
        normals[3 * v + 2] = N[3 * v + 2];
      }
      this.shaded[v] = shaded ? 1 : 0;
      if (shaded) this.shadedVertices[shadedCount++] = v;
    }
    this.shadedCount = shadedCount;
    let outerCount = 0;
    for (let k = 0; k < ringCount; k++) {
      const v = this.ring[k];
      for (let j = t.neighbourStart[v]; j < t.neighbourStart[v + 1]; j++) {
        const u = t.neighbours[j];
        if (this.shaded[u] === 0 && this.onOuter[u] === 0) {
          this.onOuter[u] = 1;
          this.outer[outerCount++] = u;
        }
      }
    }
    for (let k = 0; k < outerCount; k++) this.onOuter[this.outer[k]] = 0;
    this.outerCount = outerCount;
    this.revision++;
  }
}

function distanceSquared(x: Float32Array, X: Float32Array, i: number): number {
  const dx = x[i] - X[i];
  const dy = x[i + 1] - X[i + 1];
  const dz = x[i + 2] - X[i + 2];
  return dx * dx + dy * dy + dz * dz;
}

function setRest(x: Float32Array, X: Float32Array, i: number): void {
  x[i] = X[i];
  x[i + 1] = X[i + 1];
  x[i + 2] = X[i + 2];
}

/**
 * Breadth-first, ring by ring: flags `rings` rings of neighbours around the flagged vertices `queue[0..tail]`, appending
 * each newly flagged vertex to `queue`; returns the new tail.
 */
function addRings(start: Uint32Array, neighbours: Uint32Array, flags: Uint8Array, queue: Uint32Array, tail: number, rings: number): number {
  let head = 0;
  for (let r = 0; r < rings; r++) {
    const end = tail;
    for (; head < end; head++) {
      const v = queue[head];
      for (let j = start[v]; j < start[v + 1]; j++) {
        const u = neighbours[j];
        if (flags[u] === 0) {
          flags[u] = 1;
          queue[tail++] = u;
        }
      }
    }
  }
  return tail;
}
