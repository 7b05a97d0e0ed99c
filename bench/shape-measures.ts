/** What the benchmarks measure of shapes and timings: the 2 % criterion, the largest vertex distance, quantiles. */

/** "Within 2 % of the final shape": every vertex nearer its final place than this share of the largest final move. */
export const NEAR_FINAL = 0.02;

/** The largest distance of a vertex of `a` from its place in `b` (xyz per vertex). */
export function largestDistance(a: Float32Array, b: Float32Array): number {
  let worst = 0;
  for (let i = 0; i < a.length; i += 3) {
    const d = (a[i] - b[i]) ** 2 + (a[i + 1] - b[i + 1]) ** 2 + (a[i + 2] - b[i + 2]) ** 2;
    if (d > worst) worst = d;
  }
  return Math.sqrt(worst);
}

/** The `q` quantile of ascending `sorted` (the element at that share of the list). */
export const quantile = (sorted: number[], q: number): number => sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))];

/** The median of `xs`. */
export const median = (xs: number[]): number =>
  quantile(
    [...xs].sort((a, b) => a - b),
    0.5,
  );
