import { SOLVER_CHOICES, type SolverChoice } from '../embed/index';

/**
 * The app's `?solver=shared|transfer|main` picks where the solver runs (createFace falls back from `shared` on a page
 * that is not cross-origin isolated, with a warning); anything else, or nothing, is `auto`, with a warning for a typo.
 */
export function requestedSolver(search: string): SolverChoice {
  const requested = new URLSearchParams(search).get('solver');
  if (requested === null) return 'auto';
  if (SOLVER_CHOICES.includes(requested as SolverChoice)) return requested as SolverChoice;
  console.warn(`?solver=${requested} is not one of ${SOLVER_CHOICES.join(', ')}; using auto`);
  return 'auto';
}

/** `?workers=1|2` asks for one solver thread or two (`shared` mode only); anything else leaves the choice to the machine. */
export function requestedWorkers(search: string): 1 | 2 | 'auto' {
  const requested = new URLSearchParams(search).get('workers');
  return requested === '1' ? 1 : requested === '2' ? 2 : 'auto';
}
