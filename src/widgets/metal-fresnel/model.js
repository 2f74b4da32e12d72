// metal-fresnel, its model as pure functions: for each channel of a measured metal, the exact conductor Fresnel
// curve against the angle of incidence, each approximation's curve and its error, and the table of worst errors
// over the talk's five metals.
import { fresnelConductor } from '../../math/fresnel.js';
import { METALS, materialByKey } from '../../math/materials.js';
import { measuredRgbNk } from '../../math/optical-constants.js';
import { METAL_MODELS, channelFit, modelValue } from './models.js';

export const CHANNELS = ['R', 'G', 'B'];
export const ANGLE_STEP_DEG = 0.25;

export function angleGrid(step = ANGLE_STEP_DEG) {
  const n = Math.round(90 / step) + 1;
  return Float64Array.from({ length: n }, (_, i) => i * step);
}

const cosDeg = (deg) => Math.cos((deg * Math.PI) / 180);

/**
 * One channel over `angles` (degrees): its fit, the exact curve, and per model its curve, its error (model −
 * exact) and its worst error { value, at } (signed, at the angle in degrees).
 */
export function compareChannel(eta, k, angles) {
  const fit = channelFit(eta, k);
  const exact = angles.map((deg) => fresnelConductor(cosDeg(deg), eta, k));
  const models = Object.fromEntries(
    Object.keys(METAL_MODELS).map((model) => {
      const values = angles.map((deg) => modelValue(model, fit, cosDeg(deg)));
      const error = values.map((v, i) => v - exact[i]);
      let worst = { value: 0, at: 0 };
      error.forEach((e, i) => {
        if (Math.abs(e) > Math.abs(worst.value)) worst = { value: e, at: angles[i] };
      });
      return [model, { values, error, worst }];
    }),
  );
  return { fit, exact, models };
}

/** A metal's three channels (R, G, B at the measured data's 650, 550, 450 nm) over `angles`. */
export function compareMetal(key, angles = angleGrid()) {
  return measuredRgbNk(key).map(([eta, k], channel) => ({ channel, ...compareChannel(eta, k, angles) }));
}

/** Every channel of the talk's five metals: name, channel, fit and each model's worst error over 0–90°. */
export function errorTable(angles = angleGrid()) {
  return METALS.flatMap((m) =>
    compareMetal(m.key, angles).map((c) => ({
      key: m.key,
      name: materialByKey(m.key).name,
      channel: c.channel,
      fit: c.fit,
      worst: Object.fromEntries(Object.entries(c.models).map(([model, r]) => [model, r.worst])),
    })),
  );
}

/** The row where `model` is furthest off. */
export const worstRow = (rows, model) =>
  rows.reduce((a, r) => (Math.abs(r.worst[model].value) > Math.abs(a.worst[model].value) ? r : a));
