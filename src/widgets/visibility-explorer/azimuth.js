// The visibility explorer's anisotropic plot (beyond the talk): Smith's G1 of one direction against its azimuth
// over a surface whose roughness is the pair (αx, αy). Smith's Λ of an anisotropic surface is the isotropic Λ at
// the roughness projected on the direction's azimuth, α(φ) = sqrt(cos²φ αx² + sin²φ αy²) (Heitz 2014), so the
// curve runs from the isotropic G1 at αx (φ = 0, along the tangent) to that at αy (φ = 90°).
import { createPlot } from '../../core/ui/plot.js';
import { DEG } from '../../math/angles.js';
import { anisotropicAlphas, smithG1BeckmannAniso, smithG1GGXAniso } from '../../math/anisotropic.js';
import { seriesStyle, SERIES_DASHES } from '../../core/ui/palettes.js';
import { describeAzimuth } from './words.js';

/** The azimuths of the plot, degrees from the tangent: G1 is symmetric about both axes, so 0° to 180° shows all. */
export const AZIMUTHS = Float64Array.from({ length: 181 }, (_, i) => i);

/** The pair (αx, αy) of the state: its α and anisotropy by its convention. */
export const alphaPairOf = (state) => anisotropicAlphas(state.alpha, state.anisotropy, state.convention);

/**
 * The plot's curves at polar angle viewTheta: anisotropic GGX's and Beckmann's G1 over AZIMUTHS, and isotropic
 * GGX's G1 at αx and at αy (flat: the two ends the anisotropic GGX curve must meet). [{ label, values, ...style }]
 */
export function azimuthCurves(state) {
  const [ax, ay] = alphaPairOf(state);
  const t = state.viewTheta * DEG;
  const dir = (deg) => [Math.sin(t) * Math.cos(deg * DEG), Math.sin(t) * Math.sin(deg * DEG), Math.cos(t)];
  const over = (g1) => Array.from(AZIMUTHS, (deg) => g1(...dir(deg), ax, ay));
  // isotropic GGX at one α (the anisotropic function at αx = αy: the isotropic one clamps α to 1, Burley's αx not)
  const flat = (alpha) => Array.from(AZIMUTHS, () => smithG1GGXAniso(Math.sin(t), 0, Math.cos(t), alpha, alpha));
  return [
    { label: 'GGX, anisotropic', values: over(smithG1GGXAniso), ...seriesStyle(0) },
    { label: 'Beckmann, anisotropic', values: over(smithG1BeckmannAniso), ...seriesStyle(1) },
    { label: `GGX, isotropic at αx`, values: flat(ax), ...seriesStyle(2), dash: SERIES_DASHES[1] },
    { label: `GGX, isotropic at αy`, values: flat(ay), ...seriesStyle(3), dash: SERIES_DASHES[1] },
  ];
}

const spec = (curves, state) => {
  const [ax, ay] = alphaPairOf(state).map((a) => a.toPrecision(3));
  return {
    title: `Masking G1 of a direction ${state.viewTheta}° from n against its azimuth, (αx, αy) = (${ax}, ${ay})`,
    xLabel: 'Azimuth of the direction from the tangent, φ (degrees)',
    x: { min: 0, max: 180 },
    xValues: (u, ticks) => ticks.map((v) => `${v}°`),
    yLabel: 'G1, Smith',
    y: null,
    legend: true,
    series: curves.map((c) => ({ label: c.label, stroke: c.stroke, dash: c.dash })),
    data: [AZIMUTHS, ...curves.map((c) => c.values)],
    filename: 'visibility-G1-azimuth',
    height: 240,
  };
};

export function createAzimuthPlot(container, state) {
  const holder = document.createElement('div');
  container.append(holder);
  const note = document.createElement('p');
  note.className = 'azimuth-note';
  let curves = azimuthCurves(state);
  const plot = createPlot(holder, spec(curves, state));
  holder.append(note);
  const describe = (s) => (note.textContent = describeAzimuth(curves, alphaPairOf(s), s));
  describe(state);
  return {
    draw(next) {
      curves = azimuthCurves(next);
      plot.setData(spec(curves, next));
      describe(next);
    },
    /** The curves drawn now: label → G1 over AZIMUTHS. */
    curves: () => Object.fromEntries(curves.map((c) => [c.label, Array.from(c.values)])),
    dispose() {
      plot.dispose();
      holder.remove();
    },
  };
}
