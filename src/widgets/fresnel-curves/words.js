// fresnel-curves, in words: the about text, the readout's caption and the plots' summary for screen readers.
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
