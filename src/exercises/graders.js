// The graders (metrics) an exercise file can name. Each computes the right answer from src/math at the moment
// of checking, from its params and the widget's state, and says what is off and by how much.
//
// A grader declares:
//   answer    { kind: 'state' }: the student answers by moving the widget (the keys in `reads`);
//             { kind: 'number', label, unit }: typed into a box; { kind: 'choice', choices(params) }: picked.
//   widget    the widget it reads (null: any widget, or none); reads: state keys the student sets (left free);
//             given: state keys that pose the question (must be locked); requires: locked values it assumes.
//   params    a state-style schema (src/core/framework/state.js) for the file's "params"; `required: true` has no
//             default.
//   tolerance what the file's "tolerance" (a positive number) means.
//   grade({ state, answer, params, tolerance, hidden }) → { ok, summary, details: [text] }
//   hide(params, random) → the secret part of the question, drawn when the exercise opens (optional).
import { fresnelConductor, fresnelDielectric, fresnelSchlick, f0FromIor } from '../math/fresnel.js';
import { fresnelParams, isMetal, materialByKey } from '../math/materials.js';
import { NDF_TERMS, VISIBILITY_TERMS, microfacetBRDFAt, punctualRadiance } from '../math/brdf.js';
import { matchNdfWidths } from '../math/ndf-width.js';
import { smithG1Beckmann, smithG1GGX } from '../math/visibility.js';
import { albedoGGX } from '../math/integrate.js';
import { randomWalkAlbedoGGX } from '../math/random-walk.js';
import { diffuseLambert } from '../math/diffuse.js';
import { transmittance, waterAbsorptionRgb } from '../math/media.js';
import { FRESNEL_ZONE_BOUNDS_DEG, fresnelZone } from '../math/zones.js';
import { displayRms, highlightArea, peakOf, sphereRadiance } from './sphere-image.js';
import { DEG } from '../math/angles.js';
import { termOptions } from '../math/catalogue/index.js';
import { F82_GRADERS } from './f82-grader.js';

/** A number for feedback: 3 significant digits, no exponent for everyday sizes. */
export const fmt = (x, digits = 3) => {
  if (!Number.isFinite(x)) return String(x);
  const a = Math.abs(x);
  if (a !== 0 && (a < 1e-3 || a >= 1e5)) return x.toExponential(digits - 1);
  return String(Number(x.toPrecision(digits)));
};
const pct = (x) => `${fmt(x * 100)}%`;
const times = (r) => `${fmt(r, 2)}×`;

/** The terms' one labels (src/math/catalogue), as graders' choices and in their feedback. */
export const NDF_NAMES = termOptions('ndf');
export const VISIBILITY_NAMES = termOptions('visibility');
const CHANNELS = { r: 'red (650 nm)', g: 'green (550 nm)', b: 'blue (450 nm)' };
const ZONES = { green: 'green (θ < 45°)', yellow: 'yellow (45°–75°)', red: 'red (θ > 75°)' };

/** Water depth (m) at which channel `ch` keeps `threshold` of its light. */
export const depthForTransmittance = (ch, threshold) => -Math.log(threshold) / waterAbsorptionRgb()['rgb'.indexOf(ch)];

/** Exact reflectance of a table material at the 550 nm sample, as the surfaces widget draws it. */
export function interfaceReflectance(material, thetaDeg) {
  const p = fresnelParams(material);
  const c = Math.cos(thetaDeg * DEG);
  return isMetal(material) ? fresnelConductor(c, p.eta[1], p.k[1]) : fresnelDielectric(c, p.eta[1]);
}

/** Angle (degrees, 0.01° steps) where Schlick's approximation is furthest from exact Fresnel, and that error. */
export function schlickWorstAngle(ior) {
  const f0 = f0FromIor(ior);
  let best = { deg: 0, error: 0 };
  for (let i = 0; i <= 9000; i++) {
    const c = Math.cos(i * 0.01 * DEG);
    const e = Math.abs(fresnelSchlick(f0, c) - fresnelDielectric(c, ior));
    if (e > best.error) best = { deg: i * 0.01, error: e };
  }
  return best;
}

/** D(θh) / D(0) over θh = 0°, 0.25°, … 89.75° for each NDF at a matched half width. */
export function ndfProfiles(hwhm, shapes) {
  const params = matchNdfWidths(hwhm, shapes);
  const out = {};
  for (const kind of Object.keys(NDF_NAMES)) {
    const D = (deg) => NDF_TERMS[kind](Math.cos(deg * DEG), params[kind]);
    const peak = D(0);
    out[kind] = Float64Array.from({ length: 360 }, (_, i) => D(i * 0.25) / peak);
  }
  return out;
}

/**
 * The largest factor between two profiles (max of a/b and b/a) where `ref` is at least `floor` of its peak —
 * the part of a highlight a picture shows at 1/floor exposure — and where it is (θh in degrees).
 */
export function profileFactor(a, ref, floor) {
  let worst = { factor: 1, deg: 0 };
  ref.forEach((r, i) => {
    if (r < floor) return;
    const f = Math.max(a[i] / r, r / a[i]);
    if (f > worst.factor) worst = { factor: f, deg: i * 0.25 };
  });
  return worst;
}

/** The sphere the sphere-match grader compares: GGX, height-correlated Smith, Schlick. */
export function materialSphere({ f0, alpha }, { lightTheta, size }) {
  const p = { F: 'schlick', D: 'ggx', V: 'smithGGXCorrelated', f0, alpha };
  return sphereRadiance(size, lightTheta, (a) => microfacetBRDFAt(a, p));
}

/** The highlight an NDF makes on the sphere: F = 1, implicit visibility, so its shape is D's. */
export function highlightSphere(kind, { hwhm, abcA2, sgdP, lightTheta }, size = 96) {
  const p = { F: 'one', D: kind, V: 'implicit', ...matchNdfWidths(hwhm, { abcA2, sgdP })[kind] };
  return sphereRadiance(size, lightTheta, (a) => microfacetBRDFAt(a, p));
}

export const visibilityAtMirror = (term, thetaDeg, alpha) => {
  const c = Math.cos(thetaDeg * DEG);
  return VISIBILITY_TERMS[term]({ nl: c, nv: c, nh: 1, lh: c }, { alpha });
};

/** "x is too low by d (r%)" for a number answer against its target. */
function offBy(answer, target, unit) {
  const d = answer - target;
  const rel = target !== 0 ? ` (${d > 0 ? '+' : '−'}${pct(Math.abs(d / target))})` : '';
  return `${fmt(answer)}${unit} is too ${d > 0 ? 'high' : 'low'} by ${fmt(Math.abs(d))}${unit}${rel}`;
}

export const GRADERS = {
  'transmittance-depth': {
    title: 'Water depth for a transmittance',
    summary:
      'The depth of clear water (Hale & Querry) at which one RGB channel keeps `threshold` of its light: d = ' +
      '−ln(threshold) / σa.',
    answer: { kind: 'number', label: 'Depth', unit: 'm' },
    widget: null,
    params: {
      channel: { type: 'enum', options: CHANNELS, default: 'r', label: 'channel' },
      threshold: { type: 'number', min: 1e-6, max: 0.99, default: 0.01, label: 'threshold' },
    },
    tolerance: 'metres either side of the depth',
    grade({ answer, params, tolerance }) {
      const target = depthForTransmittance(params.channel, params.threshold);
      const sigma = waterAbsorptionRgb()['rgb'.indexOf(params.channel)];
      const left = transmittance(sigma, answer);
      const name = CHANNELS[params.channel];
      if (Math.abs(answer - target) <= tolerance) {
        return {
          ok: true,
          summary:
            `Right: at ${fmt(answer)} m water keeps ${pct(left)} of the ${name} light; the threshold is ` +
            `${pct(params.threshold)} (within ±${fmt(tolerance)} m).`,
          details: [],
        };
      }
      return {
        ok: false,
        summary: `${offBy(answer, target, ' m')}; needs to be within ±${fmt(tolerance)} m.`,
        details: [
          `At ${fmt(answer)} m, ${pct(left)} of the ${name} light is left; the exercise asks where ` +
            `${pct(params.threshold)} is left.`,
          answer < target ? 'Go deeper.' : 'The light was already below the threshold at a shallower depth.',
        ],
      };
    },
  },

  'fresnel-reflectance-angle': {
    title: 'Angle for a reflectance',
    summary: 'Set the angle of incidence at which the material reflects `target` (exact Fresnel, 550 nm).',
    answer: { kind: 'state' },
    widget: 'surfaces',
    reads: ['theta'],
    given: ['material'],
    params: { target: { type: 'number', min: 0, max: 1, required: true, label: 'target reflectance' } },
    tolerance: 'reflectance (0–1) either side of the target',
    grade({ state, params, tolerance }) {
      const R = interfaceReflectance(state.material, state.theta);
      const name = materialByKey(state.material).name;
      const where = `At ${state.theta}°, ${name} reflects ${pct(R)}`;
      if (Math.abs(R - params.target) <= tolerance)
        return {
          ok: true,
          summary: `Right: ${where}; the target is ${pct(params.target)} ± ${pct(tolerance)}.`,
          details: [],
        };
      const rising = interfaceReflectance(state.material, Math.min(state.theta + 1, 89.9)) > R;
      const wantUp = params.target > R;
      return {
        ok: false,
        summary:
          `${where}: ${fmt(Math.abs(R - params.target) * 100)} points ` +
          `${R < params.target ? 'below' : 'above'} the target ${pct(params.target)} (needs ± ${pct(tolerance)}).`,
        details: [`${wantUp === rising ? 'Raise' : 'Lower'} the angle of incidence.`],
      };
    },
  },

  'sphere-match': {
    title: 'Match a sphere',
    summary:
      'Match the target sphere (GGX, height-correlated Smith, Schlick F with F0 and α) by the RMS difference of ' +
      'the two pictures on a size × size grid.',
    answer: { kind: 'state' },
    widget: 'brdf-lobe',
    reads: ['f0', 'alpha'],
    requires: { D: 'ggx', V: 'smithGGXCorrelated', F: 'schlick' },
    params: {
      f0: { type: 'number', min: 0, max: 1, required: true, label: 'target F0' },
      alpha: { type: 'number', min: 0.02, max: 1, required: true, label: 'target α' },
      lightTheta: { type: 'number', min: 0, max: 89, default: 30, label: 'light angle from the view (°)' },
      exposure: { type: 'number', min: 0.01, max: 100, default: 1, label: 'exposure' },
      size: { type: 'number', min: 8, max: 128, default: 48, label: 'grid size' },
    },
    tolerance: 'RMS difference of the display values (0–1, sRGB-encoded, clamped) over the sphere’s pixels',
    grade({ state, params, tolerance }) {
      const target = materialSphere(params, params);
      const yours = materialSphere(state, params);
      const rms = displayRms(yours, target, params.exposure);
      const verdict = `RMS error ${fmt(rms, 2)} (display value 0–1), needs < ${fmt(tolerance, 2)}.`;
      if (rms < tolerance) return { ok: true, summary: `Right: ${verdict.replace('needs <', 'under')}`, details: [] };
      const details = [];
      const peak = peakOf(yours) / peakOf(target);
      const area = highlightArea(yours) / highlightArea(target);
      if (Math.abs(peak - 1) > 0.05)
        details.push(`Your highlight is ${times(peak)} as bright as the target’s at its peak.`);
      if (Math.abs(area - 1) > 0.05)
        details.push(`Your highlight covers ${times(area)} the target’s area (pixels above half its peak).`);
      if (Math.abs(state.alpha - params.alpha) > 0.015)
        details.push(`Roughness too ${state.alpha < params.alpha ? 'low' : 'high'}.`);
      if (Math.abs(state.f0 - params.f0) > 0.015) details.push(`F0 too ${state.f0 < params.f0 ? 'low' : 'high'}.`);
      return { ok: false, summary: verdict, details };
    },
  },

  'smith-g1': {
    title: 'Masking at a view angle',
    summary: 'Set the view angle at which Smith’s G1 (the share of the microsurface seen, not masked) equals `target`.',
    answer: { kind: 'state' },
    widget: 'microfacets',
    reads: ['viewTheta'],
    given: ['kind', 'alpha'],
    params: { target: { type: 'number', min: 0, max: 1, required: true, label: 'target G1' } },
    tolerance: 'G1 (0–1) either side of the target',
    grade({ state, params, tolerance }) {
      const G1 = (state.kind === 'ggx' ? smithG1GGX : smithG1Beckmann)(
        Math.cos(Math.abs(state.viewTheta) * DEG),
        state.alpha,
      );
      const where = `At θv = ${state.viewTheta}°, G1 = ${fmt(G1)}`;
      if (Math.abs(G1 - params.target) <= tolerance)
        return {
          ok: true,
          summary: `Right: ${where}; the target is ${fmt(params.target)} ± ${fmt(tolerance)}.`,
          details: [],
        };
      return {
        ok: false,
        summary:
          `${where}: ${fmt(Math.abs(G1 - params.target))} ${G1 > params.target ? 'above' : 'below'} the ` +
          `target ${fmt(params.target)} (needs ± ${fmt(tolerance)}).`,
        details: [
          G1 > params.target
            ? 'Too little is masked: view the surface at a more grazing angle.'
            : 'Too much is masked: view the surface closer to its normal.',
        ],
      };
    },
  },

  'albedo-loss': {
    title: 'Energy lost by single scattering',
    summary:
      'The percentage of light a GGX surface (height-correlated Smith, F = 1) fails to reflect at one angle: ' +
      '100 (1 − E(μ)), E by deterministic quadrature (albedoGGX, within 1e-5).',
    answer: { kind: 'number', label: 'Energy lost', unit: '%' },
    widget: null,
    params: {
      alpha: { type: 'number', min: 0.01, max: 1, required: true, label: 'α' },
      thetaDeg: { type: 'number', min: 0, max: 89, default: 0, label: 'view angle (°)' },
    },
    tolerance: 'percentage points either side',
    grade({ answer, params, tolerance }) {
      const loss = 100 * (1 - albedoGGX(Math.cos(params.thetaDeg * DEG), params.alpha));
      if (Math.abs(answer - loss) <= tolerance)
        return {
          ok: true,
          summary:
            `Right: the white furnace loses ${fmt(loss)}% at α = ${params.alpha}, θ = ` +
            `${params.thetaDeg}° (within ±${fmt(tolerance)} points).`,
          details: [],
        };
      return {
        ok: false,
        summary: `${offBy(answer, loss, '%')}; needs to be within ±${fmt(tolerance)} points.`,
        details: [
          answer < loss
            ? 'More light is lost than that: rough surfaces send much of it into second bounces that single ' +
              'scattering ignores.'
            : 'Less is lost than that: read the albedo E at the angle, the loss is 1 − E.',
        ],
      };
    },
  },

  'multiple-scattering-gain': {
    title: 'Energy that multiple bounces give back',
    summary:
      'The percentage points of albedo a GGX metal (height-correlated Smith, Schlick’s F of F0 at every bounce) ' +
      'gains ' +
      'from light that bounces more than once: 100 (A − A₁), A the albedo and A₁ its first bounce, by the ' +
      'random walk on the ' +
      'Smith microsurface (Heitz et al. 2016; 100 000 seeded paths, standard error about 0.1 point).',
    answer: { kind: 'number', label: 'Energy given back', unit: 'percentage points' },
    widget: null,
    params: {
      alpha: { type: 'number', min: 0.05, max: 1, required: true, label: 'α' },
      f0: { type: 'number', min: 0, max: 1, required: true, label: 'F0' },
      thetaDeg: { type: 'number', min: 0, max: 85, default: 0, label: 'view angle (°)' },
    },
    tolerance: 'percentage points either side',
    grade({ answer, params, tolerance }) {
      const walk = randomWalkAlbedoGGX(Math.cos(params.thetaDeg * DEG), params.alpha, params.f0, 100_000, 1);
      const gain = 100 * (walk.albedo - walk.single);
      const where =
        `at α = ${params.alpha}, F0 = ${params.f0}, θ = ${params.thetaDeg}° one bounce reflects ` +
        `${fmt(100 * walk.single)}% and all bounces ${fmt(100 * walk.albedo)}%`;
      if (Math.abs(answer - gain) <= tolerance)
        return {
          ok: true,
          summary: `Right: ${where}, ${fmt(gain)} points more (within ±${fmt(tolerance)}).`,
          details: [],
        };
      return {
        ok: false,
        summary: `${offBy(answer, gain, ' points')}; needs to be within ±${fmt(tolerance)} points.`,
        details: [
          answer < gain
            ? 'More comes back than that: a metal reflects most of what reaches a second facet, so most of what ' +
              'single scattering loses returns.'
            : 'Less comes back than that: only what single scattering loses (1 − E with F = 1) can return, and ' +
              'each bounce keeps only F of it.',
        ],
      };
    },
  },

  'light-zone': {
    title: 'Place the light for a Fresnel zone',
    summary:
      'Move the light so that l·h falls in `zone` (orthographic view: l·h = cos(θ/2) everywhere, θ the light’s ' +
      'angle from the view).',
    answer: { kind: 'state' },
    widget: 'fresnel-zones',
    reads: ['lightTheta'],
    requires: { mode: 'zones-lh', camera: 'orthographic' },
    params: { zone: { type: 'enum', options: ZONES, required: true, label: 'zone' } },
    tolerance: 'degrees by which θd = θ/2 must clear the zone’s boundaries',
    grade({ state, params, tolerance }) {
      const thetaD = state.lightTheta / 2;
      const got = Object.keys(ZONES)[fresnelZone(Math.cos(thetaD * DEG))];
      const want = Object.keys(ZONES).indexOf(params.zone);
      const [lo, hi] = [[0, ...FRESNEL_ZONE_BOUNDS_DEG][want], [...FRESNEL_ZONE_BOUNDS_DEG, 90][want]];
      const clears = thetaD >= lo + (lo > 0 ? tolerance : 0) && thetaD <= hi - (hi < 90 ? tolerance : 0);
      const where =
        `The light is ${state.lightTheta}° from the view, so θd = ${fmt(thetaD)}° and l·h = ` +
        `${fmt(Math.cos(thetaD * DEG))}: the object is ${got}`;
      if (got === params.zone && clears) return { ok: true, summary: `Right: ${where}.`, details: [] };
      const gap = thetaD < lo + tolerance ? lo + tolerance - thetaD : thetaD - (hi - tolerance);
      return {
        ok: false,
        summary:
          `${where}; the exercise wants it ${ZONES[params.zone]}, with θd at least ${fmt(tolerance)}° ` +
          `inside the zone.`,
        details: [
          `Move the light about ${fmt(2 * gap, 2)}° ${thetaD < lo + tolerance ? 'further from' : 'closer to'} ` +
            `the view (θd changes half as fast as the light).`,
        ],
      };
    },
  },

  'schlick-worst-angle': {
    title: 'Where Schlick is worst',
    summary:
      'The angle of incidence at which Schlick’s approximation is furthest from exact Fresnel, for the widget’s ' +
      'custom IOR (0.01° scan).',
    answer: { kind: 'number', label: 'Angle', unit: '°' },
    widget: 'fresnel-curves',
    given: ['ior'],
    params: {},
    tolerance: 'degrees either side',
    grade({ state, answer, tolerance }) {
      const worst = schlickWorstAngle(state.ior);
      const f0 = f0FromIor(state.ior);
      const c = Math.cos(Math.min(Math.max(answer, 0), 90) * DEG);
      const there = Math.abs(fresnelSchlick(f0, c) - fresnelDielectric(c, state.ior));
      if (Math.abs(answer - worst.deg) <= tolerance)
        return {
          ok: true,
          summary:
            `Right: Schlick is worst at ${fmt(worst.deg)}°, off by ${fmt(worst.error)} (within ` +
            `±${fmt(tolerance)}°).`,
          details: [],
        };
      return {
        ok: false,
        summary: `${offBy(answer, worst.deg, '°')}; needs to be within ±${fmt(tolerance)}°.`,
        details: [
          `At ${fmt(answer)}° Schlick is off by ${fmt(there)}; at its worst it is off by ${fmt(worst.error)}, ` +
            `${times(worst.error / Math.max(there, 1e-12))} as much.`,
        ],
      };
    },
  },

  'ndf-profile': {
    title: 'Which NDF made the highlight',
    summary:
      'The page shows a highlight made by a hidden NDF (`hidden`, or a random one) at half width `hwhm`; a ' +
      'choice is right when its profile D(θh)/D(0) at that width matches the highlight’s wherever the highlight ' +
      'is at least `floor` of its peak.',
    answer: { kind: 'choice', choices: () => NDF_NAMES },
    widget: null,
    params: {
      hidden: { type: 'enum', options: { random: 'random', ...NDF_NAMES }, default: 'random', label: 'hidden NDF' },
      hwhm: { type: 'number', min: 1, max: 40, default: 5, label: 'half width (°)' },
      floor: { type: 'number', min: 1e-4, max: 0.5, default: 0.01, label: 'floor' },
      abcA2: { type: 'number', min: 0.5, max: 10, default: 2.5, label: 'ABC a2' },
      sgdP: { type: 'number', min: 0, max: 1.9, default: 0.64, label: 'SGD p' },
      lightTheta: { type: 'number', min: 0, max: 80, default: 30, label: 'light angle from the view (°)' },
    },
    tolerance: 'largest factor (≥ 1) allowed between the two profiles where the highlight is above the floor',
    /** Well posed: whichever NDF is hidden, no other is within the tolerance of it (one right answer). */
    check(params, tolerance) {
      const profiles = ndfProfiles(params.hwhm, params);
      const hidden = params.hidden === 'random' ? Object.keys(NDF_NAMES) : [params.hidden];
      const problems = [];
      for (const h of hidden) {
        for (const k of Object.keys(NDF_NAMES)) {
          const f = k === h ? Infinity : profileFactor(profiles[k], profiles[h], params.floor).factor;
          if (f <= tolerance) {
            problems.push(
              `at a half width of ${params.hwhm}° ${NDF_NAMES[k]} is within ${fmt(f, 3)}× of ${NDF_NAMES[h]}, ` +
                `inside the tolerance ${fmt(tolerance, 3)}: two answers would be right`,
            );
          }
        }
      }
      return problems;
    },
    /** The hidden NDF: the one named, or one drawn by `random` (the page seeds it: the same seed, the same NDF). */
    hide(params, random = Math.random) {
      if (params.hidden !== 'random') return params.hidden;
      const kinds = Object.keys(NDF_NAMES);
      return kinds[Math.floor(random() * kinds.length)];
    },
    grade({ answer, params, tolerance, hidden }) {
      const profiles = ndfProfiles(params.hwhm, params);
      const mine = profileFactor(profiles[answer], profiles[hidden], params.floor);
      const where = `wherever the highlight is above ${pct(params.floor)} of its peak`;
      const verdict =
        mine.factor - 1 < 1e-9
          ? `${NDF_NAMES[answer]} made it: its profile is the highlight’s`
          : `${NDF_NAMES[answer]}’s profile is within ${pct(mine.factor - 1)} of the highlight’s ${where}`;
      if (mine.factor <= tolerance)
        return {
          ok: true,
          summary: `Right: ${verdict} (profiles within ${pct(tolerance - 1)} of each other ${where} count).`,
          details: [],
        };
      const side =
        profiles[answer][Math.round(mine.deg / 0.25)] > profiles[hidden][Math.round(mine.deg / 0.25)]
          ? 'brighter'
          : 'darker';
      return {
        ok: false,
        summary:
          `${NDF_NAMES[answer]}’s profile is ${times(mine.factor)} ${side} than the highlight’s at θh = ` +
          `${fmt(mine.deg)}°; a match needs ≤ ${fmt(tolerance, 3)}×.`,
        details: [
          side === 'brighter'
            ? 'The highlight’s tail falls off faster than your choice’s.'
            : 'The highlight’s tail reaches further than your choice’s.',
        ],
      };
    },
  },

  'visibility-ratio': {
    title: 'Ratio of two visibility terms',
    summary:
      'V_numerator / V_denominator with l and v mirrored about n at `thetaDeg` (h = n), at the widget’s roughness.',
    answer: { kind: 'number', label: 'Ratio', unit: '' },
    widget: 'visibility-explorer',
    given: ['alpha'],
    params: {
      numerator: { type: 'enum', options: VISIBILITY_NAMES, required: true, label: 'numerator term' },
      denominator: { type: 'enum', options: VISIBILITY_NAMES, required: true, label: 'denominator term' },
      thetaDeg: { type: 'number', min: 0, max: 89, required: true, label: 'angle of l and v (°)' },
    },
    tolerance: 'absolute error of the ratio',
    grade({ state, answer, params, tolerance }) {
      const num = visibilityAtMirror(params.numerator, params.thetaDeg, state.alpha);
      const den = visibilityAtMirror(params.denominator, params.thetaDeg, state.alpha);
      const ratio = num / den;
      const what =
        `${VISIBILITY_NAMES[params.numerator]} / ${VISIBILITY_NAMES[params.denominator]} at ` +
        `${params.thetaDeg}°, α = ${state.alpha}`;
      if (Math.abs(answer - ratio) <= tolerance)
        return { ok: true, summary: `Right: ${what} is ${fmt(ratio)} (within ±${fmt(tolerance)}).`, details: [] };
      return {
        ok: false,
        summary: `${offBy(answer, ratio, '')} for ${what}; needs to be within ±${fmt(tolerance)}.`,
        details: ['Read both curves at the angle (hover the plot in the mirrored configuration) and divide.'],
      };
    },
  },

  'lambert-radiance': {
    title: 'Brightness of a Lambertian surface',
    summary:
      'Radiance of a Lambertian surface (albedo cdiff) under a punctual light c_light at `thetaDeg` from the ' +
      'normal: Lo = π (cdiff/π) c_light cos θ.',
    answer: { kind: 'number', label: 'Radiance Lo', unit: '' },
    widget: null,
    params: {
      cdiff: { type: 'number', min: 0, max: 1, default: 1, label: 'cdiff' },
      cLight: { type: 'number', min: 1e-6, max: 1e6, required: true, label: 'c_light' },
      thetaDeg: { type: 'number', min: 0, max: 90, required: true, label: 'light angle from the normal (°)' },
    },
    tolerance: 'absolute error, in the units of c_light',
    grade({ answer, params, tolerance }) {
      const { cdiff, cLight, thetaDeg } = params;
      const target = punctualRadiance(diffuseLambert(cdiff), Math.cos(thetaDeg * DEG), cLight);
      if (Math.abs(answer - target) <= tolerance)
        return { ok: true, summary: `Right: Lo = ${fmt(target)} (within ±${fmt(tolerance)}).`, details: [] };
      const near = (x) => Math.abs(answer - x) <= tolerance * Math.max(1, x / Math.max(target, 1e-12));
      const details = [];
      if (near(target * Math.PI))
        details.push('That is π times too bright: the π of the punctual light equation cancels Lambert’s 1/π.');
      else if (near(target / Math.PI))
        details.push('That is π times too dark: the punctual light brings a factor π (Lo = π f c_light cos θ).');
      else if (near(cLight * cdiff))
        details.push('You left out the cosine: the light arrives at θ from the normal, spread over a larger area.');
      else if (target > 0) details.push(`Your value is ${times(answer / target)} the right one.`);
      return { ok: false, summary: `${offBy(answer, target, '')}; needs to be within ±${fmt(tolerance)}.`, details };
    },
  },
  ...F82_GRADERS,
};

export const isGraderName = (name) => Object.hasOwn(GRADERS, name);
