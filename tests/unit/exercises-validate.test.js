// The exercise format: every shipped file is valid, and each kind of mistake gets its exact message.
import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { validateExercise } from '../../src/exercises/validate.js';
import { readExerciseSet } from '../../src/exercises/load.js';
import { createProgress } from '../../src/exercises/progress.js';
import { parseNumberAnswer } from '../../src/exercises/answer.js';
import { WIDGETS } from '../../src/widgets/registry.js';

const DIR = join(import.meta.dirname, '../../public/exercises');
const schemaOf = async (name) => (Object.hasOwn(WIDGETS, name) ? (await WIDGETS[name].load()).widget.schema : null);
const fromDisk = async (url) => ({ json: JSON.parse(readFileSync(join(DIR, url.split('/').pop()), 'utf8')) });
const good = () => JSON.parse(readFileSync(join(DIR, 'water-red-depth.json'), 'utf8'));
const errorsOf = async (raw) => (await validateExercise(raw, { schemaOf })).errors;

describe('shipped exercises', () => {
  it('the index loads twenty-seven valid exercises (sixteen widget, eleven shader) over nine chapters', async () => {
    const index = JSON.parse(readFileSync(join(DIR, 'index.json'), 'utf8'));
    const { exercises, problems } = await readExerciseSet(index, {
      source: 'index.json',
      baseUrl: 'http://x/exercises/index.json',
      schemaOf,
      load: fromDisk,
    });
    expect(problems).toEqual([]);
    expect(exercises).toHaveLength(27);
    expect(new Set(exercises.map((e) => e.chapter))).toEqual(
      new Set(['media', 'surfaces', 'brdf', 'microfacets', 'fresnel', 'ndf', 'visibility', 'diffuse', 'today']),
    );
  });

  it('fills in the defaults of optional params', async () => {
    const { exercise } = await validateExercise({ ...good(), params: { channel: 'g' } }, { schemaOf });
    expect(exercise.params).toEqual({ channel: 'g', threshold: 0.01 });
  });
});

describe('validator messages', () => {
  const cases = [
    ['not an object', [], ['the exercise is not a JSON object']],
    ['unknown widget', { widget: 'banana', locked: [], state: {} }, ['widget: unknown widget "banana"']],
    [
      'unknown state key',
      { state: { depth: 3 } },
      ['state.depth: unknown key for widget "media" (keys: view, medium, distance, samples)'],
    ],
    [
      'state value out of range',
      { state: { medium: 'water', view: 'one', distance: 5 } },
      ['state.distance: 5 is outside -3…2'],
    ],
    [
      'state value of the wrong type',
      { state: { medium: 'water', view: 'one', distance: '1' } },
      ['state.distance: "1" is not a number'],
    ],
    [
      'enum value unknown',
      { state: { medium: 'beer', view: 'one' } },
      ['state.medium: "beer" is not one of water, red, cloudy, milk'],
    ],
    ['locked key unknown', { locked: ['medium', 'colour'] }, ['locked: "colour" is not a state key of widget "media"']],
    ['missing tolerance', { tolerance: undefined }, ['tolerance: missing (a positive number)']],
    ['negative tolerance', { tolerance: -1 }, ['tolerance: -1 is not a positive number']],
    [
      'unknown grader',
      { grader: 'guess' },
      [
        'grader: unknown grader "guess" (graders: transmittance-depth, fresnel-reflectance-angle, ' +
          'sphere-match, smith-g1, albedo-loss, multiple-scattering-gain, light-zone, ' +
          'schlick-worst-angle, ndf-profile, visibility-ratio, lambert-radiance, f82-schlick-gap, ' +
          'highlight-stretch, aniso-pair, openpbr-layer)',
      ],
    ],
    [
      'unknown param',
      { params: { channel: 'r', depth: 3 } },
      ['params.depth: unknown for grader "transmittance-depth" (params: channel, threshold)'],
    ],
    ['param out of range', { params: { threshold: 2 } }, ['params.threshold: 2 is outside 0.000001…0.99']],
    [
      'unknown chapter',
      { chapter: 'optics' },
      [
        'chapter: "optics" is not a chapter (chapters: media, surfaces, brdf, microfacets, ' +
          'fresnel, ndf, visibility, diffuse, rendering, today, performance)',
      ],
    ],
    ['bad id', { id: 'Red Depth' }, ['id: "Red Depth" is not a name of lower-case letters, digits and dashes']],
    ['missing prompt', { prompt: '' }, ['prompt: missing (a non-empty string)']],
    [
      'unknown field',
      { answer: 14 },
      [
        'answer: unknown field (fields: id, chapter, title, prompt, widget, state, locked, grader, params, ' +
          'tolerance, points)',
      ],
    ],
  ];
  for (const [what, change, expected] of cases) {
    it(what, async () => {
      const raw = Array.isArray(change) ? change : { ...good(), ...change };
      for (const [k, v] of Object.entries(change)) if (v === undefined) delete raw[k];
      expect(await errorsOf(raw)).toEqual(expected);
    });
  }

  it('checks a colour field of the widget', async () => {
    const lambert = JSON.parse(readFileSync(join(DIR, 'lambert-brightness.json'), 'utf8'));
    expect(await errorsOf({ ...lambert, state: { ...lambert.state, cdiff: 'white' } })).toEqual([
      'state.cdiff: "white" is not a colour like "#rrggbb"',
    ]);
  });

  it('names what a grader needs of the widget', async () => {
    const sphere = JSON.parse(readFileSync(join(DIR, 'match-sphere.json'), 'utf8'));
    expect(await errorsOf({ ...sphere, locked: ['D', 'V', 'F', 'alpha'] })).toEqual([
      'locked: "alpha" is what the student sets for grader "sphere-match"; it must stay free',
    ]);
    expect(await errorsOf({ ...sphere, state: { ...sphere.state, D: 'beckmann' } })).toEqual([
      'state.D: grader "sphere-match" needs "ggx", got "beckmann"',
    ]);
    expect(await errorsOf({ ...sphere, locked: ['D', 'V'] })).toEqual([
      'locked: must include "F" (grader "sphere-match" assumes F = "schlick")',
    ]);
    expect(await errorsOf({ ...sphere, params: { f0: 0.5 } })).toEqual([
      'params.alpha: missing (required by grader "sphere-match")',
    ]);
    expect(await errorsOf({ ...sphere, widget: 'media', state: {}, locked: [] })).toEqual([
      'widget: grader "sphere-match" reads the "brdf-lobe" widget, not "media"',
    ]);
    const ndf = JSON.parse(readFileSync(join(DIR, 'which-ndf.json'), 'utf8'));
    const twins = await errorsOf({ ...ndf, state: { hwhm: 5 }, params: { ...ndf.params, hwhm: 5 }, tolerance: 1.3 });
    expect(twins).toHaveLength(2); // each of the pair accepts the other
    expect(twins[0]).toMatch(
      new RegExp(
        '^params: at a half width of 5° Blinn–Phong is within 1\\.1\\d*× of Beckmann, ' +
          'inside the tolerance 1\\.3: two answers would be right$',
      ),
    );
    const schlick = JSON.parse(readFileSync(join(DIR, 'schlick-worst.json'), 'utf8'));
    expect(await errorsOf({ ...schlick, locked: ['materials'] })).toEqual([
      'locked: must include "ior" (grader "schlick-worst-angle" takes the question from it)',
    ]);
  });

  it('a set reports bad JSON, missing files and duplicate ids by source, and keeps the good ones', async () => {
    const load = async (url) => {
      if (url.endsWith('missing.json')) return { error: 'could not be loaded (HTTP 404)' };
      return fromDisk(url);
    };
    const index = {
      exercises: [
        'water-red-depth.json',
        'missing.json',
        'water-red-depth.json',
        { ...good(), id: 'other', widget: 'nope' },
      ],
    };
    const { exercises, problems } = await readExerciseSet(index, {
      source: 'mine.json',
      baseUrl: 'http://x/mine.json',
      schemaOf,
      load,
    });
    expect(exercises.map((e) => e.id)).toEqual(['water-red-depth']);
    expect(problems).toEqual([
      { source: 'missing.json', errors: ['missing.json could not be loaded (HTTP 404)'] },
      { source: 'water-red-depth.json', errors: ['id: "water-red-depth" is already used by water-red-depth.json'] },
      { source: 'mine.json #4', errors: ['widget: unknown widget "nope"'] },
    ]);
  });
});

describe('progress', () => {
  const memory = () => {
    const m = new Map();
    return { getItem: (k) => m.get(k) ?? null, setItem: (k, v) => m.set(k, v), removeItem: (k) => m.delete(k) };
  };
  it('counts attempts, keeps solved, survives a new session and resets', () => {
    const storage = memory();
    const p = createProgress(storage);
    p.record('a', false);
    p.record('a', true);
    p.record('a', false);
    expect(createProgress(storage).of('a')).toEqual({ solved: true, attempts: 3 });
    p.reset();
    expect(createProgress(storage).of('a')).toEqual({ solved: false, attempts: 0 });
  });
  it('reads no inherited entry: an id named like an Object.prototype property has no progress', () => {
    Object.defineProperty(Object.prototype, 'planted', { value: { solved: true, attempts: 5 }, configurable: true });
    try {
      expect(createProgress(memory()).of('planted')).toEqual({ solved: false, attempts: 0 });
    } finally {
      delete Object.prototype.planted;
    }
  });
  it('starts empty from corrupt data', () => {
    const storage = memory();
    storage.setItem('shading-lab.exercises.progress.v1', '{oops');
    expect(createProgress(storage).of('a')).toEqual({ solved: false, attempts: 0 });
  });
});

describe('a typed number answer', () => {
  it('is read as a plain decimal like a state value (Number() would take 0x10 as 16 and 0b11 as 3)', () => {
    expect(parseNumberAnswer('0x10')).toBeNaN();
    expect(parseNumberAnswer('0b11')).toBeNaN();
    expect(parseNumberAnswer('Infinity')).toBeNaN();
    expect(parseNumberAnswer('24,4')).toBe(24.4);
    expect(parseNumberAnswer(' 24.4 ')).toBe(24.4);
    expect(parseNumberAnswer('2.44e1')).toBe(24.4);
  });
});
