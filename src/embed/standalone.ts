/**
 * The standalone module's entry: everything of `softface` and `softface/element` (so `<soft-face>` is registered),
 * with three.js bundled in, for a `<script type="module">` on a static host.
 */
export * from './index';
export * from './element';
