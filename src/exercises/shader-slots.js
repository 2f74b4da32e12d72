// How a shader exercise grades each slot of user code (SLOTS, core/custom/slots.js): the axes of its input grid, the
// slot's arguments for one grid point (rounded to float32, as the GPU receives them), and the catalogue term's
// float64 value at exactly those rounded inputs. Pure: loads in Node.
import { CATALOGUE, termEntry } from '../math/catalogue/index.js';
import { iorFromF0 } from '../math/fresnel.js';
import { SLOTS } from '../core/custom/slots.js';

const f32 = Math.fround;

/** A cosine axis: a grazing or below-horizon stress value is allowed, and 1 + 1e-6 as a rounded dot product gives. */
const cosine = (label, words) => ({ label, words, limits: [-1, 1.001] });
/** A cosine that builds a unit vector (the diffuse slot's l and v): within [-1, 1]. */
const vectorCosine = (label, words) => ({ label, words, limits: [-1, 1] });
const alpha = { label: 'α', words: 'roughness α', limits: [0, 10] };
/** The roughness along one axis of the tangent frame (the anisotropic slots' vec2 alpha). */
const alphaAxis = (axis) => ({ label: `α${axis}`, words: `the roughness α${axis} along ${axis}`, limits: [0, 10] });
/** An azimuth from the tangent t (x), in degrees. */
const azimuth = (label, words) => ({ label, words, limits: [-360, 360] });

/** F's vec3 F0 takes a grey value on each channel (evaluateCustom's inputs: D [nh, alpha], F [f0r, f0g, f0b, lh]…). */
const grey = (x) => [x, x, x];

/**
 * l and v in the local frame (n = (0,0,1)) from their cosines with n and the cosine of the azimuth between them,
 * each component rounded to float32; l in the xz-plane.
 */
export function directionsOf(nl, nv, cosPhi) {
  const sl = Math.sqrt(Math.max(0, (1 - nl) * (1 + nl)));
  const sv = Math.sqrt(Math.max(0, (1 - nv) * (1 + nv)));
  const sinPhi = Math.sqrt(Math.max(0, (1 - cosPhi) * (1 + cosPhi)));
  return { l: [sl, 0, nl].map(f32), v: [sv * cosPhi, sv * sinPhi, nv].map(f32) };
}

/**
 * A unit vector of the tangent frame (x = t, y = b, z = n) from its cosine with n and its azimuth from t in degrees,
 * each component rounded to float32: what an anisotropic slot receives.
 */
export function directionAt(cosTheta, phiDeg) {
  const s = Math.sqrt(Math.max(0, (1 - cosTheta) * (1 + cosTheta)));
  const phi = (phiDeg * Math.PI) / 180;
  return [s * Math.cos(phi), s * Math.sin(phi), cosTheta].map(f32);
}

/** The reference of an anisotropic slot: the term's float64 function over its arguments, each from `values`. */
const byArgs = (entry, values) => entry.js(...entry.args.map((name) => values[name]));

/** The cosines the rounded vectors really have: what the reference must be evaluated at. */
function cosinesOf(l, v, cosPhi) {
  const ll = Math.hypot(l[0], l[1]);
  const lv = Math.hypot(v[0], v[1]);
  return { nl: l[2], nv: v[2], cosPhi: ll && lv ? (l[0] * v[0] + l[1] * v[1]) / (ll * lv) : cosPhi };
}

/**
 * Each gradable slot: its family, the word for its value in feedback, its axes
 * (name → label, words, hard limits for the domain), the flattened GPU arguments of one point (in the slot's
 * signature order), and the reference.
 * `params` are the term's parameters: the point's where the names agree, else the exercise's fixed ones.
 */
export const GRADED_SLOTS = {
  D: {
    family: 'ndf',
    value: 'D',
    axes: { nh: cosine('n·h', 'the cosine n·h'), alpha },
    gpuArgs: (p) => [p.nh, p.alpha].map(f32),
    reference: (entry, p, fixed) => entry.evaluate(f32(p.nh), { ...fixed, alpha: f32(p.alpha) }),
  },
  V: {
    family: 'visibility',
    value: 'V',
    axes: { nl: cosine('n·l', 'the cosine n·l'), nv: cosine('n·v', 'the cosine n·v'), alpha },
    gpuArgs: (p) => [p.nl, p.nv, p.alpha].map(f32),
    reference: (entry, p, fixed) => entry.evaluate({ nl: f32(p.nl), nv: f32(p.nv) }, { ...fixed, alpha: f32(p.alpha) }),
  },
  F: {
    family: 'fresnel',
    value: 'F',
    axes: {
      f0: { label: 'F0', words: 'the reflectance at normal incidence F0', limits: [0, 1] },
      lh: cosine('l·h', 'the cosine l·h'),
    },
    gpuArgs: (p) => [...grey(p.f0), p.lh].map(f32),
    // a term that reads η (the exact dielectric) gets the η whose F0 this is, unless the exercise fixes it
    reference: (entry, p, fixed) => entry.evaluate(f32(p.lh), { eta: iorFromF0(f32(p.f0)), ...fixed, f0: f32(p.f0) }),
  },
  // h from its cosine with n and its azimuth from the tangent: D is stretched along the tangent frame's axes
  DAniso: {
    family: 'ndf',
    value: 'D',
    gives: ['hx', 'hy', 'hz', 'alphaX', 'alphaY'],
    axes: {
      nh: cosine('n·h', 'the cosine n·h'),
      phiH: azimuth('φh', 'the azimuth φh of h from the tangent t, in degrees'),
      alphaX: alphaAxis('x'),
      alphaY: alphaAxis('y'),
    },
    gpuArgs: (p) => [...directionAt(p.nh, p.phiH), p.alphaX, p.alphaY].map(f32),
    reference: (entry, p) => {
      const [hx, hy, hz] = directionAt(p.nh, p.phiH);
      return byArgs(entry, { hx, hy, hz, alphaX: f32(p.alphaX), alphaY: f32(p.alphaY) });
    },
  },
  // l in the plane of t and n at the azimuth φl, v at φv: Λ's projected roughness depends on each direction's own
  VAniso: {
    family: 'visibility',
    value: 'V',
    gives: ['lx', 'ly', 'lz', 'vx', 'vy', 'vz', 'alphaX', 'alphaY'],
    axes: {
      nl: cosine('n·l', 'the cosine n·l'),
      phiL: azimuth('φl', 'the azimuth φl of l from the tangent t, in degrees'),
      nv: cosine('n·v', 'the cosine n·v'),
      phiV: azimuth('φv', 'the azimuth φv of v from the tangent t, in degrees'),
      alphaX: alphaAxis('x'),
      alphaY: alphaAxis('y'),
    },
    gpuArgs: (p) => [...directionAt(p.nl, p.phiL), ...directionAt(p.nv, p.phiV), p.alphaX, p.alphaY].map(f32),
    reference: (entry, p) => {
      const [lx, ly, lz] = directionAt(p.nl, p.phiL);
      const [vx, vy, vz] = directionAt(p.nv, p.phiV);
      return byArgs(entry, { lx, ly, lz, vx, vy, vz, alphaX: f32(p.alphaX), alphaY: f32(p.alphaY) });
    },
  },
  diffuse: {
    family: 'diffuse',
    value: 'diffuse BRDF',
    axes: {
      cdiff: { label: 'c_diff', words: 'the diffuse colour c_diff', limits: [0, 1] },
      nl: vectorCosine('n·l', 'the cosine n·l'),
      nv: vectorCosine('n·v', 'the cosine n·v'),
      cosPhi: vectorCosine('cos φ', 'the cosine of the azimuth φ between l and v'),
      alpha,
    },
    gpuArgs: (p) => {
      const { l, v } = directionsOf(p.nl, p.nv, p.cosPhi);
      return [p.cdiff, ...l, ...v, p.alpha].map(f32); // the diffuse slot's c_diff is grey: one number
    },
    reference: (entry, p, fixed) => {
      const { l, v } = directionsOf(p.nl, p.nv, p.cosPhi);
      const c = cosinesOf(l, v, p.cosPhi);
      return entry.evaluate(c.nl, c.nv, c.cosPhi, { ...fixed, cdiff: f32(p.cdiff), alpha: f32(p.alpha) });
    },
  },
};

/** How many channels of the GPU's output a slot's value fills (1: a float; 3: a vec3), from custom-core's SLOTS. */
export const channelsOf = (slotKey) => SLOTS[slotKey].outputs;

/** The slot keys a shader exercise can name ('brdf', the whole BRDF, has no catalogue term to grade against). */
export const GRADED_SLOT_KEYS = Object.keys(GRADED_SLOTS);

/** What a term reads beyond its parameters, per family's calling convention, that a slot cannot give. */
const ANGLES_OF = { ndf: ['nh', 'sin2h'], fresnel: ['cos'], diffuse: ['nl', 'nv', 'cosPhi'] };

/**
 * Why the catalogue term `key` cannot be graded in `slotKey` with the fixed `params`, as a list of messages
 * (empty when it can): unknown term, an angle the slot does not get, a parameter neither an axis nor fixed.
 */
export function referenceProblems(slotKey, key, params) {
  const slot = GRADED_SLOTS[slotKey];
  const terms = CATALOGUE[slot.family].terms;
  if (!Object.hasOwn(terms, key))
    return [`reference.term: ${JSON.stringify(key)} is not a ${slot.family} term (${Object.keys(terms).join(', ')})`];
  const entry = termEntry(slot.family, key);
  // an anisotropic slot calls the term's own function over the fields it gives; the others, the family's convention
  if (!(slot.gives ? entry.js : entry.evaluate)) return [`reference.term: "${key}" is not a pointwise function`];
  const problems = [];
  const angles = slot.gives ?? (slot.family === 'visibility' ? ['nl', 'nv'] : ANGLES_OF[slot.family]);
  for (const arg of entry.args) {
    if (Object.hasOwn(entry.params, arg) || angles.includes(arg)) continue;
    problems.push(`reference.term: "${key}" reads ${arg}, which ${slotKey}'s function does not get`);
  }
  const derived = slotKey === 'F' ? ['eta'] : [];
  for (const name of Object.keys(entry.params)) {
    if (Object.hasOwn(slot.axes, name) || derived.includes(name) || Object.hasOwn(params, name)) continue;
    problems.push(`reference.params.${name}: missing ("${key}" reads it and the slot does not give it)`);
  }
  for (const [name, value] of Object.entries(params)) {
    const p = Object.hasOwn(entry.params, name) ? entry.params[name] : null; // no inherited names (__proto__)
    if (!p) problems.push(`reference.params.${name}: "${key}" has no parameter ${name}`);
    else if (Object.hasOwn(slot.axes, name)) problems.push(`reference.params.${name}: is an axis of the domain`);
    else if (typeof value !== 'number' || !(value >= p.min && value <= p.max))
      problems.push(`reference.params.${name}: ${JSON.stringify(value)} is not a number within ${p.min}…${p.max}`);
  }
  return problems;
}
