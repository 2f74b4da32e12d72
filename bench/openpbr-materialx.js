// `node bench/bench.js --only materialx`: the app's OpenPBR Surface against the specification's reference
// implementation, MaterialX 1.39.5's open_pbr_surface graph as its EsslShaderGenerator writes it in GLSL ES 3.00
// (scripts/materialx-shaders.py). Both shaders, MaterialX's and the app's (shaders/openpbr.glsl), run in headless
// Chromium on the same grid of 4 directional lights × 162 views (tests/support/materialx-render.js, shared with
// tests/browser/materialx.test.js), for the material lab's presets and one material built up layer by layer. Per
// material and channel: the largest and the mean difference of the app's radiance from MaterialX's, relative (the
// materials span a near-black velvet to a gold highlight: an absolute figure would only say which is brightest),
// against the larger of MaterialX's value and 1 % of the material's brightest sample (so a near-black sample counts
// at 1 % of the picture's scale), and where the largest is. Also the app's float64 openPbrBRDF against the same
// pictures, and, for the isotropic materials with no coat or fuzz, the catalogue's terms with Turquin's
// multiple-scattering compensation added (tests/support/openpbr-base.js): the app's lobes are single-scattering,
// the talk's model, and MaterialX compensates them; what is left with the compensation is what else differs.
// Without the MaterialX venv (scripts/materialx-venv.sh) it says so and the report keeps the last figures.
import { launchBrowser, ROOT } from '../tests/browser/harness.js';
import { MATERIALX_BENCH_MATERIALS } from '../tests/support/materialx-materials.js';
import { materialxPython, MATERIALX_MISSING } from '../tests/support/materialx-python.js';
import {
  anglesOf,
  appPrograms,
  brdfRadiance,
  FLOOR,
  generateMaterialx,
  LIGHTS,
  materialxPrograms,
  radianceAt,
  relativeDifferences,
  renderPrograms,
  samplesOf,
  VIEWS,
} from '../tests/support/materialx-render.js';
import { openPbrBaseBRDF } from '../tests/support/openpbr-base.js';
import { openPbrBRDF } from '../src/math/openpbr.js';
import { DEG } from '../src/math/angles.js';
import { percent, rgb } from '../src/pages/openpbr-materialx.js';
import { viteModules } from '../scripts/vite-modules.js';

/** The app's assembleGlsl with its shader chunks (read by import.meta.glob), loaded through Vite's module runner. */
async function appAssembler() {
  const runner = await viteModules();
  try {
    return (await runner.import('/src/core/gpu/glsl.js')).assembleGlsl;
  } finally {
    await runner.close();
  }
}

/** A comparison's figures: per channel the largest and mean relative difference, and where the largest is. */
const figures = ({ max, mean, worst }) => ({
  maxRelative: max,
  meanRelative: mean,
  worst: { relative: worst.error, channel: 'rgb'[worst.channel], ...anglesOf(worst) },
});

/** The compensated composition (openpbr-base.js) has no coat, fuzz or anisotropy: the materials it can stand for. */
const compensable = (m) => !m.layers.length && !(m.inputs.specular_roughness_anisotropy > 0);

/** One material's rows: the app's GLSL and float64 BRDF, and the compensated composition, against MaterialX. */
function materialRow(material, materialx, app) {
  const reference = radianceAt(materialx);
  const against = (compared) => figures(relativeDifferences(samplesOf(reference, compared)));
  return {
    name: material.name,
    label: material.label,
    source: material.source,
    layers: material.layers,
    glsl: against(radianceAt(app)),
    float64: against(brdfRadiance(openPbrBRDF, material.inputs)),
    ...(compensable(material) ? { withTurquin: against(brdfRadiance(openPbrBaseBRDF, material.inputs)) } : {}),
  };
}

/** The MaterialX part of the report, or null (and why, on stderr) when the MaterialX package is not installed. */
export async function measureMaterialx() {
  const python = materialxPython();
  if (!python) {
    console.error(`--only materialx: ${MATERIALX_MISSING}; the report keeps the last MaterialX figures`);
    return null;
  }
  const generated = generateMaterialx(python, MATERIALX_BENCH_MATERIALS, ROOT);
  const programs = appPrograms(MATERIALX_BENCH_MATERIALS, await appAssembler());
  const browser = await launchBrowser();
  try {
    const page = await browser.newPage();
    // SwiftShader compiles MaterialX's 2100-line shader at its first draw: minutes on the loaded machine
    page.setDefaultTimeout(900_000);
    const materialx = await renderPrograms(page, materialxPrograms(generated));
    const app = await renderPrograms(page, programs);
    return {
      date: new Date().toISOString(),
      materialx: generated.version,
      chromium: await browser.version(),
      lightsDeg: LIGHTS.map((l) => Math.round(Math.acos(l[2]) / DEG)),
      views: VIEWS.length,
      floor: FLOOR,
      rows: MATERIALX_BENCH_MATERIALS.map((m) => materialRow(m, materialx.get(m.name), app.get(m.name))),
    };
  } finally {
    await browser.close();
  }
}

/** The part as a table on stdout. */
export function printMaterialx(part) {
  console.log(
    `\nOpenPBR Surface against MaterialX ${part.materialx}'s open_pbr_surface (its GLSL ES), measured ` +
      `${part.date.slice(0, 10)}: relative difference per channel (r / g / b) over ${part.lightsDeg.length} lights ` +
      `× ${part.views} views, against the larger of MaterialX's value and ${part.floor * 100} % of the peak`,
  );
  for (const r of part.rows) {
    const w = r.glsl.worst;
    const turquin = r.withTurquin ? `; with Turquin's compensation ${percent(r.withTurquin.worst.relative)}` : '';
    console.log(
      `  ${r.label.padEnd(34)} GLSL max ${rgb(r.glsl.maxRelative)}, mean ${rgb(r.glsl.meanRelative)} ` +
        `(worst at θl ${w.thetaL}°, θv ${w.thetaV}°, φv ${w.phiV}°, ${w.channel}); float64 max ` +
        `${percent(r.float64.worst.relative)}${turquin}`,
    );
  }
}
