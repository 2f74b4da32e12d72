// brdf-lobe: the microfacet BRDF taken apart, in the spirit of Disney's BRDF Explorer. For a light the user
// drags: the BRDF in the plane of incidence (polar), as a 3-D lobe, over the half/difference angles, and its
// directional albedo; each factor (F, D, G, the denominator) can be switched off, and a second BRDF overlaid.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createPlot } from '../../core/ui/plot.js';
import { NDF_TERMS, VISIBILITY_TERMS, brdfAngles, microfacetBRDF, microfacetFactors } from '../../math/brdf.js';
import { ndfParamsMatchingGGX } from '../../math/ndf-width.js';
import { directionFromCos, reflectanceImportanceGGX } from '../../math/integrate.js';
import { directionsFromHalfDiff } from '../../math/half-diff.js';
import { NDFS } from '../ndf-explorer/ndf-explorer.js';
import { TERMS } from '../visibility-explorer/visibility-explorer.js';
import { createPolarPlot } from './polar-plot.js';
import { createLobeView } from './lobe-view.js';
import { createHalfDiffImage } from './half-diff-image.js';
import { WALK_ANGLES, hasMultipleLobe, kullaContyLobe, walkMultiplePart } from './multiple-lobe.js';
import { DEG } from '../../math/angles.js';

const ndfOptions = Object.fromEntries(Object.keys(NDF_TERMS).map((k) => [k, NDFS[k].name]));
const visOptions = Object.fromEntries(Object.keys(VISIBILITY_TERMS).map((k) => [k, TERMS[k].name]));

export const schema = {
  lightTheta: { type: 'number', min: 0, max: 89, step: 1, default: 45, label: 'Light θl', unit: '°' },
  viewTheta: { type: 'number', min: -89, max: 89, step: 1, default: 45, label: 'View θv (+: mirror side)', unit: '°' },
  D: { type: 'enum', options: ndfOptions, default: 'ggx', label: 'A: D' },
  V: { type: 'enum', options: visOptions, default: 'smithGGXCorrelated', label: 'A: V' },
  F: { type: 'enum', options: { schlick: 'Schlick', one: 'F = 1' }, default: 'schlick', label: 'F' },
  alpha: { type: 'number', min: 0.02, max: 1, step: 0.01, default: 0.3, label: 'A: roughness α (GGX)' },
  f0: { type: 'number', min: 0, max: 1, step: 0.01, default: 0.04, label: 'F0' },
  useF: { type: 'bool', default: true, label: 'Factor F' },
  useD: { type: 'bool', default: true, label: 'Factor D' },
  useG: { type: 'bool', default: true, label: 'Factor G' },
  useDenominator: { type: 'bool', default: true, label: '÷ 4(n·l)(n·v)' },
  cosine: { type: 'bool', default: false, label: 'Lobe × n·v (intensity)' },
  multiple: { type: 'bool', default: false, label: 'Multiple scattering (A, GGX)' },
  compare: { type: 'bool', default: false, label: 'Overlay BRDF B' },
  D2: { type: 'enum', options: ndfOptions, default: 'beckmann', label: 'B: D' },
  V2: { type: 'enum', options: visOptions, default: 'smithBeckmannSeparable', label: 'B: V' },
  alpha2: { type: 'number', min: 0.02, max: 1, step: 0.01, default: 0.3, label: 'B: roughness α (GGX)' },
  phiD: { type: 'number', min: 0, max: 180, step: 1, default: 90, label: 'Image φd', unit: '°' },
};

const ABOUT =
  'Drag l or v on the polar plot (or focus it and use the arrow keys). The lobe is f(l, v) for every view ' +
  'direction: turn off D and the highlight’s shape is gone; turn off the denominator and the lobe stops ' +
  'growing at grazing angles (that denominator, with F, is why at moderate roughness f itself is largest towards the ' +
  'horizon, while at α = 0.1 it peaks near the mirror direction); turn off G and nothing dims at the horizon. ' +
  '× n·v multiplies the lobe by the cosine of the view, showing how much light leaves towards each direction; the ' +
  'reflectance equation’s cosine is another one, n·l, of the incoming light. Roughness is GGX’s α; other NDFs take ' +
  'the parameters that give them the same half width. The image over (θh, θd) shows the same BRDF in the ' +
  'angles it really depends on; the albedo plot integrates it over all light directions. Multiple scattering adds, ' +
  'dotted, the light that bounces between microfacets before it leaves (Kulla & Conty 2017), nearly diffuse in shape, ' +
  'with dots from the random walk on the microsurface (Heitz et al. 2016) that it approximates.';

const lightDir = (deg) => [-Math.sin(deg * DEG), 0, Math.cos(deg * DEG)];
const viewDir = (deg) => [Math.sin(deg * DEG), 0, Math.cos(deg * DEG)];

function brdfSpec(state, which) {
  const [D, V, alpha] = which === 'B' ? [state.D2, state.V2, state.alpha2] : [state.D, state.V, state.alpha];
  return {
    D,
    V,
    F: state.F,
    f0: state.f0,
    ...ndfParamsMatchingGGX(D, alpha),
    samplingAlpha: alpha,
    label: `${which}: ${NDFS[D].name.split(' (')[0]} + ${TERMS[V].name}`,
  };
}

const TERMS_USED = [
  'microfacetBRDF',
  'fresnelSchlick',
  'ndfGGX',
  'ndfBeckmann',
  'ndfBlinnPhong',
  'ndfABC',
  'ndfSGD',
  'visibilitySmithGGXCorrelated',
  'multipleScatteringKullaConty',
  'fresnelMultipleScatteringKullaConty',
];

const multipleF0 = (s) => (s.F === 'one' || !s.useF ? 1 : s.f0); // F = 1 when Fresnel is off
const kullaContyAt = (s, l, v) => kullaContyLobe(l, v, s.alpha, multipleF0(s));

/** The dotted lobe and the walk's dots when multiple scattering is on (and defined for A), else nulls. */
function multipleScattering(s, A, l) {
  if (!s.multiple || !hasMultipleLobe(A)) return { lobe: null, points: null };
  const f0 = multipleF0(s);
  const weight = (v) => (s.cosine ? Math.max(v[2], 0) : 1);
  const lobe = Array.from({ length: 357 }, (_, i) => {
    const v = viewDir(-89 + i * 0.5);
    return [-89 + i * 0.5, kullaContyLobe(l, v, s.alpha, f0) * weight(v)];
  });
  const points = WALK_ANGLES.map((theta, i) => {
    const v = viewDir(theta);
    const w = walkMultiplePart(l, v, s.alpha, f0, 1 + i);
    return [theta, w.value * weight(v), w.error * weight(v)];
  });
  return { lobe, points };
}

function multipleWords(s, A, ms) {
  if (!s.multiple) return '';
  if (!ms.lobe) return ' Multiple scattering is shown for GGX with height-correlated Smith only: choose those for A.';
  const at = (theta) => ms.lobe[Math.round((theta + 89) * 2)][1];
  return (
    ` Dotted: the multiple-scattering lobe of Kulla & Conty (${at(0).toPrecision(3)} /sr at 0°, ${at(60).toPrecision(3)} at 60°), ` +
    `with dots from the random walk (${ms.points.find((p) => p[0] === 5)[1].toPrecision(3)} ± ${ms.points.find((p) => p[0] === 5)[2].toPrecision(1)} at 5°).`
  );
}

export function createBrdfLobe(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'brdf-lobe',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const top = document.createElement('div');
  top.className = 'lobe-row';
  const bottom = document.createElement('div');
  bottom.className = 'lobe-row';
  const readout = document.createElement('div');
  shell.view.append(top, bottom, readout);
  const update = (partial) => updateState(partial);
  const polar = createPolarPlot(top, { onDrag: update });
  const lobeHolder = document.createElement('div');
  lobeHolder.className = 'lobe-3d';
  top.append(lobeHolder);
  const lobe3d = createLobeView(lobeHolder);
  const images = document.createElement('div');
  images.className = 'half-diff-row';
  bottom.append(images);
  const imageA = createHalfDiffImage(images, 'A over (θh, θd)');
  const imageB = createHalfDiffImage(images, 'B over (θh, θd)');
  const plotHolder = document.createElement('div');
  plotHolder.className = 'albedo-plot';
  bottom.append(plotHolder);

  const use = () => ({
    F: shell.state.useF,
    D: shell.state.useD,
    G: shell.state.useG,
    denominator: shell.state.useDenominator,
  });
  const specs = () => [brdfSpec(shell.state, 'A'), ...(shell.state.compare ? [brdfSpec(shell.state, 'B')] : [])];

  const albedoSpec = () => {
    const angles = Float64Array.from({ length: 45 }, (_, i) => i * 2 + 1);
    const series = specs().map((p, i) => ({
      label: p.label,
      stroke: i ? '#009e73' : '#d55e00',
      dash: i ? [6, 4] : undefined, // B dashed, as on the polar plot
      values: angles.map((deg) =>
        reflectanceImportanceGGX(
          (l, v) => microfacetBRDF(l, v, p),
          directionFromCos(Math.cos(deg * DEG)),
          p.samplingAlpha,
          512,
        ),
      ),
    }));
    return {
      title: 'Directional albedo E(θv) = ∫ f (n·l) dω (all factors on)',
      xLabel: 'View angle θv (degrees)',
      yLabel: 'E',
      x: { min: 0, max: 90 },
      y: null,
      xValues: (u, t) => t.map((v) => `${v}°`),
      series,
      data: [angles, ...series.map((s) => s.values)],
      filename: 'brdf-albedo',
      height: 250,
    };
  };
  let albedo = createPlot(plotHolder, albedoSpec());

  const render = (changed) => {
    const s = shell.state;
    const l = lightDir(s.lightTheta);
    const v = viewDir(s.viewTheta);
    const [A, B] = specs();
    const f = (p) => (vv) => microfacetFactors(l, vv, p, use()) * (s.cosine ? Math.max(vv[2], 0) : 1);
    const lobeOf = (p) =>
      Array.from({ length: 357 }, (_, i) => {
        const theta = -89 + i * 0.5;
        return [theta, f(p)(viewDir(theta))];
      });
    const lobeA = lobeOf(A);
    const lobeB = B ? lobeOf(B) : null;
    const ms = multipleScattering(s, A, l);
    const max = Math.max(...[lobeA, lobeB, ms.lobe, ms.points].flatMap((lobe) => (lobe ?? []).map((x) => x[1])), 1e-9);
    const a = brdfAngles(l, v);
    polar.draw({
      lobeA,
      lobeB,
      lobeMS: ms.lobe,
      points: ms.points,
      max,
      lightTheta: s.lightTheta,
      viewTheta: s.viewTheta,
      halfTheta: a.h ? Math.atan2(a.h[0], a.h[2]) / DEG : null,
    });
    const peakOf = (lobe) => lobe.reduce((a, x) => (x[1] > a[1] ? x : a));
    const off = ['F', 'D', 'G'].filter((k) => !s[`use${k}`]).concat(s.useDenominator ? [] : ['the denominator']);
    const what = `${s.cosine ? 'f(l, v) × n·v' : 'f(l, v)'} for ${A.label}${B ? ` and, dashed, ${B.label}` : ''}${off.length ? ` with ${off.join(', ')} switched off` : ''}`;
    const peaks = [
      [A, lobeA],
      [B, lobeB],
    ]
      .filter(([p]) => p)
      .map(([p, lobe]) => {
        const [theta, value] = peakOf(lobe);
        return `${p.label.slice(0, 1)} peaks at ${theta.toFixed(1)}° (${value.toPrecision(3)} /sr)`;
      });
    shell.describe(
      `Polar plot in the plane of incidence: ${what}. Light ${s.lightTheta}° from n on the left, view at ${s.viewTheta}°, mirror direction at ${s.lightTheta}°. ${peaks.join('; ')}.${multipleWords(s, A, ms)}`,
      polar.canvas,
    );
    const max3d = Math.max(max, 1e-9);
    lobe3d.update({
      fA: f(A),
      fB: B ? f(B) : null,
      max: max3d,
      description:
        `3-D lobe of ${A.label}${B ? ` (solid) and ${B.label} (wireframe)` : ''} over the hemisphere, light ${s.lightTheta}° from n; ` +
        `each direction's distance from the centre is ${s.cosine ? 'f × n·v' : 'f'}, scaled to ${max3d.toPrecision(3)}. Arrows: n, l, v, h and the mirror direction.`,
      directions: { n: [0, 0, 1], l, v, h: a.h, mirror: [-l[0], 0, l[2]] },
    });
    if (!changed || changed.some((k) => !['lightTheta', 'viewTheta'].includes(k))) {
      const image = (p) => (th, td) => {
        const d = directionsFromHalfDiff(th, td, s.phiD * DEG);
        return microfacetFactors(d.l, d.v, p, use());
      };
      const words = (p, alpha) => `${p.label}, α ${alpha}, F0 ${s.f0}, at φd ${s.phiD}°`;
      imageA.draw(image(A), words(A, s.alpha));
      imageB.draw(B ? image(B) : () => 0, B ? words(B, s.alpha2) : 'not shown (no overlay)');
      images.classList.toggle('single', !B);
    }
    if (changed?.some((k) => ['D', 'V', 'F', 'alpha', 'f0', 'compare', 'D2', 'V2', 'alpha2'].includes(k)))
      albedo.setData(albedoSpec());
    const rows = [A, B].filter(Boolean).map((p) => {
      const t = microfacetFactors(l, v, p, { F: true, D: true, G: true, denominator: true });
      const terms = { F: 1, D: 1, G: 1 };
      if (a.h && a.nl > 0 && a.nv > 0) {
        terms.F = p.F === 'one' ? 1 : microfacetFactors(l, v, p, { F: true, D: false, G: false, denominator: false });
        terms.D = microfacetFactors(l, v, p, { F: false, D: true, G: false, denominator: false });
        terms.G = microfacetFactors(l, v, p, { F: false, D: false, G: true, denominator: false });
      }
      return `<tr><td>${p.label}</td><td>${terms.F.toFixed(4)}</td><td>${terms.D.toPrecision(4)}</td><td>${terms.G.toFixed(4)}</td><td>${t.toPrecision(4)}</td></tr>`;
    });
    readout.innerHTML =
      `<table class="data-table compact"><caption>At l = ${s.lightTheta}°, v = ${s.viewTheta}°: n·l ${a.nl.toFixed(3)}, n·v ${a.nv.toFixed(3)}, n·h ${a.nh.toFixed(3)}, l·h ${a.lh.toFixed(3)}</caption>` +
      `<thead><tr><th>BRDF</th><th>F</th><th>D (1/sr)</th><th>G</th><th>f = FDG/(4 n·l n·v) (1/sr)</th></tr></thead><tbody>${rows.join('')}</tbody></table>` +
      (ms.lobe
        ? `<p class="multiple-readout">Multiple scattering at v (A): Kulla–Conty ${kullaContyAt(s, l, v).toPrecision(3)} /sr` +
          ` beside single scattering ${microfacetBRDF(l, v, A).toPrecision(3)} /sr (dotted lobe; dots: the random walk, bars ± 2 standard errors).</p>`
        : '');
  };

  const updateState = shell.connect({ title: 'BRDF lobe', onChanged: render, onStateChange });
  render(null);

  return {
    update,
    getState: () => shell.state,
    dispose() {
      polar.dispose();
      lobe3d.dispose();
      imageA.dispose();
      imageB.dispose();
      albedo.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'brdf-lobe', schema, create: createBrdfLobe, terms: TERMS_USED };
