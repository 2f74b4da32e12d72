// @ts-check
// Parity rows of the generated dispatch itself: each D and V term through ndfTerm(m) / visibilityTerm(m), the
// microfacet input m filled field by field from the term's args (the floats of one input), its own parameters at
// their defaults through the uniforms termUniforms binds. Against the term's float64 function over the same
// inputs: it shows that each entry's args name the fields the dispatch passes, and that isotropic terms keep
// their values through the struct.
import { FIELDS } from '../../../math/catalogue/microfacet-input.js';
import { termInputs } from '../../../math/catalogue/grids.js';
import { termDefines } from '../../../math/catalogue/index.js';
import { termUniforms } from '../../../math/catalogue/uniforms.js';

/** @typedef {import('../../../math/catalogue/types.js').TermEntry} TermEntry */
/** @typedef {import('../../../math/catalogue/types.js').TermFamily} TermFamily */

/**
 * GLSL that fills an input from the floats arg(0) … of one parity input (the term's field args, in order) and
 * calls the dispatch: an isotropic α sets both of (αx, αy); the fields the term does not name stay those of
 * l = v = h = n (Kelemen's branch reads n·l, n·v for its horizon).
 * @param {TermFamily} family
 * @param {string[]} fields
 */
function dispatchPrelude(family, fields) {
  const set = fields.map((name, i) =>
    name === 'alpha' ? `m.alpha = vec2(arg(${i}));` : `${FIELDS[name].glsl} = arg(${i});`,
  );
  return [
    '#include "parity-args.glsl"',
    `float parityDispatch() {`,
    '  MicrofacetInput m = microfacetNormalInput(vec3(0.0, 0.0, 1.0), vec2(1.0));',
    ...set.map((line) => `  ${line}`),
    `  return ${family.glslDispatch}(m);`,
    '}',
  ].join('\n');
}

/**
 * The dispatch row of one term: inputs over its field args only (its own parameters fixed at their defaults).
 * @param {TermFamily} family
 * @param {TermEntry} term
 * @param {(kind: string, dims: number) => any[]} angles
 * @param {[number, number]} range
 */
function dispatchCase(family, term, angles, range) {
  const fields = term.args.filter((arg) => Object.hasOwn(FIELDS, arg));
  const own = Object.fromEntries(
    term.args
      .filter((arg) => !fields.includes(arg))
      .map((arg) => [arg, term.params[arg].default ?? term.params[arg].min]),
  );
  const choice = { [family.choice]: term.key };
  const uniforms = termUniforms(choice, own);
  // a normaliser is the uniform's, once per draw (SGD's at its default α), as the GPU reads it
  const normaliser = term.normaliserUniform ? [uniforms[term.normaliserUniform]] : [];
  const js = (/** @type {number[]} */ ...inputs) => {
    const values = { ...own, ...Object.fromEntries(fields.map((name, i) => [name, inputs[i]])) };
    return term.js?.(...term.args.map((arg) => values[arg]), ...normaliser);
  };
  return {
    name: `${family.glslDispatch} (${term.define})`,
    chunk: `${family.family}-term.glsl`,
    defines: termDefines(choice),
    prelude: dispatchPrelude(family, fields),
    glsl: 'parityDispatch()',
    outputs: 1,
    uniforms,
    js,
    range,
    // the coarse grids: the row checks the wiring, the function rows the accuracy
    args: termInputs({ ...term, args: fields }, (kind, dims) => angles(kind, Math.max(dims, 4))),
  };
}

/**
 * The dispatch rows of the families whose dispatch takes the microfacet input.
 * @param {Record<string, TermFamily>} catalogue
 * @param {(kind: string, dims: number) => any[]} angles the parity grids of the angles (parity-cases.js)
 * @param {Record<string, [number, number]>} ranges each family's range
 */
export function dispatchParityCases(catalogue, angles, ranges) {
  return Object.values(catalogue)
    .filter((family) => family.microfacetInput)
    .flatMap((family) =>
      Object.values(family.terms)
        .filter((term) => term.js && term.define)
        .map((term) => dispatchCase(family, term, angles, ranges[family.family])),
    );
}
