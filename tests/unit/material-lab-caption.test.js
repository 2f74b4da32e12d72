// The material lab's caption over its approximation says what the approximation does with each light on: a whole
// BRDF (a table, the user's, OpenPBR) has no split-sum, mirror or ambient form, so those lights are left out of it,
// as lab-approximations.js's notes say, and the caption must not claim them.
import { describe, expect, it } from 'vitest';
import { methodText } from '../../src/widgets/material-lab/words.js';
import { approximationNotes } from '../../src/lab/lab-approximations.js';

const lights = { punctual: {}, env: {}, ambient: [0.1, 0.1, 0.1] };
const state = (brdfSource, envMethod) => ({ brdfSource, envMethod, environment: 'studio', samples: 64 });

describe('material lab caption', () => {
  it('the talk’s model: the environment by the chosen method, the ambient light in', () => {
    expect(methodText(state('model', 'split-sum'), lights)).toBe('punctual (exact) + studio by split-sum + ambient');
  });

  it.each(['measured', 'custom', 'openpbr'])('%s: split sum and ambient left out, importance sampling kept', (src) => {
    expect(methodText(state(src, 'split-sum'), lights)).toBe('punctual (exact) + studio left out + ambient left out');
    expect(methodText(state(src, 'importance'), lights)).toMatch(/studio by 64 importance samples/);
  });

  it('agrees with the notes under the images for OpenPBR', () => {
    const scene = {
      openpbr: {},
      lights,
      methods: { env: 'split-sum', area: 'representative' },
      material: { alpha: 0.04 },
      terms: {},
    };
    expect(approximationNotes(scene).join(' ')).toMatch(/environment is left out of the approximation/);
  });
});
