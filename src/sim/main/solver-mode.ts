import type { SolverMode } from '../shared/protocol';

const MODES: readonly SolverMode[] = ['shared', 'transfer', 'main'];

/** A solver mode and, if the request could not be met, why. */
export interface SolverModeChoice {
  mode: SolverMode;
  warning?: string;
}

/**
 * `?solver=shared|transfer|main` picks the mode; otherwise `shared` where SharedArrayBuffer exists (cross-origin
 * isolated pages) and `transfer` elsewhere. `shared` on a page without isolation falls back to `transfer`.
 */
export function chooseSolverMode(search: string, isolated: boolean): SolverModeChoice {
  const automatic: SolverMode = isolated ? 'shared' : 'transfer';
  const requested = new URLSearchParams(search).get('solver');
  if (requested === null) return { mode: automatic };
  if (!MODES.includes(requested as SolverMode)) {
    return { mode: automatic, warning: `?solver=${requested} is not one of ${MODES.join(', ')}; using ${automatic}` };
  }
  if (requested === 'shared' && !isolated) {
    return { mode: 'transfer', warning: '?solver=shared needs a cross-origin isolated page (SharedArrayBuffer); using transfer' };
  }
  return { mode: requested as SolverMode };
}

/** `?workers=1|2` asks for one solver thread or two (`shared` mode only); anything else leaves the choice to the machine. */
export function chooseWorkers(search: string): 1 | 2 | 'auto' {
  const requested = new URLSearchParams(search).get('workers');
  return requested === '1' ? 1 : requested === '2' ? 2 : 'auto';
}
