/**
 * Runs a face's take-back steps last first; every step runs even if one fails, and the first failure is thrown after
 * the rest have run.
 */
export function takeBack(steps: readonly (() => void)[]): void {
  let failure: unknown;
  for (let i = steps.length - 1; i >= 0; i--) {
    try {
      steps[i]();
    } catch (error) {
      failure ??= error;
    }
  }
  if (failure !== undefined) throw failure;
}
