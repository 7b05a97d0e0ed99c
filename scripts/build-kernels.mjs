/**
 * Writes the solver's WebAssembly kernels: the text below, compiled with wabt, as bytes in
 * src/core/solver/wasm-kernels-bytes.ts (committed, so that neither the app nor Node needs a compiler). `--check`
 * compiles and fails if the committed bytes differ (the unit tests run it).
 *
 * The length kernels project four edges of a colour at a time in 32-bit float lanes: the edges of a colour share no
 * vertex, so the four gathers and scatters never meet (see projectFreeEdges and projectHeldEdges in length-kernels.ts,
 * which they mirror). The bending kernel is projectBendingPart's loop, one vertex at a time, as it computes.
 */
import { readFileSync, writeFileSync } from 'node:fs';
import wabtInit from 'wabt';

const OUT = new URL('../src/core/solver/wasm-kernels-bytes.ts', import.meta.url);
const LANES = [0, 1, 2, 3];
/** Words per edge record (EDGE_RECORD in constraint-lists.ts): two ends (xyz offsets), the rest length, a spare. */
const RECORD_BYTES = 16;

/** f32x4 of the float at byte `offset` from each lane's address local `$<name><lane>`. */
function gather(name, offset) {
  let e = `(f32x4.splat (f32.load offset=${offset} (local.get $${name}0)))`;
  for (const l of LANES.slice(1)) e = `(f32x4.replace_lane ${l} ${e} (f32.load offset=${offset} (local.get $${name}${l})))`;
  return e;
}

/**
 * The head of a kernel's loop: counter `$<k>` from `$<k0>` while under `$<k1>`, in a block `$done` the loop leaves by
 * and a loop `$next` a turn continues by (the body steps the counter and ends with `(br $next))))`).
 */
function loopOver(k, k0, k1) {
  return (
    `    (local.set $${k} (local.get $${k0}))\n    (block $done\n      (loop $next\n` +
    `        (br_if $done (i32.ge_u (local.get $${k}) (local.get $${k1})))\n`
  );
}

/** The length error's share, 2 s (d⁴ - r⁴) / (5 d⁴ + 10 d² r² + r⁴): the Padé form of projectFreeEdges. */
function share(kind, s, d2, r2) {
  const g = (n) => `(local.get $${n})`;
  const c = (v) => (kind === 'f32x4' ? `(f32x4.splat (f32.const ${v}))` : `(f32.const ${v})`);
  const op = (o, a, b) => `(${kind}.${o} ${a} ${b})`;
  const d4 = op('mul', g(d2), g(d2));
  const r4 = op('mul', g(r2), g(r2));
  const top = op('mul', g(s), op('sub', d4, r4));
  const bottom = op('add', op('add', op('mul', op('mul', c(5), g(d2)), g(d2)), op('mul', op('mul', c(10), g(d2)), g(r2))), r4);
  return op('div', top, bottom);
}

/**
 * Three stores that move the xyz floats at address local `$addr` by `op` (add or sub) of `term(axis)`, each in double
 * precision rounded back to single, as the loops' `x[i] += ...` do; `indent` spaces before each.
 */
function shiftXyz(addr, op, term, indent) {
  const pad = ' '.repeat(indent);
  return ['x', 'y', 'z']
    .map((d, i) => {
      const at = `offset=${4 * i} (local.get $${addr})`;
      return `${pad}(f32.store ${at}\n${pad}  (f32.demote_f64 (f64.${op} (f64.promote_f32 (f32.load ${at})) ${term(d)})))\n`;
    })
    .join('');
}

function lengthKernel(shared) {
  const one = `
  ;; One edge at record address $p: the loop's tail.
  (func $one (param $xp i32) (param $p i32) (param $s f32)
    (local $ia i32) (local $ib i32) (local $ax f32) (local $ay f32) (local $az f32) (local $bx f32) (local $by f32)
    (local $bz f32) (local $dx f32) (local $dy f32) (local $dz f32) (local $d2 f32) (local $r0 f32) (local $r2 f32)
    (local $k f32)
    (local.set $ia (i32.add (local.get $xp) (i32.shl (i32.load (local.get $p)) (i32.const 2))))
    (local.set $ib (i32.add (local.get $xp) (i32.shl (i32.load offset=4 (local.get $p)) (i32.const 2))))
    (local.set $ax (f32.load (local.get $ia)))
    (local.set $ay (f32.load offset=4 (local.get $ia)))
    (local.set $az (f32.load offset=8 (local.get $ia)))
    (local.set $bx (f32.load (local.get $ib)))
    (local.set $by (f32.load offset=4 (local.get $ib)))
    (local.set $bz (f32.load offset=8 (local.get $ib)))
    (local.set $dx (f32.sub (local.get $bx) (local.get $ax)))
    (local.set $dy (f32.sub (local.get $by) (local.get $ay)))
    (local.set $dz (f32.sub (local.get $bz) (local.get $az)))
    (local.set $d2 (f32.add (f32.add (f32.mul (local.get $dx) (local.get $dx)) (f32.mul (local.get $dy) (local.get $dy)))
      (f32.mul (local.get $dz) (local.get $dz))))
    (local.set $r0 (f32.load offset=8 (local.get $p)))
    (local.set $r2 (f32.mul (local.get $r0) (local.get $r0)))
    (local.set $k ${share('f32', 's', 'd2', 'r2')})
    (f32.store (local.get $ia) (f32.add (local.get $ax) (f32.mul (local.get $k) (local.get $dx))))
    (f32.store offset=4 (local.get $ia) (f32.add (local.get $ay) (f32.mul (local.get $k) (local.get $dy))))
    (f32.store offset=8 (local.get $ia) (f32.add (local.get $az) (f32.mul (local.get $k) (local.get $dz))))
    (f32.store (local.get $ib) (f32.sub (local.get $bx) (f32.mul (local.get $k) (local.get $dx))))
    (f32.store offset=4 (local.get $ib) (f32.sub (local.get $by) (f32.mul (local.get $k) (local.get $dy))))
    (f32.store offset=8 (local.get $ib) (f32.sub (local.get $bz) (f32.mul (local.get $k) (local.get $dz)))))`;
  /** Lane `l`'s end `e` (a or b): the byte address of its xyz, from the record's word `word`. */
  const end = (e, l, word) =>
    `        (local.set $${e}${l} (i32.add (local.get $xp)\n` +
    `          (i32.shl (i32.load offset=${RECORD_BYTES * l + 4 * word} (local.get $p)) (i32.const 2))))\n`;
  const ends = LANES.map((l) => end('a', l, 0) + end('b', l, 1)).join('');
  let rest = '(f32x4.splat (f32.load offset=8 (local.get $p)))';
  for (const l of LANES.slice(1)) rest = `(f32x4.replace_lane ${l} ${rest} (f32.load offset=${RECORD_BYTES * l + 8} (local.get $p)))`;
  const axes = [
    ['x', 0],
    ['y', 4],
    ['z', 8],
  ];
  const loads = axes
    .map(([c, o]) => `        (local.set $a${c} ${gather('a', o)})\n        (local.set $b${c} ${gather('b', o)})\n`)
    .join('');
  const stores = axes
    .map(
      ([c, o]) =>
        `        (local.set $t (f32x4.add (local.get $a${c}) (f32x4.mul (local.get $k) (local.get $d${c}))))\n` +
        LANES.map((l) => `        (f32.store offset=${o} (local.get $a${l}) (f32x4.extract_lane ${l} (local.get $t)))\n`).join('') +
        `        (local.set $t (f32x4.sub (local.get $b${c}) (f32x4.mul (local.get $k) (local.get $d${c}))))\n` +
        LANES.map((l) => `        (f32.store offset=${o} (local.get $b${l}) (f32x4.extract_lane ${l} (local.get $t)))\n`).join(''),
    )
    .join('');
  return `(module
  (import "env" "memory" (memory 1 65536${shared ? ' shared' : ''}))${one}
  ;; Free edges: positions at byte $xp, records at byte $rp, words $j0..$j1 of them (four a record), share $s.
  (func (export "free") (param $xp i32) (param $rp i32) (param $s0 f32) (param $j0 i32) (param $j1 i32)
    (local $j i32) (local $p i32) ${LANES.map((l) => `(local $a${l} i32) (local $b${l} i32)`).join(' ')}
    (local $ax v128) (local $ay v128) (local $az v128) (local $bx v128) (local $by v128) (local $bz v128) (local $dx v128)
    (local $dy v128) (local $dz v128) (local $d2 v128) (local $r2 v128) (local $k v128) (local $s v128) (local $t v128)
    (local.set $s (f32x4.splat (local.get $s0)))
    (local.set $j (local.get $j0))
    (block $done
      (loop $next
        (br_if $done (i32.gt_u (i32.add (local.get $j) (i32.const ${LANES.length * 4})) (local.get $j1)))
        (local.set $p (i32.add (local.get $rp) (i32.shl (local.get $j) (i32.const 2))))
${ends}${loads}        (local.set $dx (f32x4.sub (local.get $bx) (local.get $ax)))
        (local.set $dy (f32x4.sub (local.get $by) (local.get $ay)))
        (local.set $dz (f32x4.sub (local.get $bz) (local.get $az)))
        (local.set $d2 (f32x4.add (f32x4.add (f32x4.mul (local.get $dx) (local.get $dx)) (f32x4.mul (local.get $dy) (local.get $dy)))
          (f32x4.mul (local.get $dz) (local.get $dz))))
        (local.set $t ${rest})
        (local.set $r2 (f32x4.mul (local.get $t) (local.get $t)))
        (local.set $k ${share('f32x4', 's', 'd2', 'r2')})
${stores}        (local.set $j (i32.add (local.get $j) (i32.const ${LANES.length * 4})))
        (br $next)))
    (block $end
      (loop $tail
        (br_if $end (i32.ge_u (local.get $j) (local.get $j1)))
        (call $one (local.get $xp) (i32.add (local.get $rp) (i32.shl (local.get $j) (i32.const 2))) (local.get $s0))
        (local.set $j (i32.add (local.get $j) (i32.const 4)))
        (br $tail))))${[heldKernel, bendKernel, secondRingKernels, orientKernel, positionKernel, collideKernel, normalKernels, frameKernels]
          .map((kernel) => kernel())
          .join('')}
)
`;
}

/**
 * Held edges (projectHeldEdges in length-kernels.ts): the exact length error outside the slack band, and a push along
 * each end's bulge direction (directions at byte $dp) by the bulge times the compression past the band times the
 * edge's muscle weight (the record's fourth word). An edge of zero length is left as it is.
 */
function heldKernel() {
  const v = (n) => `(local.get $${n})`;
  const ends = LANES.map(
    (l) =>
      `        (local.set $a${l} (i32.shl (i32.load offset=${RECORD_BYTES * l} (local.get $p)) (i32.const 2)))\n` +
      `        (local.set $b${l} (i32.shl (i32.load offset=${RECORD_BYTES * l + 4} (local.get $p)) (i32.const 2)))\n`,
  ).join('');
  const word = (o) => {
    let e = `(f32x4.splat (f32.load offset=${o} (local.get $p)))`;
    for (const l of LANES.slice(1)) e = `(f32x4.replace_lane ${l} ${e} (f32.load offset=${RECORD_BYTES * l + o} (local.get $p)))`;
    return e;
  };
  /** f32x4 of the float at byte offset `o` past base `base` plus each lane's end offset `$<name><lane>`. */
  const at = (name, base, o) => {
    let e = `(f32x4.splat (f32.load offset=${o} (i32.add (local.get $${base}) (local.get $${name}0))))`;
    for (const l of LANES.slice(1))
      e = `(f32x4.replace_lane ${l} ${e} (f32.load offset=${o} (i32.add (local.get $${base}) (local.get $${name}${l}))))`;
    return e;
  };
  const axes = [
    ['x', 0],
    ['y', 4],
    ['z', 8],
  ];
  const loads = axes
    .map(([c, o]) => `        (local.set $a${c} ${at('a', 'xp', o)})\n        (local.set $b${c} ${at('b', 'xp', o)})\n`)
    .join('');
  /** Lane `l`'s store at byte `o` of end `e` (a or b); lanes past the list's end (l >= $n) are not stored. */
  const store = (e, l, o) => {
    const put = `(f32.store offset=${o} (i32.add (local.get $xp) (local.get $${e}${l})) (f32x4.extract_lane ${l} (local.get $t)))`;
    return `        ${l === 0 ? put : `(if (i32.gt_u (local.get $n) (i32.const ${l})) (then ${put}))`}\n`;
  };
  /** End `e`'s new coordinate `c`: its place, plus (a) or minus (b) k times the edge, plus the push along its seed. */
  const moved = (e, c, o) =>
    `        (local.set $t (f32x4.add (f32x4.${e === 'a' ? 'add' : 'sub'} ${v(e + c)} (f32x4.mul ${v('k')} ${v(`d${c}`)}))\n` +
    `          (f32x4.mul ${v('push')} ${at(e, 'dp', o)})))\n`;
  const stores = axes.map(([c, o]) => ['a', 'b'].map((e) => moved(e, c, o) + LANES.map((l) => store(e, l, o)).join('')).join('')).join('');
  const half = '(f32x4.splat (f32.const 0.5))';
  return `
  ;; Held edges: positions at byte $xp, records at byte $rp, directions at byte $dp, words $j0..$j1 of the records,
  ;; half the stiffness $s0, the bulge $g0, the band's lower end $w0 (1 - pretension). Lanes past $j1 are not stored.
  (func (export "held") (param $xp i32) (param $rp i32) (param $dp i32) (param $s0 f32) (param $g0 f32) (param $w0 f32)
    (param $j0 i32) (param $j1 i32)
    (local $j i32) (local $p i32) (local $n i32) ${LANES.map((l) => `(local $a${l} i32) (local $b${l} i32)`).join(' ')}
    (local $ax v128) (local $ay v128) (local $az v128) (local $bx v128) (local $by v128) (local $bz v128) (local $dx v128)
    (local $dy v128) (local $dz v128) (local $len v128) (local $r0 v128) (local $over v128) (local $under v128)
    (local $short v128) (local $k v128) (local $push v128) (local $live v128) (local $t v128)
${loopOver('j', 'j0', 'j1')}        (local.set $p (i32.add (local.get $rp) (i32.shl (local.get $j) (i32.const 2))))
        ;; Records past the end (the last group's) read as edges of zero length from vertex 0 to itself: never stored.
        (local.set $n (i32.shr_u (i32.sub (local.get $j1) (local.get $j)) (i32.const 2)))
${ends}        (if (i32.lt_u (local.get $n) (i32.const 4)) (then
          (local.set $a3 (i32.const 0)) (local.set $b3 (i32.const 0))
          (if (i32.lt_u (local.get $n) (i32.const 3)) (then (local.set $a2 (i32.const 0)) (local.set $b2 (i32.const 0))))
          (if (i32.lt_u (local.get $n) (i32.const 2)) (then (local.set $a1 (i32.const 0)) (local.set $b1 (i32.const 0))))))
${loads}        (local.set $dx (f32x4.sub ${v('bx')} ${v('ax')}))
        (local.set $dy (f32x4.sub ${v('by')} ${v('ay')}))
        (local.set $dz (f32x4.sub ${v('bz')} ${v('az')}))
        (local.set $len (f32x4.sqrt (f32x4.add (f32x4.add (f32x4.mul ${v('dx')} ${v('dx')}) (f32x4.mul ${v('dy')} ${v('dy')}))
          (f32x4.mul ${v('dz')} ${v('dz')}))))
        (local.set $r0 ${word(8)})
        (local.set $over (f32x4.sub ${v('len')} ${v('r0')}))
        (local.set $under (f32x4.sub ${v('len')} (f32x4.mul (f32x4.splat ${v('w0')}) ${v('r0')})))
        (local.set $short (f32x4.mul (f32x4.sub ${v('under')} (f32x4.abs ${v('under')})) ${half}))
        ;; Lanes of zero length (and those past the end) move nothing: k and the push masked to 0.
        (local.set $live (f32x4.gt ${v('len')} (f32x4.splat (f32.const 0))))
        (local.set $k (v128.and ${v('live')} (f32x4.div (f32x4.mul (f32x4.splat ${v('s0')})
          (f32x4.add (f32x4.mul (f32x4.add ${v('over')} (f32x4.abs ${v('over')})) ${half}) ${v('short')})) ${v('len')})))
        (local.set $push (v128.and ${v('live')} (f32x4.mul (f32x4.mul (f32x4.splat (f32.neg ${v('g0')})) ${word(12)}) ${v('short')})))
${stores}        (local.set $j (i32.add (local.get $j) (i32.const ${LANES.length * 4})))
        (br $next))))`;
}

/**
 * Bending (projectBendingPart in solver-kernels.ts): the first ring's constraints of the bending list's vertices
 * `$r0..$r1` in pass `$pass`, in the loop's order and in its double-precision arithmetic on the single-precision
 * positions, so that the result is the loop's to the bit. Arrays at bytes: positions `$xp`, rest normals `$np`, the
 * neighbours' CSR starts `$sp` and xyz offsets `$op`, the constraint at rest `$ap` (doubles), the gains `$gp`, the
 * inverse degrees `$wp`, the passes `$pp` (bytes), the list `$lp`.
 */
function bendKernel() {
  return `
  (func (export "bend") (param $xp i32) (param $np i32) (param $sp i32) (param $op i32) (param $ap i32) (param $gp i32)
    (param $wp i32) (param $pp i32) (param $lp i32) (param $r0 i32) (param $r1 i32) (param $pass i32)
    (local $r i32) (local $v i32) (local $g f64) (local $j i32) (local $j1 i32) (local $ib i32) (local $kb i32)
    (local $nx f64) (local $ny f64) (local $nz f64) (local $mean f64) (local $w f64) (local $c f64) (local $lambda f64) (local $q f64)
${loopOver('r', 'r0', 'r1')}        (local.set $v (i32.load (i32.add (local.get $lp) (i32.shl (local.get $r) (i32.const 2)))))
        (local.set $r (i32.add (local.get $r) (i32.const 1)))
        (local.set $g (f64.promote_f32 (f32.load (i32.add (local.get $gp) (i32.shl (local.get $v) (i32.const 2))))))
        (br_if $next (i32.le_u (i32.load8_u (i32.add (local.get $pp) (local.get $v))) (local.get $pass)))
        (br_if $next (f64.eq (local.get $g) (f64.const 0)))
        (local.set $j (i32.load (i32.add (local.get $sp) (i32.shl (local.get $v) (i32.const 2)))))
        (local.set $j1 (i32.load offset=4 (i32.add (local.get $sp) (i32.shl (local.get $v) (i32.const 2)))))
        (local.set $ib (i32.mul (local.get $v) (i32.const 12)))
        (local.set $nx (f64.promote_f32 (f32.load (i32.add (local.get $np) (local.get $ib)))))
        (local.set $ny (f64.promote_f32 (f32.load offset=4 (i32.add (local.get $np) (local.get $ib)))))
        (local.set $nz (f64.promote_f32 (f32.load offset=8 (i32.add (local.get $np) (local.get $ib)))))
        (local.set $ib (i32.add (local.get $xp) (local.get $ib)))
        (local.set $mean (f64.const 0))
        (block $g1 (loop $gather
          (br_if $g1 (i32.ge_u (local.get $j) (local.get $j1)))
          (local.set $kb (i32.add (local.get $xp)
            (i32.shl (i32.load (i32.add (local.get $op) (i32.shl (local.get $j) (i32.const 2)))) (i32.const 2))))
          (local.set $mean (f64.add (local.get $mean)
            (f64.add (f64.add (f64.mul (f64.promote_f32 (f32.load (local.get $kb))) (local.get $nx))
                              (f64.mul (f64.promote_f32 (f32.load offset=4 (local.get $kb))) (local.get $ny)))
                     (f64.mul (f64.promote_f32 (f32.load offset=8 (local.get $kb))) (local.get $nz)))))
          (local.set $j (i32.add (local.get $j) (i32.const 1)))
          (br $gather)))
        (local.set $w (f64.promote_f32 (f32.load (i32.add (local.get $wp) (i32.shl (local.get $v) (i32.const 2))))))
        (local.set $c (f64.sub (f64.sub (f64.mul (local.get $mean) (local.get $w))
          (f64.add (f64.add (f64.mul (f64.promote_f32 (f32.load (local.get $ib))) (local.get $nx))
                            (f64.mul (f64.promote_f32 (f32.load offset=4 (local.get $ib))) (local.get $ny)))
                   (f64.mul (f64.promote_f32 (f32.load offset=8 (local.get $ib))) (local.get $nz))))
          (f64.load (i32.add (local.get $ap) (i32.shl (local.get $v) (i32.const 3))))))
        (local.set $lambda (f64.mul (local.get $g) (local.get $c)))
${shiftXyz('ib', 'add', (d) => `(f64.mul (local.get $lambda) (local.get $n${d}))`, 8)}
        (local.set $q (f64.mul (local.get $lambda) (local.get $w)))
        (local.set $j (i32.load (i32.add (local.get $sp) (i32.shl (local.get $v) (i32.const 2)))))
        (block $s1 (loop $scatter
          (br_if $s1 (i32.ge_u (local.get $j) (local.get $j1)))
          (local.set $kb (i32.add (local.get $xp)
            (i32.shl (i32.load (i32.add (local.get $op) (i32.shl (local.get $j) (i32.const 2)))) (i32.const 2))))
${shiftXyz('kb', 'sub', (d) => `(f64.mul (local.get $q) (local.get $n${d}))`, 10)}
          (local.set $j (i32.add (local.get $j) (i32.const 1)))
          (br $scatter)))
        (br $next))))`;
}

/** Three f64 products of the xyz floats at address local `$a` with `$nx`, `$ny`, `$nz`, summed as the loops sum them. */
function heightAt(a) {
  const f = (o, n) => `(f64.mul (f64.promote_f32 (f32.load offset=${o} (local.get $${a}))) (local.get $${n}))`;
  return `(f64.add (f64.add ${f(0, 'nx')}\n            ${f(4, 'ny')})\n            ${f(8, 'nz')})`;
}

/**
 * The second ring's bending (projectSecondRingPart in second-ring.ts), in its two halves: `ringSteps`, each region
 * vertex's step and its ring's moves, and `ringGather`, each vertex's own step less its rings' moves; in the loop's
 * double-precision arithmetic, so that the result is its to the bit. Arrays at bytes: positions `$xp`, rest normals
 * `$np`, the region's vertices `$vp`, the rings' CSR starts `$sp` and xyz offsets `$op`, inverse sizes `$wp`, the
 * constraint at rest `$ap` (doubles), gains `$gp`, reach `$hp` (bytes), moves `$mp` and steps `$tp`; region entries
 * `$k0..$k1`.
 */
function secondRingKernels() {
  const word = (base, index) => `(i32.add (local.get $${base}) (i32.shl (local.get $${index}) (i32.const 2)))`;
  return `
  (func (export "ringSteps") (param $xp i32) (param $np i32) (param $vp i32) (param $sp i32) (param $op i32)
    (param $wp i32) (param $ap i32) (param $gp i32) (param $mp i32) (param $tp i32) (param $k0 i32) (param $k1 i32)
    (local $k i32) (local $v i32) (local $j i32) (local $j1 i32) (local $ib i32) (local $kb i32) (local $g f64)
    (local $nx f64) (local $ny f64) (local $nz f64) (local $mean f64) (local $w f64) (local $step f64) (local $q f64)
${loopOver('k', 'k0', 'k1')}        (local.set $v (i32.load ${word('vp', 'k')}))
        (local.set $k (i32.add (local.get $k) (i32.const 1)))
        (local.set $g (f64.promote_f32 (f32.load ${word('gp', 'v')})))
        (local.set $ib (i32.mul (local.get $v) (i32.const 12)))
        (local.set $nx (f64.promote_f32 (f32.load (i32.add (local.get $np) (local.get $ib)))))
        (local.set $ny (f64.promote_f32 (f32.load offset=4 (i32.add (local.get $np) (local.get $ib)))))
        (local.set $nz (f64.promote_f32 (f32.load offset=8 (i32.add (local.get $np) (local.get $ib)))))
        (local.set $w (f64.promote_f32 (f32.load ${word('wp', 'v')})))
        (local.set $step (f64.const 0))
        (if (f64.ne (local.get $g) (f64.const 0)) (then
          (local.set $j (i32.load ${word('sp', 'v')}))
          (local.set $j1 (i32.load offset=4 ${word('sp', 'v')}))
          (local.set $mean (f64.const 0))
          (block $g1 (loop $gather
            (br_if $g1 (i32.ge_u (local.get $j) (local.get $j1)))
            (local.set $kb (i32.add (local.get $xp) (i32.shl (i32.load ${word('op', 'j')}) (i32.const 2))))
            (local.set $mean (f64.add (local.get $mean) ${heightAt('kb')}))
            (local.set $j (i32.add (local.get $j) (i32.const 1)))
            (br $gather)))
          (local.set $kb (i32.add (local.get $xp) (local.get $ib)))
          (local.set $step (f64.mul (local.get $g)
            (f64.sub (f64.sub (f64.mul (local.get $mean) (local.get $w)) ${heightAt('kb')})
              (f64.load (i32.add (local.get $ap) (i32.shl (local.get $v) (i32.const 3)))))))))
        (local.set $q (f64.mul (local.get $step) (local.get $w)))
        (local.set $kb (i32.add (local.get $mp) (local.get $ib)))
        (f32.store (local.get $kb) (f32.demote_f64 (f64.mul (local.get $q) (local.get $nx))))
        (f32.store offset=4 (local.get $kb) (f32.demote_f64 (f64.mul (local.get $q) (local.get $ny))))
        (f32.store offset=8 (local.get $kb) (f32.demote_f64 (f64.mul (local.get $q) (local.get $nz))))
        (f32.store ${word('tp', 'v')} (f32.demote_f64 (local.get $step)))
        (br $next))))
  (func (export "ringGather") (param $xp i32) (param $np i32) (param $vp i32) (param $sp i32) (param $op i32)
    (param $hp i32) (param $mp i32) (param $tp i32) (param $k0 i32) (param $k1 i32)
    (local $k i32) (local $u i32) (local $j i32) (local $j1 i32) (local $ib i32) (local $kb i32) (local $own f64)
    (local $dx f64) (local $dy f64) (local $dz f64)
${loopOver('k', 'k0', 'k1')}        (local.set $u (i32.load ${word('vp', 'k')}))
        (local.set $k (i32.add (local.get $k) (i32.const 1)))
        (br_if $next (i32.eqz (i32.load8_u (i32.add (local.get $hp) (local.get $u)))))
        (local.set $ib (i32.mul (local.get $u) (i32.const 12)))
        (local.set $own (f64.promote_f32 (f32.load ${word('tp', 'u')})))
        (local.set $kb (i32.add (local.get $np) (local.get $ib)))
        (local.set $dx (f64.mul (local.get $own) (f64.promote_f32 (f32.load (local.get $kb)))))
        (local.set $dy (f64.mul (local.get $own) (f64.promote_f32 (f32.load offset=4 (local.get $kb)))))
        (local.set $dz (f64.mul (local.get $own) (f64.promote_f32 (f32.load offset=8 (local.get $kb)))))
        (local.set $j (i32.load ${word('sp', 'u')}))
        (local.set $j1 (i32.load offset=4 ${word('sp', 'u')}))
        (block $g1 (loop $gather
          (br_if $g1 (i32.ge_u (local.get $j) (local.get $j1)))
          (local.set $kb (i32.add (local.get $mp) (i32.shl (i32.load ${word('op', 'j')}) (i32.const 2))))
          (local.set $dx (f64.sub (local.get $dx) (f64.promote_f32 (f32.load (local.get $kb)))))
          (local.set $dy (f64.sub (local.get $dy) (f64.promote_f32 (f32.load offset=4 (local.get $kb)))))
          (local.set $dz (f64.sub (local.get $dz) (f64.promote_f32 (f32.load offset=8 (local.get $kb)))))
          (local.set $j (i32.add (local.get $j) (i32.const 1)))
          (br $gather)))
        (local.set $kb (i32.add (local.get $xp) (local.get $ib)))
${shiftXyz('kb', 'add', (d) => `(local.get $d${d})`, 8)}        (br $next))))`;
}

/**
 * Orientation (projectOrientationPart in orientation-kernel.ts): the listed triangles `$t0..$t1` of a part, in the
 * loop's order and double-precision arithmetic, so that the result is its to the bit. `$mode` is ORIENT_FULL (0),
 * ORIENT_AGAIN (1) or ORIENT_WATCHED (2); `$floor` scales the bound. Arrays at bytes: positions `$xp`, corners `$cp`
 * (xyz offsets), frames `$fp` (xyzA), the unchecked and watched flags `$up`, `$wp` (bytes), each vertex's triangles'
 * CSR starts `$sp` and triangles `$vp`, each triangle's place in the list `$lp`. Returns 1 if a triangle was more than
 * a hair under its bound.
 */
function orientKernel() {
  const f = (v) => `(local.get $${v})`;
  const load = (base, o) => `(f64.promote_f32 (f32.load offset=${o} (local.get $${base})))`;
  const mark = (corner) => `
          (local.set $v (i32.div_u (local.get $${corner}) (i32.const 12)))
          (local.set $j (i32.load (i32.add (local.get $sp) (i32.shl (local.get $v) (i32.const 2)))))
          (local.set $j1 (i32.load offset=4 (i32.add (local.get $sp) (i32.shl (local.get $v) (i32.const 2)))))
          (block $m1 (loop $m
            (br_if $m1 (i32.ge_u (local.get $j) (local.get $j1)))
            (local.set $l (i32.load (i32.add (local.get $lp)
              (i32.shl (i32.load (i32.add (local.get $vp) (i32.shl (local.get $j) (i32.const 2)))) (i32.const 2)))))
            (if (i32.ge_s (local.get $l) (i32.const 0)) (then (i32.store8 (i32.add (local.get $up) (local.get $l)) (i32.const 1))))
            (local.set $j (i32.add (local.get $j) (i32.const 1)))
            (br $m)))`;

  return `
  (func (export "orient") (param $xp i32) (param $cp i32) (param $fp i32) (param $up i32) (param $wp i32) (param $sp i32)
    (param $vp i32) (param $lp i32) (param $t0 i32) (param $t1 i32) (param $mode i32) (param $floor f64) (result i32)
    (local $t i32) (local $flags i32) (local $a i32) (local $b i32) (local $c i32) (local $v i32) (local $j i32)
    (local $j1 i32) (local $l i32) (local $corrected i32) (local $ax f64) (local $ay f64) (local $az f64) (local $ux f64)
    (local $uy f64) (local $uz f64) (local $vx f64) (local $vy f64) (local $vz f64) (local $nx f64) (local $ny f64)
    (local $nz f64) (local $bound f64) (local $area f64) (local $least f64) (local $cc f64) (local $gax f64)
    (local $gay f64) (local $gaz f64) (local $gbx f64) (local $gby f64) (local $gbz f64) (local $gcx f64) (local $gcy f64)
    (local $gcz f64) (local $norm f64) (local $lambda f64)
    (local.set $flags (select (local.get $up) (local.get $wp) (i32.eq (local.get $mode) (i32.const 1))))
${loopOver('t', 't0', 't1')}        (if (i32.ne (local.get $mode) (i32.const 0)) (then
          ;; Four flags a word: a zero word skips four triangles.
          (if (i32.and (i32.eqz (i32.and (local.get $t) (i32.const 3)))
                (i32.eqz (i32.load (i32.add (local.get $flags) (local.get $t))))) (then
            (local.set $t (i32.add (local.get $t) (i32.const 4)))
            (br $next)))
          (if (i32.eqz (i32.load8_u (i32.add (local.get $flags) (local.get $t)))) (then
            (local.set $t (i32.add (local.get $t) (i32.const 1)))
            (br $next)))))
        (if (i32.ne (local.get $mode) (i32.const 2)) (then (i32.store8 (i32.add (local.get $up) (local.get $t)) (i32.const 0))))
        (local.set $l (i32.add (local.get $cp) (i32.mul (local.get $t) (i32.const 12))))
        (local.set $a (i32.add (local.get $xp) (i32.shl (i32.load (local.get $l)) (i32.const 2))))
        (local.set $b (i32.add (local.get $xp) (i32.shl (i32.load offset=4 (local.get $l)) (i32.const 2))))
        (local.set $c (i32.add (local.get $xp) (i32.shl (i32.load offset=8 (local.get $l)) (i32.const 2))))
        (local.set $ax ${load('a', 0)})
        (local.set $ay ${load('a', 4)})
        (local.set $az ${load('a', 8)})
        (local.set $ux (f64.sub ${load('b', 0)} ${f('ax')}))
        (local.set $uy (f64.sub ${load('b', 4)} ${f('ay')}))
        (local.set $uz (f64.sub ${load('b', 8)} ${f('az')}))
        (local.set $vx (f64.sub ${load('c', 0)} ${f('ax')}))
        (local.set $vy (f64.sub ${load('c', 4)} ${f('ay')}))
        (local.set $vz (f64.sub ${load('c', 8)} ${f('az')}))
        (local.set $l (i32.add (local.get $fp) (i32.shl (local.get $t) (i32.const 4))))
        (local.set $nx ${load('l', 0)})
        (local.set $ny ${load('l', 4)})
        (local.set $nz ${load('l', 8)})
        (local.set $bound ${load('l', 12)})
        (local.set $area (f64.add (f64.add
          (f64.mul ${f('nx')} (f64.sub (f64.mul ${f('uy')} ${f('vz')}) (f64.mul ${f('uz')} ${f('vy')})))
          (f64.mul ${f('ny')} (f64.sub (f64.mul ${f('uz')} ${f('vx')}) (f64.mul ${f('ux')} ${f('vz')}))))
          (f64.mul ${f('nz')} (f64.sub (f64.mul ${f('ux')} ${f('vy')}) (f64.mul ${f('uy')} ${f('vx')})))))
        (if (i32.and (i32.eqz (local.get $mode)) (f64.lt ${f('area')} (f64.mul (f64.const 1.5) ${f('bound')}))) (then
          (i32.store8 (i32.add (local.get $wp) (local.get $t)) (i32.const 1))))
        (local.set $least (f64.mul ${f('floor')} ${f('bound')}))
        (local.set $cc (f64.sub ${f('area')} ${f('least')}))
        (local.set $t (i32.add (local.get $t) (i32.const 1)))
        (br_if $next (f64.ge ${f('cc')} (f64.const 0)))
        (if (f64.lt ${f('cc')} (f64.mul (f64.const -0.01) ${f('least')})) (then (local.set $corrected (i32.const 1))))
        (local.set $gbx (f64.sub (f64.mul ${f('vy')} ${f('nz')}) (f64.mul ${f('vz')} ${f('ny')})))
        (local.set $gby (f64.sub (f64.mul ${f('vz')} ${f('nx')}) (f64.mul ${f('vx')} ${f('nz')})))
        (local.set $gbz (f64.sub (f64.mul ${f('vx')} ${f('ny')}) (f64.mul ${f('vy')} ${f('nx')})))
        (local.set $gcx (f64.sub (f64.mul ${f('ny')} ${f('uz')}) (f64.mul ${f('nz')} ${f('uy')})))
        (local.set $gcy (f64.sub (f64.mul ${f('nz')} ${f('ux')}) (f64.mul ${f('nx')} ${f('uz')})))
        (local.set $gcz (f64.sub (f64.mul ${f('nx')} ${f('uy')}) (f64.mul ${f('ny')} ${f('ux')})))
        (local.set $gax (f64.sub (f64.neg ${f('gbx')}) ${f('gcx')}))
        (local.set $gay (f64.sub (f64.neg ${f('gby')}) ${f('gcy')}))
        (local.set $gaz (f64.sub (f64.neg ${f('gbz')}) ${f('gcz')}))
        (local.set $norm (f64.add (f64.add (f64.add (f64.add (f64.add (f64.add (f64.add (f64.add
          (f64.mul ${f('gax')} ${f('gax')}) (f64.mul ${f('gay')} ${f('gay')})) (f64.mul ${f('gaz')} ${f('gaz')}))
          (f64.mul ${f('gbx')} ${f('gbx')})) (f64.mul ${f('gby')} ${f('gby')})) (f64.mul ${f('gbz')} ${f('gbz')}))
          (f64.mul ${f('gcx')} ${f('gcx')})) (f64.mul ${f('gcy')} ${f('gcy')})) (f64.mul ${f('gcz')} ${f('gcz')})))
        (if (f64.eq ${f('norm')} (f64.const 0)) (then
          ;; Not within its bound: check it again next time (the triangle is t - 1 now).
          (if (i32.ne (local.get $mode) (i32.const 2)) (then
            (i32.store8 (i32.sub (i32.add (local.get $up) (local.get $t)) (i32.const 1)) (i32.const 1))))
          (br $next)))
        (if (i32.ne (local.get $mode) (i32.const 2)) (then
          ;; The corners' addresses less the positions' are 4 * their xyz offsets: 12 * their vertices.
          (local.set $a (i32.sub (local.get $a) (local.get $xp)))
          (local.set $b (i32.sub (local.get $b) (local.get $xp)))
          (local.set $c (i32.sub (local.get $c) (local.get $xp)))${mark('a')}${mark('b')}${mark('c')}
          (local.set $a (i32.add (local.get $a) (local.get $xp)))
          (local.set $b (i32.add (local.get $b) (local.get $xp)))
          (local.set $c (i32.add (local.get $c) (local.get $xp)))))
        (local.set $lambda (f64.div (f64.neg ${f('cc')}) ${f('norm')}))
${['a', 'b', 'c'].map((k) => shiftXyz(k, 'add', (d) => `(f64.mul ${f('lambda')} ${f(`g${k}${d}`)})`, 8)).join('')}        (br $next)))
    (local.get $corrected))`;
}

/**
 * Position and muscle constraints (projectPositions in solver-kernels.ts) of region entries `$k0..$k1`, in the loop's
 * double-precision arithmetic, so that the result is its to the bit: `$s` the position stiffness, `$extra` the added
 * stiffness of skin sunk in, `$ms` the muscle stiffness. Arrays at bytes: positions `$xp`, rest `$rp`, rest normals
 * `$np`, targets `$tp`, weights `$wp` and normal weights `$hp`, the region's vertices `$vp`.
 */
function positionKernel() {
  const f = (v) => `(local.get $${v})`;
  const at = (base, o) => `(f64.promote_f32 (f32.load offset=${o} (i32.add (local.get $${base}) (local.get $ib))))`;
  const axes = ['x', 'y', 'z'];
  const toRest = axes.map((d, i) => `        (local.set $u${d} (f64.sub ${at('rp', 4 * i)} ${at('xp', 4 * i)}))\n`).join('');
  const normal = axes.map((d, i) => `        (local.set $n${d} ${at('np', 4 * i)})\n`).join('');
  const toTarget = axes.map((d, i) => `        (local.set $d${d} (f64.sub ${at('tp', 4 * i)} ${at('xp', 4 * i)}))\n`).join('');
  return `
  (func (export "positions") (param $xp i32) (param $rp i32) (param $np i32) (param $tp i32) (param $wp i32) (param $hp i32)
    (param $vp i32) (param $s f64) (param $extra f64) (param $ms f64) (param $k0 i32) (param $k1 i32)
    (local $k i32) (local $v i32) (local $ib i32) (local $a i32) (local $nx f64) (local $ny f64) (local $nz f64)
    (local $ux f64) (local $uy f64) (local $uz f64) (local $dx f64) (local $dy f64) (local $dz f64) (local $depth f64)
    (local $kk f64) (local $w f64) (local $wn f64) (local $m f64) (local $along f64)
${loopOver('k', 'k0', 'k1')}        (local.set $v (i32.load (i32.add (local.get $vp) (i32.shl (local.get $k) (i32.const 2)))))
        (local.set $k (i32.add (local.get $k) (i32.const 1)))
        (local.set $ib (i32.mul (local.get $v) (i32.const 12)))
        (local.set $a (i32.add (local.get $xp) (local.get $ib)))
${normal}${toRest}        (local.set $depth (f64.add (f64.add (f64.mul ${f('ux')} ${f('nx')}) (f64.mul ${f('uy')} ${f('ny')}))
          (f64.mul ${f('uz')} ${f('nz')})))
        (local.set $kk (select (f64.mul ${f('extra')} ${f('depth')}) (f64.const 0) (f64.gt ${f('depth')} (f64.const 0))))
${shiftXyz('a', 'add', (d) => `(f64.add (f64.mul ${f('s')} ${f(`u${d}`)}) (f64.mul ${f('kk')} ${f(`n${d}`)}))`, 8)}
        (local.set $w (f64.promote_f32 (f32.load (i32.add (local.get $wp) (i32.shl (local.get $v) (i32.const 2))))))
        (local.set $wn (f64.promote_f32 (f32.load (i32.add (local.get $hp) (i32.shl (local.get $v) (i32.const 2))))))
        (br_if $next (i32.and (f64.eq ${f('w')} (f64.const 0)) (f64.eq ${f('wn')} (f64.const 0))))
        (local.set $m (f64.mul ${f('ms')} ${f('w')}))
${toTarget}        (local.set $along (f64.mul (f64.sub (f64.mul ${f('ms')} ${f('wn')}) ${f('m')})
          (f64.add (f64.add (f64.mul ${f('dx')} ${f('nx')}) (f64.mul ${f('dy')} ${f('ny')})) (f64.mul ${f('dz')} ${f('nz')}))))
${shiftXyz('a', 'add', (d) => `(f64.add (f64.mul ${f('m')} ${f(`d${d}`)}) (f64.mul ${f('along')} ${f(`n${d}`)}))`, 8)}
        (br $next))))`;
}

/**
 * The collisions of one collider's candidates (projectCollisions in solver-kernels.ts, with shapeDistance in
 * colliders.ts), one at a time in their double-precision arithmetic, the direction rounded to single precision as the
 * loop's scratch array rounds it: the collider's shape (COLLIDER_SHAPE doubles) at byte $sp, the listed candidates
 * $k0..$k1 at byte $lp, their vertices, clearances and sides at bytes $vp, $cp and $dp.
 */
function collideKernel() {
  const f = (v) => `(local.get $${v})`;
  /** The shape's value `i` (a double). */
  const S = (i) => `(f64.load offset=${8 * i} (local.get $sp))`;
  /** `v` rounded to single precision and back, as a store into the loop's Float32Array scratch does. */
  const single = (v) => `(f64.promote_f32 (f32.demote_f64 ${v}))`;
  const dot = (ax, ay, az, bx, by, bz) => `(f64.add (f64.add (f64.mul ${ax} ${bx}) (f64.mul ${ay} ${by})) (f64.mul ${az} ${bz}))`;
  /** `v` clamped to 0..1 as the loop's `v < 0 ? 0 : v > 1 ? 1 : v` does (a NaN stays). */
  const clamp = (v) =>
    `(select (f64.const 0) (select (f64.const 1) ${f(v)} (f64.gt ${f(v)} (f64.const 1))) (f64.lt ${f(v)} (f64.const 0)))`;
  const axes = ['x', 'y', 'z'];
  const toShape = axes
    .map((d, i) => `        (local.set $r${d} (f64.sub (f64.promote_f32 (f32.load offset=${4 * i} (local.get $a))) ${S(i)}))\n`)
    .join('');
  const span = axes.map((d, i) => `            (local.set $s${d} (f64.sub ${S(3 + i)} ${S(i)}))\n`).join('');
  const normal = axes.map((d, i) => `              (local.set $n${d} ${S(13 + i)})\n`).join('');
  const face = axes.map((d) => `                (local.set $o${d} ${single(`(f64.mul ${f('side')} ${f(`n${d}`)})`)})\n`).join('');
  const up = axes.map((d, i) => `              (local.set $p${d} (f64.mul ${f('u')} ${S(6 + i)}))\n`).join('');
  const along = axes.map((d) => `            (local.set $p${d} (f64.add ${f(`p${d}`)} (f64.mul ${f('t')} ${f(`s${d}`)})))\n`).join('');
  const away = axes.map((d) => `          (local.set $d${d} (f64.sub ${f(`r${d}`)} ${f(`p${d}`)}))\n`).join('');
  const unit = axes.map((d) => `            (local.set $o${d} ${single(`(f64.div ${f(`d${d}`)} ${f('d')})`)})\n`).join('');
  return `
  (func (export "collide") (param $xp i32) (param $sp i32) (param $lp i32) (param $vp i32) (param $cp i32) (param $dp i32)
    (param $k0 i32) (param $k1 i32)
    (local $k i32) (local $j i32) (local $a i32) (local $kind f64) (local $side f64) (local $rx f64) (local $ry f64)
    (local $rz f64) (local $sx f64) (local $sy f64) (local $sz f64) (local $nx f64) (local $ny f64) (local $nz f64)
    (local $px f64) (local $py f64) (local $pz f64) (local $dx f64) (local $dy f64) (local $dz f64) (local $ox f64)
    (local $oy f64) (local $oz f64) (local $t f64) (local $u f64) (local $d f64) (local $dist f64) (local $push f64)
    (local.set $kind ${S(10)})
${loopOver('k', 'k0', 'k1')}        (local.set $j (i32.load (i32.add (local.get $lp) (i32.shl (local.get $k) (i32.const 2)))))
        (local.set $k (i32.add (local.get $k) (i32.const 1)))
        (local.set $a (i32.add (local.get $xp)
          (i32.mul (i32.load (i32.add (local.get $vp) (i32.shl (local.get $j) (i32.const 2)))) (i32.const 12))))
        (local.set $side (f64.convert_i32_s (i32.load8_s (i32.add (local.get $dp) (local.get $j)))))
${toShape}        (local.set $px (f64.const 0))
        (local.set $py (f64.const 0))
        (local.set $pz (f64.const 0))
        (block $measured
          ;; Not a sphere (kind 0): the nearest point of the segment, or of the slab's rectangle.
          (if (f64.ne ${f('kind')} (f64.const 0)) (then
${span}            (local.set $t (f64.mul ${dot(f('rx'), f('ry'), f('rz'), f('sx'), f('sy'), f('sz'))} ${S(11)}))
            (if (f64.eq ${f('kind')} (f64.const 2)) (then
              (local.set $u (f64.mul ${dot(f('rx'), f('ry'), f('rz'), S(6), S(7), S(8))} ${S(12)}))
${normal}              ;; Over the face of a one-sided slab: along its normal toward the candidate's rest side.
              (if (i32.and (i32.and (i32.and (f64.ne ${f('side')} (f64.const 0)) (f64.ge ${f('t')} (f64.const 0)))
                  (i32.and (f64.le ${f('t')} (f64.const 1)) (f64.ge ${f('u')} (f64.const 0))))
                  (i32.and (f64.le ${f('u')} (f64.const 1)) (i32.or (i32.or (f64.ne ${f('nx')} (f64.const 0))
                    (f64.ne ${f('ny')} (f64.const 0))) (f64.ne ${f('nz')} (f64.const 0))))) (then
${face}                (local.set $dist
                  (f64.sub (f64.mul ${f('side')} ${dot(f('rx'), f('ry'), f('rz'), f('nx'), f('ny'), f('nz'))}) ${S(9)}))
                (br $measured)))
              (local.set $u ${clamp('u')})
${up}))
            (local.set $t ${clamp('t')})
${along}))
${away}          (local.set $d (f64.sqrt ${dot(f('dx'), f('dy'), f('dz'), f('dx'), f('dy'), f('dz'))}))
          (if (f64.gt ${f('d')} (f64.const 0)) (then
${unit}) (else
            (local.set $ox (f64.const 0))
            (local.set $oy (f64.const 0))
            (local.set $oz (f64.const 1))))
          (local.set $dist (f64.sub ${f('d')} ${S(9)})))
        (local.set $push (f64.sub (f64.promote_f32 (f32.load (i32.add (local.get $cp) (i32.shl (local.get $j) (i32.const 2)))))
          ${f('dist')}))
        (br_if $next (i32.eqz (f64.gt ${f('push')} (f64.const 0))))
${shiftXyz('a', 'add', (d) => `(f64.mul ${f('push')} ${f(`o${d}`)})`, 8)}
        (br $next))))`;
}

/**
 * The normals (projectNormals in solver-kernels.ts, with addFaceNormals and normalize in topology.ts) in their
 * double-precision arithmetic: `faces` adds each listed triangle's area-weighted normal to its corners' (corners, as
 * xyz offsets, at byte $cp; triangles $t0..$t1), `units` scales each listed vertex's normal to unit length (the
 * vertex list at byte $vp; entries $k0..$k1), a zero one to +z.
 */
function normalKernels() {
  const f = (v) => `(local.get $${v})`;
  const axes = ['x', 'y', 'z'];
  const corner = (c, o) => `        (local.set $${c} (i32.shl (i32.load offset=${o} (local.get $p)) (i32.const 2)))\n`;
  const at = (c, i) => `(f64.promote_f32 (f32.load offset=${4 * i} (i32.add (local.get $xp) (local.get $${c}))))`;
  const edges = ['u', 'v']
    .map((e, k) => axes.map((d, i) => `        (local.set $${e}${d} (f64.sub ${at(k === 0 ? 'b' : 'c', i)} ${at('a', i)}))\n`).join(''))
    .join('');
  const cross = [
    ['x', 'y', 'z'],
    ['y', 'z', 'x'],
    ['z', 'x', 'y'],
  ]
    .map(
      ([d, p, q]) => `        (local.set $n${d} (f64.sub (f64.mul ${f(`u${p}`)} ${f(`v${q}`)}) (f64.mul ${f(`u${q}`)} ${f(`v${p}`)})))\n`,
    )
    .join('');
  const add = ['a', 'b', 'c']
    .map((c) => `        (local.set $q (i32.add (local.get $op) (local.get $${c})))\n${shiftXyz('q', 'add', (d) => f(`n${d}`), 8)}`)
    .join('');
  const unit = axes
    .map((_, i) => {
      const slot = `offset=${4 * i} (local.get $q)`;
      return `            (f32.store ${slot} (f32.demote_f64 (f64.div (f64.promote_f32 (f32.load ${slot})) ${f('len')})))\n`;
    })
    .join('');
  const load = (i) => `(f64.promote_f32 (f32.load offset=${4 * i} (local.get $q)))`;
  return `
  (func (export "faces") (param $xp i32) (param $cp i32) (param $op i32) (param $t0 i32) (param $t1 i32)
    (local $t i32) (local $p i32) (local $a i32) (local $b i32) (local $c i32) (local $q i32) (local $ux f64)
    (local $uy f64) (local $uz f64) (local $vx f64) (local $vy f64) (local $vz f64) (local $nx f64) (local $ny f64)
    (local $nz f64)
${loopOver('t', 't0', 't1')}        (local.set $p (i32.add (local.get $cp) (i32.mul (local.get $t) (i32.const 12))))
        (local.set $t (i32.add (local.get $t) (i32.const 1)))
${corner('a', 0)}${corner('b', 4)}${corner('c', 8)}${edges}${cross}${add}        (br $next))))
  (func (export "units") (param $op i32) (param $vp i32) (param $k0 i32) (param $k1 i32)
    (local $k i32) (local $q i32) (local $len f64)
${loopOver('k', 'k0', 'k1')}        (local.set $q (i32.add (local.get $op)
          (i32.mul (i32.load (i32.add (local.get $vp) (i32.shl (local.get $k) (i32.const 2)))) (i32.const 12))))
        (local.set $k (i32.add (local.get $k) (i32.const 1)))
        (local.set $len (f64.sqrt (f64.add (f64.add (f64.mul ${load(0)} ${load(0)}) (f64.mul ${load(1)} ${load(1)}))
          (f64.mul ${load(2)} ${load(2)}))))
        (if (f64.gt ${f('len')} (f64.const 0)) (then
${unit}) (else
          (f32.store offset=8 (local.get $q) (f32.const 1))))
        (br $next))))`;
}

/**
 * The frame's bookkeeping (startFramePart, relaxPart and recordStepsPart in frame-kernels.ts) over region entries
 * $k0..$k1 (the vertex list at byte $vp), in their double-precision arithmetic: `start` stores each vertex's place and
 * carries its momentum, `relax` lets each take its share of its solved move, `steps` stores each move, adds its length
 * to the vertex's way and returns the largest squared move.
 */
function frameKernels() {
  const f = (v) => `(local.get $${v})`;
  const axes = ['x', 'y', 'z'];
  /** The float at component `c` of the xyz at byte `$<base> + $ib`, promoted. */
  const at = (base, c) => `(f64.promote_f32 (f32.load offset=${4 * c} (i32.add (local.get $${base}) (local.get $ib))))`;
  /** The float of vertex $v in the per-vertex array at byte `$<base>`, promoted. */
  const one = (base) => `(f64.promote_f32 (f32.load (i32.add (local.get $${base}) (i32.shl (local.get $v) (i32.const 2)))))`;
  const byte = (base) => `(i32.add (local.get $${base}) (local.get $v))`;
  const dot = (a, b) =>
    `(f64.add (f64.add (f64.mul ${f(`${a}x`)} ${f(`${b}x`)}) (f64.mul ${f(`${a}y`)} ${f(`${b}y`)})) (f64.mul ${f(`${a}z`)} ${f(`${b}z`)}))`;
  const vertex = `        (local.set $v (i32.load (i32.add (local.get $vp) (i32.shl (local.get $k) (i32.const 2)))))
        (local.set $k (i32.add (local.get $k) (i32.const 1)))
        (local.set $ib (i32.mul (local.get $v) (i32.const 12)))
`;
  const slot = (base, c) => `offset=${4 * c} (i32.add (local.get $${base}) (local.get $ib))`;
  const copy = axes.map((_, c) => `        (f32.store ${slot('pp', c)} (f32.load ${slot('xp', c)}))\n`).join('');
  const lastAndNormal = axes
    .map((d, c) => `        (local.set $l${d} ${at('lp', c)})\n        (local.set $n${d} ${at('np', c)})\n`)
    .join('');
  const carried = (d) => `(f64.add (f64.mul ${f('beta')} ${f(`l${d}`)}) (f64.mul ${f('along')} ${f(`n${d}`)}))`;
  const solved = axes.map((d, c) => `        (local.set $d${d} (f64.sub ${at('xp', c)} ${at('pp', c)}))\n`).join('');
  const lastOnly = axes.map((d, c) => `        (local.set $l${d} ${at('lp', c)})\n`).join('');
  const share = axes
    .map((d, c) => {
      const slot = `offset=${4 * c} (i32.add (local.get $xp) (local.get $ib))`;
      return `        (f32.store ${slot} (f32.demote_f64 (f64.add ${at('pp', c)} (f64.mul ${f('w')} ${f(`d${d}`)}))))\n`;
    })
    .join('');
  const store = axes
    .map((d, c) => `        (f32.store offset=${4 * c} (i32.add (local.get $lp) (local.get $ib)) (f32.demote_f64 ${f(`d${d}`)}))\n`)
    .join('');
  const xyz = (p) => axes.map((d) => `(local $${p}${d} f64)`).join(' ');
  return `
  (func (export "start") (param $xp i32) (param $pp i32) (param $np i32) (param $lp i32) (param $rp i32) (param $sp i32)
    (param $vp i32) (param $beta f64) (param $extra f64) (param $carry i32) (param $k0 i32) (param $k1 i32)
    (local $k i32) (local $v i32) (local $ib i32) (local $a i32) (local $along f64) ${xyz('l')} ${xyz('n')}
${loopOver('k', 'k0', 'k1')}${vertex}${copy}        (br_if $next (i32.eqz (local.get $carry)))
        (if (i32.or (i32.eq (i32.load8_u ${byte('rp')}) (i32.const 1)) (f64.lt ${one('sp')} (f64.const 1))) (then
          (i32.store8 ${byte('rp')} (i32.const 0))
          (br $next)))
${lastAndNormal}        (local.set $along (f64.mul ${f('extra')} ${dot('l', 'n')}))
        (local.set $a (i32.add (local.get $xp) (local.get $ib)))
${shiftXyz('a', 'add', carried, 8)}        (br $next))))
  (func (export "relax") (param $xp i32) (param $pp i32) (param $lp i32) (param $sp i32) (param $cp i32) (param $rp i32)
    (param $vp i32) (param $cap f64) (param $least f64) (param $within i32) (param $k0 i32) (param $k1 i32)
    (local $k i32) (local $v i32) (local $ib i32) (local $calm i32) (local $turn f64) (local $w f64) ${xyz('d')} ${xyz('l')}
${loopOver('k', 'k0', 'k1')}${vertex}${solved}${lastOnly}        (local.set $turn ${dot('d', 'l')})
        (if (f64.lt ${f('turn')} (f64.const 0)) (then (i32.store8 ${byte('rp')} (i32.const 1))))
        (local.set $w ${one('sp')})
        (local.set $calm (i32.load8_u ${byte('cp')}))
        ;; Turned back by more than 120 degrees: a cycle, not a curve.
        (if (i32.and (f64.lt ${f('turn')} (f64.const 0))
            (f64.gt (f64.mul (f64.mul (f64.const 4) ${f('turn')}) ${f('turn')}) (f64.mul ${dot('d', 'd')} ${dot('l', 'l')}))) (then
          (if (i32.and (f64.gt ${f('w')} ${f('least')}) (i32.lt_u (local.get $calm) (local.get $within))) (then
            (local.set $w (f64.mul ${f('w')} (f64.const 0.5)))
            (f32.store (i32.add (local.get $sp) (i32.shl (local.get $v) (i32.const 2))) (f32.demote_f64 ${f('w')}))))
          (i32.store8 ${byte('cp')} (i32.const 0)))
        (else
          (if (i32.lt_u (local.get $calm) (i32.const 255)) (then
            (i32.store8 ${byte('cp')} (i32.add (local.get $calm) (i32.const 1)))))))
        (if (f64.gt ${f('w')} ${f('cap')}) (then (local.set $w ${f('cap')})))
        (br_if $next (f64.eq ${f('w')} (f64.const 1)))
${share}        (br $next))))
  (func (export "steps") (param $xp i32) (param $pp i32) (param $lp i32) (param $hp i32) (param $vp i32) (param $k0 i32)
    (param $k1 i32) (result f64)
    (local $k i32) (local $v i32) (local $ib i32) (local $d2 f64) (local $largest f64) ${xyz('d')}
${loopOver('k', 'k0', 'k1')}${vertex}${solved}${store}        (local.set $d2 ${dot('d', 'd')})
        (if (f64.gt ${f('d2')} ${f('largest')}) (then (local.set $largest ${f('d2')})))
        (f32.store (i32.add (local.get $hp) (i32.shl (local.get $v) (i32.const 2)))
          (f32.demote_f64 (f64.add ${one('hp')} (f64.sqrt ${f('d2')}))))
        (br $next)))
    (local.get $largest))`;
}

/** The TypeScript module that carries the kernel's bytes. */
async function source() {
  const wabt = await wabtInit();
  const module = wabt.parseWat('lengths.wat', lengthKernel(true), { simd: true, threads: true });
  const { buffer } = module.toBinary({});
  module.destroy();
  const lines = Buffer.from(buffer)
    .toString('base64')
    .match(/.{1,100}/g)
    .map((l) => `  '${l}',`);
  return [
    '// Made by scripts/build-kernels.mjs (npm run build:kernels) from the text it holds; do not edit.',
    '',
    '/**',
    " * The solver's kernels (see wasm-kernels.ts) on a shared memory, as base64 of their binary; the same on a plain memory",
    " * differs in one byte, the memory import's flags.",
    ' */',
    'export const KERNELS = [',
    ...lines,
    "].join('');",
    '',
  ].join('\n');
}

if (process.argv.includes('--print')) {
  process.stdout.write(lengthKernel(true));
  process.exit(0);
}
const text = await source();
if (process.argv.includes('--check')) {
  if (readFileSync(OUT, 'utf8') !== text) {
    console.error('build-kernels: src/core/solver/wasm-kernels-bytes.ts differs from its source; run npm run build:kernels');
    process.exit(1);
  }
} else writeFileSync(OUT, text);
