// The white furnace's spheres: one per roughness in a uniform white environment, each pixel E(n·v) from the
// split-sum table (GGX, height-correlated Smith, F = 1), or, compensated, the albedo with the lost energy put back
// (from the albedo-loss table, made when a compensation is first chosen). The probe reads E and the loss there.
import { createSphereGrid } from '../../core/ui/sphere-grid.js';
import { HALF_SIZE } from '../../core/ui/sphere-impostor.js';
import { createDfgTexture } from '../../lab/environment-maps.js';
import { createAlbedoTableTexture, albedoTableOnce } from '../../core/gpu/albedo-table-texture.js';
import { albedoGGX } from '../../math/integrate.js';
import { specularAlbedoFromTable } from '../../math/albedo-table.js';
import { termDefines } from '../../math/catalogue/index.js';
import { sharedUniforms } from '../../math/catalogue/uniforms.js';

/** The furnace's shader variant: a compensation's own switch and, with one, the albedo-loss table it reads. */
export const furnaceDefines = (compensation) => ({
  FURNACE: 1,
  ...termDefines({ compensation }),
  ...(compensation === 'none' ? {} : { ALBEDO_TABLE_GGX: 1 }),
});

/** The probe's rows at a sphere point: E(n·v), the energy lost and, compensated, the albedo with it put back. */
function probeRows(a, alpha, compensation, compensationLabel) {
  const e = albedoGGX(a.nv, alpha);
  const rows = [
    ['E(n·v), F = 1', e.toFixed(4)],
    ['energy lost', `${((1 - e) * 100).toFixed(1)}%`],
  ];
  if (compensation === 'none') return rows;
  const compensated = specularAlbedoFromTable(albedoTableOnce(), a.nv, alpha, 1, compensation);
  return [...rows, [`with ${compensationLabel}`, compensated.toFixed(4)]];
}

/** What the furnace shows, over the spheres: a sphere that loses nothing disappears into the background. */
export const furnaceCaption = (compensationLabel) =>
  'White furnace: light of radiance 1 from all around, on a background of the same radiance. A sphere that loses ' +
  'no energy looks just like the background and disappears (dashed: round each sphere). ' +
  (compensationLabel
    ? `${compensationLabel} puts back the light lost between facets: every sphere disappears (probe one: E = 1).`
    : 'The grey that stays is the energy lost; probe a sphere to read it.');

/**
 * Dashed circles round the spheres, just outside each silhouette so that no sphere pixel is covered (the grid's
 * cells are squares: cell i spans [i, i + 1] of n × 1; a sphere's radius is half a cell over HALF_SIZE).
 */
const OUTSIDE = 1.03;
function createOutlines(holder) {
  const svg = document.createElementNS('http://www.w3.org/2000/svg', 'svg');
  svg.classList.add('furnace-outlines');
  svg.setAttribute('aria-hidden', 'true');
  holder?.append(svg);
  return (n) => {
    svg.setAttribute('viewBox', `0 0 ${Math.max(n, 1)} 1`);
    svg.innerHTML = Array.from(
      { length: n },
      (_, i) =>
        `<circle cx="${i + 0.5}" cy="0.5" r="${(0.5 / HALF_SIZE) * OUTSIDE}" vector-effect="non-scaling-stroke" />`,
    ).join('');
  };
}

export function createFurnaceSpheres(container) {
  const caption = document.createElement('p');
  caption.className = 'furnace-caption';
  container.append(caption);
  const grid = createSphereGrid(container, { label: 'Spheres in a white furnace', background: '#ffffff' });
  const outline = createOutlines(grid.canvas?.parentElement);
  const dfg = createDfgTexture(); // GGX, height-correlated Smith: scale + bias is E
  let lossTable = null;
  return {
    /** One sphere per α of the sweep, with `compensation` (a key) whose label the probe shows. */
    draw(sweep, compensation, compensationLabel) {
      caption.textContent = furnaceCaption(compensation === 'none' ? null : compensationLabel);
      outline(sweep.length);
      if (compensation !== 'none') lossTable ??= createAlbedoTableTexture();
      grid.setCells(
        sweep.map((d) => ({
          label: `α = ${d.alpha}`,
          defines: furnaceDefines(compensation),
          uniforms: { ...sharedUniforms({ alphaPair: [d.alpha, d.alpha] }), uDfg: dfg, uAlbedoTableGGX: lossTable },
          probe: (a) => probeRows(a, d.alpha, compensation, compensationLabel),
        })),
      );
    },
    get canvas() {
      return grid.canvas;
    },
    dispose() {
      caption.remove();
      grid.dispose();
      dfg.dispose();
      lossTable?.dispose();
    },
  };
}
