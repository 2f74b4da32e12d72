// The MaterialX part of the report (bench/openpbr-materialx.js) as docs/performance.md's table (bench/readme-lines.js).
import { percent, rgb } from '../src/pages/openpbr-materialx.js';

/** The part's lines: what was compared, then one row per material. */
export const materialxLines = (part) => [
  `**OpenPBR Surface against MaterialX's reference shader** (\`node bench/bench.js --only materialx\`, measured ` +
    `${part.date.slice(0, 10)}): MaterialX ${part.materialx}'s \`open_pbr_surface\` as its EsslShaderGenerator ` +
    `writes it, and the app's \`shaders/openpbr.glsl\`, in Chromium under one directional light at ` +
    `${part.lightsDeg.join('°, ')}° × ${part.views} views; the app's radiance against MaterialX's per channel ` +
    `(r / g / b), relative to the larger of MaterialX's value and ${part.floor * 100} % of the material's peak. ` +
    '"With Turquin": the catalogue\'s terms with MaterialX\'s multiple-scattering compensation put in (uncoated ' +
    'isotropic materials only).',
  '',
  '| material | largest | mean | largest at (θl, θv, φv) | float64 `openPbrBRDF`: largest | with Turquin: largest |',
  '|---|---|---|---|---|---|',
  ...part.rows.map((r) => {
    const w = r.glsl.worst;
    return (
      `| ${r.label} | ${rgb(r.glsl.maxRelative)} | ${rgb(r.glsl.meanRelative)} | ` +
      `${w.thetaL}°, ${w.thetaV}°, ${w.phiV}° (${w.channel}) | ${percent(r.float64.worst.relative)} | ` +
      `${r.withTurquin ? percent(r.withTurquin.worst.relative) : '—'} |`
    );
  }),
  '',
];
