// @ts-check
// The shapes of the catalogue of terms (checked by TypeScript's checkJs). Types only: nothing runs here.

/**
 * One parameter a term reads, with the range its functions accept (they clamp to it) and its unit.
 * @typedef {object} TermParam
 * @property {number} min
 * @property {number} max
 * @property {string} unit '' for a pure number, 'rad' for an angle
 * @property {string} label
 * @property {boolean} [clamped] the functions clamp the value to [min, max] (stress inputs go beyond it)
 * @property {number[]} [delicate] the values inside the range where the functions are delicate, swept by the
 *   stress tests (without them, the range's decades or quarters)
 * @property {'float' | 'vec2' | 'colour'} [kind] 'float' when absent; a vec2 (the roughness pair) or an RGB colour
 *   has the range on each component
 * @property {string} [uniform] the GLSL uniform that carries it (a term's dispatch declares it when the term reads
 *   it; termUniforms fills it from the parameter's value)
 * @property {number} [default] the value a view draws with when it gives none
 */

/** @typedef {(...args: any[]) => number} TermFunction */

/**
 * One term of a family: the one spelling (state, URL), the one label, its source, its float64 function and its
 * GLSL twin, and the #define that selects it in the family's GLSL dispatch.
 * @typedef {object} TermEntry
 * @property {string} key camelCase; the state and URL spelling
 * @property {string} label the one label the whole app uses
 * @property {string} short for legends
 * @property {string} cite 'Author(s) Year'
 * @property {TermFunction | null} js the float64 function of src/math, with its own signature (null: the term is
 *   the absence of a factor, e.g. F = 1, or, for a compensation, not a pointwise function)
 * @property {TermFunction | null} evaluate the family's calling convention (see TermFamily); null for compensations
 * @property {string | null} glsl the GLSL function's name (the same as js's), null when there is none
 * @property {string | null} chunk the shaders/ file that defines it
 * @property {string | null} define the #define that picks it in the family's dispatch, `<PREFIX>_<KEY>`; null
 *   when no dispatch offers it
 * @property {string | null} [glslCall] the dispatch's expression for it, over the dispatch's arguments, when it is
 *   not its function over its args (which a D or V term's dispatch derives: src/core/gpu/term-chunks.js)
 * @property {string[]} args the arguments of js and of the GLSL function, in order: for a D or V term each a field
 *   of the microfacet input (src/math/catalogue/microfacet-input.js: 'nl', 'nv', 'nh', 'lh', 'sin2h', 'hx' … 'vz',
 *   'alpha', 'alphaX', 'alphaY') or a key of params (read from its uniform); for F and diffuse an angle ('cos',
 *   'nl', 'nv', 'cosPhi') or a key of params
 * @property {(...params: number[]) => number} [normaliser] a factor of the parameters alone (args after the
 *   first), which js takes optionally and the GLSL function as its last argument: computed once per draw
 * @property {string} [normaliserUniform] the uniform that carries the normaliser to the GPU
 * @property {TermCapabilities} [capabilities] what the hosts have for it beyond its two functions
 * @property {string} [isotropic] for an anisotropic D or V (it reads the pair αx, αy), the key of the isotropic
 *   term of its family it equals at αx = αy: the hosts stretch that term into it (anisotropic-forms.js)
 * @property {Record<string, TermParam>} params for an NDF the first is its width (ndf-width.js matches it)
 */

/**
 * What the app has for a term beyond its functions, read by the hosts instead of lists of keys.
 * @typedef {object} TermCapabilities
 * @property {string} [sampler] its importance sampler, a function of integrate.js and integrate.glsl of the same
 *   name (u, alpha) → m: the lab's sampled lighting and prefilter draw from it (ndf-sampler.glsl)
 * @property {boolean} [dfgTable] the lab's split-sum DFG tables are built for it (npm run dfg-tables)
 * @property {boolean} [measuredFit] the measured-BRDF fit (src/measured/fit.js) fits a model with it
 */

/**
 * @typedef {'fresnel' | 'ndf' | 'visibility' | 'diffuse' | 'compensation'} FamilyName
 */

/**
 * A family of terms. evaluate's calling conventions: fresnel (c = l·h, p), ndf (c = n·h, p, s2 = sin²θh),
 * visibility (a = { nl, nv, nh, lh }, p), diffuse (nl, nv, cosPhi, p); compensation has none.
 * @typedef {object} TermFamily
 * @property {FamilyName} family
 * @property {string} label
 * @property {string} choice the key of this family in a term choice ({ F, D, V, diffuse, compensation })
 * @property {string} definePrefix every define of the family is `<definePrefix>_<KEY IN SCREAMING_SNAKE>`
 * @property {string | null} glslDispatch the GLSL function that dispatches on the defines
 * @property {string | null} [glslSignature] its declaration, when it is generated from the catalogue
 * @property {boolean} [microfacetInput] its dispatch takes the microfacet input (its terms' args are its fields)
 * @property {string} defaultKey
 * @property {Record<string, TermEntry>} terms in menu order
 */

export {};
