// The material lab's OpenPBR Surface material (src/math/openpbr.js): its fields, grouped as the specification groups
// them (base, specular, coat, fuzz) under the specification's own parameter names, a switch per layer, and the
// material a state gives. A layer switched off has its weight set to 0, as the specification's weight removes it
// (so the layers beneath are no longer dimmed by it). Colours are sRGB '#rrggbb' fields; the exact linear values of
// a loaded file are kept beside them (`exact`) and used while the field still shows them, so that a file read and
// saved unchanged is written as it was read. Pure: loads in Node.
import { OPENPBR_DEFAULTS } from '../math/openpbr.js';
import { linearToSrgb, srgbToLinear } from '../math/color.js';
import { hexToRgb, rgbToHex } from '../core/ui/palettes.js';

const slider = (group, label, min = 0, max = 1, step = 0.01) => ({ group, type: 'number', min, max, step, label });
const colour = (group, label) => ({ group, type: 'color', label });

/** The layers, as the specification groups its parameters: the group's name, its switch and its weight. */
export const OPENPBR_LAYERS = Object.freeze({
  base: { group: 'OpenPBR base', toggle: 'openpbrBase', weight: 'base_weight', label: 'Base' },
  specular: { group: 'OpenPBR specular', toggle: 'openpbrSpecular', weight: 'specular_weight', label: 'Specular' },
  coat: { group: 'OpenPBR coat', toggle: 'openpbrCoat', weight: 'coat_weight', label: 'Coat' },
  fuzz: { group: 'OpenPBR fuzz', toggle: 'openpbrFuzz', weight: 'fuzz_weight', label: 'Fuzz' },
});
const G = Object.fromEntries(Object.entries(OPENPBR_LAYERS).map(([k, l]) => [k, l.group]));

/** The parameters' controls (a colour's default is its linear default in sRGB). The indices stop at 3: diamond's
 * 2.42 is the highest of the talk's F0 table. */
const CONTROLS = {
  base_weight: slider(G.base, 'base_weight'),
  base_color: colour(G.base, 'base_color'),
  base_metalness: slider(G.base, 'base_metalness'),
  base_diffuse_roughness: slider(G.base, 'base_diffuse_roughness'),
  specular_weight: slider(G.specular, 'specular_weight'),
  specular_color: colour(G.specular, 'specular_color'),
  specular_roughness: slider(G.specular, 'specular_roughness', 0, 1, 0.005),
  specular_roughness_anisotropy: slider(G.specular, 'specular_roughness_anisotropy'),
  specular_ior: slider(G.specular, 'specular_ior', 1, 3),
  coat_weight: slider(G.coat, 'coat_weight'),
  coat_color: colour(G.coat, 'coat_color'),
  coat_roughness: slider(G.coat, 'coat_roughness', 0, 1, 0.005),
  coat_roughness_anisotropy: slider(G.coat, 'coat_roughness_anisotropy'),
  coat_ior: slider(G.coat, 'coat_ior', 1, 3),
  coat_darkening: slider(G.coat, 'coat_darkening'),
  fuzz_weight: slider(G.fuzz, 'fuzz_weight'),
  fuzz_color: colour(G.fuzz, 'fuzz_color'),
  fuzz_roughness: slider(G.fuzz, 'fuzz_roughness'),
};

export const OPENPBR_KEYS = Object.freeze(Object.keys(OPENPBR_DEFAULTS));
const isColour = (key) => Array.isArray(OPENPBR_DEFAULTS[key]);
/** Linear [r, g, b] as the sRGB field shows it. */
export const colourHex = (rgb) => rgbToHex(rgb.map(linearToSrgb));

// the folders start closed (types.js: `closed` on a group's first field): the lab opens on the talk's model, its
// panel near the view's height, and a preset or a file fills the OpenPBR fields
const toggle = (layer) => ({
  group: layer.group,
  closed: true,
  type: 'bool',
  default: true,
  label: `${layer.label} layer on`,
  hint: `Off sets ${layer.weight} to 0, as the specification's weight takes the layer away.`,
});

/** The schema fields of the panel: per group, its switch first, then its parameters. */
export const OPENPBR_FIELDS = Object.fromEntries(
  Object.values(OPENPBR_LAYERS).flatMap((layer) => [
    [layer.toggle, toggle(layer)],
    ...OPENPBR_KEYS.filter((k) => CONTROLS[k].group === layer.group).map((k) => {
      const fallback = OPENPBR_DEFAULTS[k];
      return [k, { ...CONTROLS[k], default: isColour(k) ? colourHex(fallback) : fallback }];
    }),
  ]),
);

/**
 * The OpenPBR material of a lab state: every key of OPENPBR_DEFAULTS, a colour from its field (or, while the field
 * shows it, its exact value in `exact`: { key: [r, g, b] } of a loaded file), the weight of a layer switched off 0.
 * @param {Record<string, any>} state
 * @param {Record<string, number[]>} [exact]
 */
export function openPbrOfState(state, exact = {}) {
  const m = Object.fromEntries(
    OPENPBR_KEYS.map((k) => {
      if (!isColour(k)) return [k, state[k]];
      const kept = exact[k] && colourHex(exact[k]) === state[k];
      return [k, kept ? [...exact[k]] : hexToRgb(state[k]).map(srgbToLinear)];
    }),
  );
  for (const layer of Object.values(OPENPBR_LAYERS)) if (!state[layer.toggle]) m[layer.weight] = 0;
  return m;
}

/** The parameters the lab's material as it would be saved: the switches' zeros left out (a file has no switch). */
export const savedOpenPbr = (state, exact) =>
  openPbrOfState(
    { ...state, ...Object.fromEntries(Object.values(OPENPBR_LAYERS).map((l) => [l.toggle, true])) },
    exact,
  );

/**
 * A material (OpenPBR's names; a key left out takes its default) as a state patch: every field set, every layer
 * on, and the colours' exact values to keep beside the fields. A value beyond its slider is refused: the Error names
 * it (the lab's sliders are narrower than the specification's unbounded indices and weights).
 * @param {Record<string, any>} material
 */
export function stateOfOpenPbr(material) {
  const patch = {};
  const exact = {};
  for (const k of OPENPBR_KEYS) {
    const value = material[k] ?? OPENPBR_DEFAULTS[k];
    if (isColour(k)) {
      exact[k] = [...value];
      patch[k] = colourHex(value);
      continue;
    }
    const { min, max } = CONTROLS[k];
    if (!(value >= min && value <= max)) throw new Error(`${k} is ${value}, beyond the lab's range [${min}, ${max}]`);
    patch[k] = value;
  }
  for (const layer of Object.values(OPENPBR_LAYERS)) patch[layer.toggle] = true;
  return { patch, exact };
}
