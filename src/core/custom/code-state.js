// @ts-check
// A user-written term as a URL and a parent frame's message carry it: the text itself, or, when that is shorter
// in a URL, compressed with lz-string (its URL-safe alphabet) and marked with a prefix. Decoding refuses, with a
// message a page can show, whatever is too long, not text, or not a valid compressed code.
import LZString from 'lz-string';

/** The longest code a term may have, in characters (a few hundred lines; a URL stays under ~16 kB). */
export const MAX_CODE_CHARS = 8000;
/** The most sliders a code declares, and so the most slider values a state's `params` holds (state.js). */
export const MAX_PARAMS = 16;
/**
 * A decimal number as a URL and a slider line write it: 12, -0.5, .5, 1e-3. Not hex, binary, Infinity or other
 * digits (state.js reads the URL's numbers with it, parse-sliders.js a slider's MIN MAX DEFAULT).
 */
export const DECIMAL = /^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i;
/**
 * The longest encoded form read: never more than the plain text's limit (compression only shortens). lz-string has
 * no output limit of its own: a crafted 8000-character payload decompresses to at most about 10 million characters
 * (measured: 48 ms in Node 20) before the length check refuses it.
 */
const MAX_ENCODED_CHARS = MAX_CODE_CHARS;
export const COMPRESSED_PREFIX = 'lz:';
/** Whether text holds a control character an editor does not type (tab, newline, carriage return are fine). */
const hasControl = (/** @type {string} */ text) =>
  [...text].some((ch) => {
    const c = ch.charCodeAt(0);
    return (c < 32 && c !== 9 && c !== 10 && c !== 13) || c === 127;
  });

/** The length of a value once a URL's query holds it. @param {string} value */
const inUrl = (value) => new URLSearchParams({ c: value }).toString().length - 2;

/**
 * The form of `code` a URL carries: compressed (marked) when that is shorter, else the code itself. A code that
 * itself begins with the mark is always compressed, so decoding is never ambiguous.
 * @param {string} code
 * @returns {string}
 */
export function encodeCode(code) {
  const compressed = COMPRESSED_PREFIX + LZString.compressToEncodedURIComponent(code);
  if (code.startsWith(COMPRESSED_PREFIX)) return compressed;
  return inUrl(compressed) < inUrl(code) ? compressed : code;
}

/**
 * The code a URL or a message carried (plain or compressed), or why it cannot be taken.
 * @param {unknown} text
 * @returns {{ code: string } | { error: string }}
 */
export function decodeCode(text) {
  if (typeof text !== 'string') return { error: 'the code is not text' };
  if (text.length > MAX_ENCODED_CHARS)
    return { error: `the code has ${text.length} characters; at most ${MAX_CODE_CHARS} are taken` };
  let code = text;
  if (text.startsWith(COMPRESSED_PREFIX)) {
    const payload = text.slice(COMPRESSED_PREFIX.length);
    const out = payload && LZString.decompressFromEncodedURIComponent(payload);
    if (!out) return { error: 'the compressed code is damaged (it does not decompress)' };
    code = out;
  }
  if (code.length > MAX_CODE_CHARS)
    return { error: `the code has ${code.length} characters once decompressed; at most ${MAX_CODE_CHARS}` };
  if (hasControl(code)) return { error: 'the code holds control characters that no shader takes' };
  return { code };
}
