// The material lab's approximations against the terms chosen: which DFG table and prefiltered map each reads,
// and the sentences that say where a method has no form for a term. The sky's sun against its real size.
import { describe, expect, it } from 'vitest';
import { LAB_TERMS, approximationInputs, approximationNotes } from '../../src/lab/lab-approximations.js';
import { ENVIRONMENTS, SUN } from '../../src/lab/environments.js';

const scene = (terms = {}, lights = {}, methods = {}) => ({
  terms: { F: 'schlick', D: 'ggx', V: 'smithGGXCorrelated', diffuse: 'lambert', layers: 'both', ...terms },
  lights: { punctual: null, sphere: null, env: null, ambient: null, ...lights },
  methods: { env: 'split-sum', area: 'representative', samples: 16, ...methods },
});
const env = { intensity: 1 };

describe('material lab approximations', () => {
  it(
    'with a measured table: no DFG table or prefiltered map is read, ' +
      'and every method without a form for it says so',
    () => {
      const measured = (lights, methods) => ({
        ...scene({}, lights, methods),
        measured: 'gold.binary',
        material: { alpha: 0.2 },
      });
      expect(approximationInputs(measured({ env, ambient: [1, 1, 1] }, {}))).toEqual({ dfg: null, prefilter: null });
      for (const method of ['split-sum', 'mirror', 'pmrem']) {
        const notes = approximationNotes(measured({ env }, { env: method }));
        expect(notes[0]).toMatch(
          /^Measured BRDF \(gold\.binary\): the reference integrates the table itself.*α 0\.200/,
        );
        expect(notes[1]).toMatch(
          /has no form for a table .* left out of the approximation: choose importance sampling\.$/,
        );
      }
      expect(approximationNotes(measured({ env }, { env: 'importance' }))[1]).toMatch(
        /^Importance sampling: N directions from the fitted GGX lobe/,
      );
      expect(approximationNotes(measured({ ambient: [1, 1, 1] }, {})).join(' ')).toMatch(
        /Ambient: .* no form for a measured table/,
      );
    },
  );

  it('read the DFG table of the chosen D and V, and the map prefiltered with the chosen D, only where used', () => {
    const terms = { D: 'beckmann', V: 'kelemen' };
    expect(approximationInputs(scene(terms, { env }))).toEqual({
      dfg: { ndf: 'beckmann', visibility: 'kelemen' },
      prefilter: 'beckmann',
    });
    expect(approximationInputs(scene(terms, { ambient: [1, 1, 1] }))).toEqual({
      dfg: { ndf: 'beckmann', visibility: 'kelemen' },
      prefilter: null,
    });
    for (const method of ['mirror', 'importance', 'pmrem']) {
      expect(approximationInputs(scene(terms, { env }, { env: method }))).toEqual({ dfg: null, prefilter: null });
    }
  });

  it(
    'say, for every diffuse term but Lambert, that the mirror, ' +
      'the split sum and ambient light use Lambert in its place',
    () => {
      for (const diffuse of Object.keys(LAB_TERMS.diffuse).filter((k) => k !== 'lambert')) {
        for (const [lights, methods] of [
          [{ env }, { env: 'split-sum' }],
          [{ env }, { env: 'mirror' }],
          [{ ambient: [1, 1, 1] }, {}],
        ]) {
          const notes = approximationNotes(scene({ diffuse }, lights, methods)).join(' ');
          expect(notes).toContain(
            `form for ${LAB_TERMS.diffuse[diffuse]}, so ${LAB_TERMS.diffuse[diffuse]} is approximated by Lambert`,
          );
        }
        // importance sampling evaluates the chosen term; with the diffuse layer off there is nothing to say
        expect(approximationNotes(scene({ diffuse }, { env }, { env: 'importance' })).join(' ')).not.toContain(
          'Lambert',
        );
        expect(approximationNotes(scene({ diffuse, layers: 'specular' }, { env })).join(' ')).not.toContain('Lambert');
      }
    },
  );

  it('name the table and the Fresnel form they use: A + B for F = 1, F0·A + B for Schlick', () => {
    const one = approximationNotes(scene({ F: 'one', D: 'beckmann', V: 'cookTorrance' }, { env, ambient: [1, 1, 1] }));
    expect(one[0]).toContain('prefiltered with the Beckmann lobe');
    expect(one[0]).toContain('DFG table of Beckmann with Cook–Torrance (A + B, as F = 1)');
    expect(one[1]).toContain('(A + B, as F = 1)');
    expect(approximationNotes(scene({}, { env }, { env: 'mirror' }))[0]).toContain('Schlick’s F at n·v');
    expect(approximationNotes(scene({ F: 'one' }, { env }, { env: 'mirror' }))[0]).toContain('Mirror: F = 1');
  });
});

describe('the sky environment', () => {
  it(
    'says its sun is enlarged, by the ratio of its radius to the real sun’s ' +
      '(semi-diameter 959.63″ at 1 au, Auwers 1891)',
    () => {
      const radiusDeg = (Math.asin(SUN.sin) * 180) / Math.PI;
      const realDeg = 959.63 / 3600;
      expect(radiusDeg / realDeg).toBeGreaterThan(7); // 7.5: enlarged, which the label has to say
      expect(ENVIRONMENTS.sky).toContain(
        `enlarged sun (${radiusDeg.toFixed(0)}°, the real one ${realDeg.toFixed(2)}°)`,
      );
    },
  );
});

describe('material lab: multiple-scattering compensation notes', () => {
  it(
    'say nothing without compensation; name the method, ' +
      "the split sum's irradiance form, the mirror's lack of one, and foreign D/V",
    () => {
      expect(approximationNotes(scene({ compensation: 'none' }, { env })).join(' ')).not.toContain(
        'Multiple scattering',
      );
      const kc = approximationNotes(scene({ compensation: 'kullaConty' }, { env })).join(' ');
      expect(kc).toContain('Kulla & Conty’s lobe');
      expect(kc).toContain('multiplies the irradiance');
      const mirror = approximationNotes(
        scene({ compensation: 'turquin', D: 'beckmann' }, { env }, { env: 'mirror' }),
      ).join(' ');
      expect(mirror).toContain('The mirror method has no form for it');
      expect(mirror).toContain('stand in for Beckmann');
    },
  );
});
