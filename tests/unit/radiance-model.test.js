// The radiance widget's model: the RGB shortcut (light ⊗ surface) against the per-wavelength product.
import { describe, expect, it } from 'vitest';
import { LIGHTS, SURFACES, colours, lampView } from '../../src/widgets/radiance/model.js';

describe('radiance widget model', () => {
  it('under the white that defines RGB (1, 1, 1) the shortcut is exact, for every surface (by construction)', () => {
    for (const s of Object.keys(SURFACES)) {
      const c = colours('daylight', s);
      c.light.forEach((x) => expect(x).toBeCloseTo(1, 12));
      c.product.forEach((x, i) => expect(x).toBeCloseTo(c.spectral[i], 12));
    }
  });
  it('a flat reflectance scales every wavelength alike, so the shortcut is exact under any light (linearity)', () => {
    for (const l of Object.keys(LIGHTS)) {
      const c = colours(l, 'grey');
      c.product.forEach((x, i) => expect(x).toBeCloseTo(c.spectral[i], 12));
      c.spectral.forEach((x, i) => expect(x).toBeCloseTo(0.5 * c.light[i], 12));
    }
  });
  it('under the sodium line, red paint’s red channel is 2.4× too bright in RGB (the figure the tour quotes)', () => {
    const c = colours('sodium', 'red');
    expect(c.product[0] / c.spectral[0]).toBeCloseTo(2.44, 2);
  });
  it('the lamp keeps its radiance at every distance; 4 m gives 1/16 of the irradiance at 1 m', () => {
    const at = (d) => lampView({ distance: d, lampRadius: 0.05 });
    expect(at(4).radiance).toBe(at(1).radiance);
    expect(at(4).irradiance / at(1).irradiance).toBeCloseTo(1 / 16, 12);
  });
});
