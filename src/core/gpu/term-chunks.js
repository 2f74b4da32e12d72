// @ts-check
// The GLSL dispatch of each term family, generated from the catalogue (src/math/catalogue): one chunk per family
// ('ndf-term.glsl', 'visibility-term.glsl', 'fresnel-term.glsl') that defines the family's dispatch function
// (ndfTerm, visibilityTerm, fresnelTerm) as an explicit chain over the terms' defines, each branch including the
// term's chunk and declaring the uniforms its call reads, and #error when no define of the family is given.
// ndfTerm and visibilityTerm take the microfacet input (shaders/microfacet-input.glsl): a term's call is its
// function over its args, each a field of the input (FIELDS[arg].glsl) or a parameter's uniform, then its
// normaliser's uniform. A new catalogue entry with a define is in the chain with no other edit. Last in the chain,
// the family's user-written term (CUSTOM_TERMS): its chunk is the user's code, which a widget adds to the chunks
// (src/core/custom/assemble.js, withCustomChunk). Also generated: 'parameters.glsl' (the shared ranges) and
// 'ndf-sampler.glsl' (sampleLobeNormal over the NDFs that declare a sampler).
import { CUSTOM_TERMS } from '../../math/catalogue/index.js';
import { FIELDS } from '../../math/catalogue/microfacet-input.js';
import { parametersGlsl } from '../../math/catalogue/parameters.js';

/** @typedef {import('../../math/catalogue/types.js').TermEntry} TermEntry */
/** @typedef {import('../../math/catalogue/types.js').TermFamily} TermFamily */

const GLSL_TYPE = { float: 'float', vec2: 'vec2', colour: 'vec3' };

/**
 * The uniforms a term's call reads, name → GLSL type: each parameter's that is no field of the input, and the
 * normaliser's.
 * @param {TermEntry} term
 * @returns {Record<string, string>}
 */
export function termUniformTypes(term) {
  /** @type {Record<string, string>} */
  const out = {};
  for (const arg of term.args) {
    const param = term.params[arg];
    if (param?.uniform && !FIELDS[arg]) out[param.uniform] = GLSL_TYPE[param.kind ?? 'float'];
  }
  if (term.normaliserUniform) out[term.normaliserUniform] = 'float';
  return out;
}

/**
 * A term's expression in its family's dispatch: its glslCall, or its function over its args (fields of the
 * microfacet input `m`, parameters' uniforms) and its normaliser's uniform.
 * @param {TermEntry} term
 */
export function termCall(term) {
  if (term.glslCall) return term.glslCall;
  const arg = (/** @type {string} */ name) => {
    const glsl = FIELDS[name]?.glsl ?? term.params[name]?.uniform;
    if (!glsl) throw new Error(`catalogue: ${term.glsl}'s argument '${name}' is no input field nor bound uniform`);
    return glsl;
  };
  const args = [...term.args.map(arg), ...(term.normaliserUniform ? [term.normaliserUniform] : [])];
  return `${term.glsl}(${args.join(', ')})`;
}

/**
 * The dispatch chunk of one family, or null for a family without a generated dispatch.
 * @param {TermFamily} family
 * @param {string} host the chunk whose #error names the missing choice
 * @returns {string | null}
 */
export function termDispatchChunk(family, host = 'brdf.glsl') {
  if (!family.glslSignature) return null;
  const lines = [
    `// ${family.glslDispatch}: ${family.label}, picked by ${family.definePrefix}_* (src/math/catalogue).`,
    ...(family.microfacetInput ? ['#include "microfacet-input.glsl"'] : []),
  ];
  const custom = CUSTOM_TERMS[family.family];
  const offered = [...Object.values(family.terms), ...(custom ? [custom] : [])].filter(
    (term) => term.define && (term.glslCall || (family.microfacetInput && term.glsl)),
  );
  offered.forEach((term, i) => {
    lines.push(`${i === 0 ? '#if' : '#elif'} defined(${term.define})`);
    if (term.chunk) lines.push(`#include "${term.chunk}"`);
    // F's dispatch takes its parameters (f0) as arguments; D and V read theirs from uniforms
    const uniforms = family.microfacetInput ? termUniformTypes(term) : {};
    for (const [name, type] of Object.entries(uniforms)) lines.push(`uniform ${type} ${name};`);
    lines.push(`${family.glslSignature} { return ${termCall(term)}; }`);
  });
  lines.push('#else', `#error "${host}: no ${family.definePrefix}_* chosen"`, '#endif');
  return lines.join('\n');
}

/**
 * sampleLobeNormal(u, alpha) of the chosen NDF, over the terms whose entry names a sampler (capabilities.sampler,
 * a function of integrate.glsl), #error for any other.
 * @param {TermFamily} ndf
 */
export function samplerChunk(ndf) {
  const sampled = Object.values(ndf.terms).filter((term) => term.capabilities?.sampler);
  const lines = ['// sampleLobeNormal: the chosen NDF\u2019s importance sampler (src/math/catalogue, capabilities).'];
  sampled.forEach((term, i) => {
    lines.push(`${i === 0 ? '#if' : '#elif'} defined(${term.define})`);
    lines.push(`vec3 sampleLobeNormal(vec2 u, float alpha) { return ${term.capabilities?.sampler}(u, alpha); }`);
  });
  const names = sampled.map((term) => term.define).join(' and ');
  lines.push('#else', `#error "ndf-sampling.glsl: only ${names} are sampled"`, '#endif');
  return lines.join('\n');
}

/**
 * Every generated chunk by its file name: each family's dispatch ('<family>-term.glsl'), 'parameters.glsl' and
 * 'ndf-sampler.glsl'.
 * @param {Record<string, TermFamily>} catalogue
 * @returns {Record<string, string>}
 */
export function termDispatchChunks(catalogue) {
  const dispatch = Object.values(catalogue)
    .map((family) => [`${family.family}-term.glsl`, termDispatchChunk(family)])
    .filter(([, text]) => text !== null);
  return {
    ...Object.fromEntries(dispatch),
    'parameters.glsl': parametersGlsl(),
    'ndf-sampler.glsl': samplerChunk(catalogue.ndf),
  };
}
