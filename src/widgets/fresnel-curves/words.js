// fresnel-curves, in words: the about text, the readout's caption and the plots' summary for screen readers.
import { declareFormula, texNumber } from '../../core/framework/formula-registry.js';
import { f0FromIor } from '../../math/fresnel.js';
import { fresnelParams, materialByKey } from '../../math/materials.js';
import { worstCurve } from './model.js';

export const TITLE = 'Fresnel curves';

export const ABOUT =
  'Exact Fresnel reflectance (solid) against the angle between light and normal, with Schlick’s ' +
  'approximation (dashed) built from the same F(0°). Metals get one curve per channel (R, G, B). Try a metal ' +
  'with <em>Measured n, k</em>: its F(0°) no longer matches the talk’s table. Hover a plot to read values.';

const FITTED_NOTE =
  '† Fitted, not measured: Gulbrandsen 2014’s n, k, chosen to reproduce the talk’s F(0°) and the ' +
  'measured edge tint. They give the curve its shape but are not the metal’s optical constants ' +
  '(choose “Measured n, k” for those).';

/** The readout's caption at the angle `theta`; `fitted` when some (n, k) shown are fitted, not measured. */
export const readoutCaption = (theta, fitted) =>
  `Values at θ = ${theta.toFixed(2)}° (move the pointer over a plot), and where Schlick is worst` +
  `${fitted ? `. ${FITTED_NOTE}` : ''}`;

/** The readout's column heads at the angle `theta`. */
export const readoutColumns = (theta) => [
  'Curve',
  'n',
  'k',
  'F(0°)',
  `exact at ${theta.toFixed(1)}°`,
  'Schlick',
  'max |Schlick − exact|',
  'at θ',
];

/** What a reader would look for in the plots (they describe themselves, core/ui/plot.js): F(0°), worst error. */
export function describeCurves(curves) {
  const named = curves.map((c) => `${c.label} (F(0°) ${c.f0.toFixed(3)})`).join(', ') || 'no material';
  const worst = worstCurve(curves);
  const error = worst
    ? `. Schlick's largest error: ${worst.maxError.toFixed(4)} for ${worst.label} at ${worst.maxErrorAt.toFixed(1)}°.`
    : '.';
  return `Fresnel reflectance against angle of incidence for ${named}${error}`;
}

const rgb = (values) => `(${values.map((x) => texNumber(x)).join(',\\ ')})`;

/** F0 of the first chosen curve: the n set by hand, or the first material's (per channel for a metal). */
function firstF0(state) {
  if (state.materials.includes('manual')) return [f0FromIor(state.ior)];
  return state.materials.length ? fresnelParams(state.materials[0], state.conductor).f0 : [];
}

/** F0 of the first chosen curve: from the n set by hand, in closed form, or the material's own (per channel). */
function f0Line(state) {
  if (state.materials.includes('manual')) {
    const n = texNumber(state.ior, 2);
    const f0 = texNumber(f0FromIor(state.ior));
    const N = `\\sym{ior}{${n}}`;
    return `F_0 = \\left(\\frac{n-1}{n+1}\\right)^2 = \\left(\\frac{${N}-1}{${N}+1}\\right)^2 = ${f0}`;
  }
  const key = state.materials[0];
  if (!key) return '';
  const { metal, f0 } = fresnelParams(key, state.conductor);
  const value = metal ? rgb(f0) : texNumber(f0[0]);
  const source = metal
    ? `\\sym{conductor}{\\text{${state.conductor === 'measured' ? 'measured' : 'fitted'} } n, k}`
    : 'n';
  return `F_0 = \\frac{(n-1)^2 + k^2}{(n+1)^2 + k^2} = ${value}\\ \\text{(${materialByKey(key).name}, from }${source})`;
}

/** Schlick's approximation built from the first chosen curve's F0, as the dashed curves are. */
export const FORMULA = declareFormula('fresnel-curves', (state) => {
  const line = f0Line(state);
  const f0 = firstF0(state);
  const F0 = '\\sym{materials}{F_0}';
  const value = f0.length === 1 ? ` = ${texNumber(f0[0])} + ${texNumber(1 - f0[0])}\\,(1 - \\cos\\theta)^5` : '';
  const schlick = `\\sym{schlick}{F_{\\text{Schlick}}}(\\theta) = ${F0} + (1 - ${F0})(1 - \\cos\\theta)^5${value}`;
  return line ? `\\begin{gathered}${line}\\\\ ${schlick}\\end{gathered}` : schlick;
});
