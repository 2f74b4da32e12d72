// @ts-check
// A user-written term as a GLSL chunk a program includes ('custom.glsl'): common.glsl first (PI, saturate,
// sin2FromCos), then the user's code after `#line 1 1`, so the compiler's log names the user's own lines in source
// string 1, then `#line 1 2`, so what follows in the program is never mistaken for the user's (string 2).
// The code is the one parseCustom accepted: slider uniforms stay as the user wrote them.
import { slotOf } from './slots.js';

export const CUSTOM_CHUNK = 'custom.glsl';
/** The source string the compiler's log gives the user's lines, and the one of what follows them. */
export const USER_SOURCE = 1;
export const AFTER_USER_SOURCE = 2;

/**
 * The chunk of a slot's code.
 * @param {string} slotKey a key of SLOTS
 * @param {string} code code that passed parseCustom (no preprocessor lines)
 * @returns {string}
 */
export function customChunk(slotKey, code) {
  const slot = slotOf(slotKey);
  const text = code.replace(/\r\n?/g, '\n');
  if (/^\s*#/m.test(text))
    throw new Error(`custom: ${slot.fn}'s code has a preprocessor line (parseCustom refuses it)`);
  return [
    `// ${slot.signature}, written by the user (lines of source string ${USER_SOURCE})`,
    '#include "common.glsl"',
    `#line 1 ${USER_SOURCE}`,
    text,
    `#line 1 ${AFTER_USER_SOURCE}`,
  ].join('\n');
}

/**
 * The shader chunks with the custom chunk added, for assembleGlsl's `chunks`.
 * @param {Record<string, string>} chunks
 * @param {string} slotKey
 * @param {string} code
 */
export const withCustomChunk = (chunks, slotKey, code) => ({ ...chunks, [CUSTOM_CHUNK]: customChunk(slotKey, code) });
