/**
 * Problems in a rig document and how they are reported: each with its path and an "expected ..., got ..." message,
 * gathered into a `RigError` whose message lists them (timelines report theirs the same way).
 */
import type * as v from 'valibot';
import { show } from '../check';

/** At most this many problems are spelled out in an error's message; `RigError.problems` has them all. */
const MAX_LISTED_PROBLEMS = 50;

/** One problem in a rig document: where (`muscles[3].radii[1]`, or '' for the whole document) and what is wrong. */
export interface RigProblem {
  /** Where in the document: a path like `muscles[3].radii[1]` or `presets[0].name`; '' for the whole document. */
  path: string;
  /** What is wrong, as "expected ..., got ..." (or e.g. `missing`, `unknown field`). */
  message: string;
}

/** A rig document that was refused: its message has one line per problem, `source: path: what is wrong`. */
export class RigError extends Error {
  readonly source: string;
  readonly problems: readonly RigProblem[];

  constructor(source: string, problems: readonly RigProblem[]) {
    const lines = problems
      .slice(0, MAX_LISTED_PROBLEMS)
      .map((p) => (p.path ? `${source}: ${p.path}: ${p.message}` : `${source}: ${p.message}`));
    if (problems.length > lines.length) lines.push(`${source}: and ${problems.length - lines.length} more problems`);
    super(lines.join('\n'));
    this.name = 'RigError';
    this.source = source;
    this.problems = problems;
  }
}

/** A valibot issue as a problem: its path and an "expected ..., got ..." message (also used for timelines). */
export function problemOf(issue: v.BaseIssue<unknown>): RigProblem {
  const path = pathOf(issue.path);
  // valibot reports a key that a strict object or tuple does not allow as expecting "never".
  if (issue.expected === 'never')
    return { path, message: issue.type === 'strict_tuple' ? 'unexpected extra item (expected 3 numbers)' : 'unknown field' };
  if (issue.input === undefined && issue.path !== undefined) return { path, message: 'missing' };
  return { path, message: `${issue.message}, got ${show(issue.input)}` };
}

function pathOf(path: readonly { key: unknown }[] | undefined): string {
  let out = '';
  for (const { key } of path ?? []) out += pathStep(key, out === '');
  return out;
}

/** One step of a problem's path: `[3]`, `.name`, or `["preset:happiness"]` for a key that is no identifier. */
export function pathStep(key: unknown, first: boolean): string {
  if (typeof key === 'number') return `[${key}]`;
  const k = String(key);
  if (/^[A-Za-z_$][\w$]*$/.test(k)) return first ? k : `.${k}`;
  return `[${JSON.stringify(k)}]`;
}
