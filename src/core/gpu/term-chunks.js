// @ts-check
// The GLSL dispatch of each term family, generated from the catalogue (src/math/catalogue): one chunk per family
// ('ndf-term.glsl', 'visibility-term.glsl', 'fresnel-term.glsl') that defines the family's dispatch function
// (ndfTerm, visibilityTerm, fresnelTerm) as an explicit chain over the terms' defines, each branch including the
// term's chunk and declaring the uniforms its call reads, and #error when no define of the family is given.
// A new catalogue entry with a define and a glslCall is in the chain with no other edit. Last in the chain, the
// family's user-written term (CUSTOM_TERMS): its chunk is the user's code, which a widget adds to the chunks
// (src/core/custom/assemble.js, withCustomChunk).
import { CUSTOM_TERMS } from '../../math/catalogue/index.js';

/**
 * The dispatch chunk of one family, or null for a family without a generated dispatch.
 * @param {import('../../math/catalogue/types.js').TermFamily} family
 * @param {string} host the chunk whose #error names the missing choice
 * @returns {string | null}
 */
export function termDispatchChunk(family, host = 'brdf.glsl') {
  if (!family.glslSignature) return null;
  const lines = [
    `// ${family.glslDispatch}: ${family.label}, picked by ${family.definePrefix}_* (src/math/catalogue).`,
  ];
  const custom = CUSTOM_TERMS[family.family];
  const offered = [...Object.values(family.terms), ...(custom ? [custom] : [])].filter(
    (term) => term.define && term.glslCall,
  );
  offered.forEach((term, i) => {
    lines.push(`${i === 0 ? '#if' : '#elif'} defined(${term.define})`);
    if (term.chunk) lines.push(`#include "${term.chunk}"`);
    for (const [name, type] of Object.entries(term.uniforms ?? {})) lines.push(`uniform ${type} ${name};`);
    lines.push(`${family.glslSignature} { return ${term.glslCall}; }`);
  });
  lines.push('#else', `#error "${host}: no ${family.definePrefix}_* chosen"`, '#endif');
  return lines.join('\n');
}

/**
 * Every generated dispatch chunk by its file name ('<family>-term.glsl').
 * @param {Record<string, import('../../math/catalogue/types.js').TermFamily>} catalogue
 * @returns {Record<string, string>}
 */
export function termDispatchChunks(catalogue) {
  return Object.fromEntries(
    Object.values(catalogue)
      .map((family) => [`${family.family}-term.glsl`, termDispatchChunk(family)])
      .filter(([, text]) => text !== null),
  );
}
