/** JSON documents as text: their size in bytes and where and why a text is not valid JSON (rigs and timelines). */

/** The length of a text in bytes of UTF-8. */
export function utf8Length(s: string): number {
  let n = 0;
  for (let i = 0; i < s.length; i++) {
    const c = s.charCodeAt(i);
    if (c < 0x80) n += 1;
    else if (c < 0x800) n += 2;
    else if (c >= 0xd800 && c <= 0xdbff && i + 1 < s.length) {
      n += 4; // a surrogate pair is one 4-byte character
      i++;
    } else n += 3;
  }
  return n;
}

/** A size in bytes as mebibytes for messages: `5 MiB`. */
export function megabytes(bytes: number): string {
  return `${Number((bytes / (1024 * 1024)).toFixed(2))} MiB`;
}

/**
 * Where and why JSON text is invalid. Engines word (and place) JSON.parse errors differently, and some give no
 * position, so the text is scanned here; the engine's message is the fallback should the scan find nothing.
 */
export function jsonSyntaxMessage(text: string, error: unknown): string {
  const found = findJsonError(text);
  if (!found) return `invalid JSON: ${error instanceof Error ? error.message : String(error)}`;
  const before = text.slice(0, found.offset);
  const line = before.split('\n').length;
  const column = found.offset - before.lastIndexOf('\n');
  return `invalid JSON at line ${line}, column ${column}: expected ${found.expected}, got ${showChar(text, found.offset)}`;
}

function showChar(text: string, offset: number): string {
  if (offset >= text.length) return 'the end of the text';
  const c = text.charCodeAt(offset);
  return c > 0x20 && c < 0x7f ? `'${text[offset]}'` : `U+${c.toString(16).toUpperCase().padStart(4, '0')}`;
}

interface JsonError {
  offset: number;
  expected: string;
}

const NUMBER = /-?(?:0|[1-9]\d*)(?:\.\d+)?(?:[eE][+-]?\d+)?/y;
const WHITESPACE = /[ \t\n\r]*/y;

function skipWhitespace(text: string, i: number): number {
  WHITESPACE.lastIndex = i;
  WHITESPACE.test(text);
  return WHITESPACE.lastIndex;
}

/** The first JSON syntax error in `text`, or undefined if it is valid; iterative, so deep nesting cannot overflow. */
function findJsonError(text: string): JsonError | undefined {
  const open: string[] = [];
  let want: 'value' | 'value or ]' | 'key' | 'key or }' | 'colon' | 'next' = 'value';
  let i = skipWhitespace(text, 0);
  for (;;) {
    const c = text[i];
    if (want === 'next') {
      const top = open[open.length - 1];
      if (top === undefined) return i === text.length ? undefined : { offset: i, expected: 'the end of the text after the document' };
      if (c === ',') want = top === '{' ? 'key' : 'value';
      else if (c === (top === '{' ? '}' : ']')) open.pop();
      else return { offset: i, expected: top === '{' ? "',' or '}' after a property value" : "',' or ']' after an array item" };
      i++;
    } else if (want === 'colon') {
      if (c !== ':') return { offset: i, expected: "':' after a property name" };
      want = 'value';
      i++;
    } else if (want === 'key' || want === 'key or }') {
      if (want === 'key or }' && c === '}') {
        open.pop();
        want = 'next';
        i++;
      } else if (c === '"') {
        const end = scanString(text, i);
        if (typeof end !== 'number') return end;
        want = 'colon';
        i = end;
      } else
        return { offset: i, expected: want === 'key' ? 'a property name in double quotes' : "a property name in double quotes or '}'" };
    } else {
      const step = scanValueStart(text, i, want === 'value or ]');
      if ('expected' in step) return step;
      if (step.opened) open.push(step.opened);
      else if (step.closed) open.pop();
      want = step.opened === '{' ? 'key or }' : step.opened === '[' ? 'value or ]' : 'next';
      i = step.end;
    }
    i = skipWhitespace(text, i);
  }
}

/** Where a value that starts at `i` ends (strings, numbers, literals), or the container it opens or closes. */
function scanValueStart(text: string, i: number, mayClose: boolean): JsonError | { end: number; opened?: string; closed?: boolean } {
  const c = text[i];
  if (c === '{' || c === '[') return { end: i + 1, opened: c };
  if (mayClose && c === ']') return { end: i + 1, closed: true };
  if (c === '"') {
    const end = scanString(text, i);
    return typeof end === 'number' ? { end } : end;
  }
  for (const word of ['true', 'false', 'null']) if (text.startsWith(word, i)) return { end: i + word.length };
  NUMBER.lastIndex = i;
  if (NUMBER.test(text)) return { end: NUMBER.lastIndex };
  return { offset: i, expected: mayClose ? "a value or ']'" : 'a value' };
}

/** The offset after the string that opens at `i`, or where it goes wrong. */
function scanString(text: string, i: number): number | JsonError {
  for (let k = i + 1; k < text.length; k++) {
    const c = text.charCodeAt(k);
    if (c === 0x22) return k + 1;
    if (c < 0x20) return { offset: k, expected: "a closing '\"' (control characters in strings must be escaped)" };
    if (c === 0x5c) {
      const e = text[k + 1];
      if (e === 'u') {
        if (!/^[0-9a-fA-F]{4}$/.test(text.slice(k + 2, k + 6))) return { offset: k, expected: 'an escape \\u followed by 4 hex digits' };
        k += 5;
      } else if (e !== undefined && '"\\/bfnrt'.includes(e)) k++;
      else return { offset: k, expected: 'an escape: \\" \\\\ \\/ \\b \\f \\n \\r \\t or \\uXXXX' };
    }
  }
  return { offset: text.length, expected: "a closing '\"' for the string" };
}
