/**
 * The standalone module's entry: everything of `softface` and `softface/element` (so `<soft-face>` is registered),
 * with three.js bundled in, for a `<script type="module">` on a static host.
 *
 * @module softface/standalone
 */
export * from './index';
export * from './element';
