// The author page's pure parts and the set format they write: points per exercise and the index's title and pass
// mark in the validator's message format; the score weighed by points (a hand-summed share); the form's reading of
// typed text (kept as typed when it is no number, for the validator to name); where each message is shown; the
// widget state kept; a new exercise of every kind, once its words are filled in, passes the validator; the
// progress file's round trip and the lecturer's view of it.
import { describe, expect, it } from 'vitest';
import { validateExercise, validateSetFields } from '../../src/exercises/validate.js';
import { readExerciseSet } from '../../src/exercises/load.js';
import { createProgress, memoryStorage, progressFile, readProgressFile } from '../../src/exercises/progress.js';
import { scoreOf } from '../../src/exercises/scorm/status.js';
import {
  KINDS,
  compactState,
  fieldFor,
  kindOf,
  newExercise,
  pathOf,
  readNumber,
  readNumberList,
  setPath,
} from '../../src/exercises/author/draft.js';
import { setJson } from '../../src/exercises/author/export.js';
import { WIDGETS } from '../../src/widgets/registry.js';

const schemaOf = async (name) => (Object.hasOwn(WIDGETS, name) ? (await WIDGETS[name].load()).widget.schema : null);
const words = { title: 'T', prompt: 'P', sources: ['Walter et al. 2007'] };

describe('the set format: points and pass mark', () => {
  it('takes points above 0 up to 100 on either kind, 1 when left out, and names a bad one', async () => {
    const one = { ...newExercise('number', 1), title: 'T', prompt: 'P', grader: 'albedo-loss', params: { alpha: 0.5 } };
    expect((await validateExercise(one, { schemaOf })).exercise.points).toBe(1);
    expect((await validateExercise({ ...one, points: 2.5 }, { schemaOf })).exercise.points).toBe(2.5);
    for (const bad of [0, -1, 101, '2'])
      expect((await validateExercise({ ...one, points: bad }, { schemaOf })).errors).toEqual([
        `points: ${JSON.stringify(bad)} is not a number of points above 0 and at most 100`,
      ]);
    const shader = { ...newExercise('shader', 2), ...words, points: 3 };
    expect((await validateExercise(shader, { schemaOf })).exercise.points).toBe(3);
  });
  it('checks an index’s title and passMark in the validator’s format, through the loader too', async () => {
    expect(validateSetFields({ title: ' Week 3 ', passMark: 60, exercises: [] })).toEqual({
      title: 'Week 3',
      passMark: 60,
      errors: [],
    });
    expect(validateSetFields({ title: 3, passMark: 120, pass: 1, exercises: [] }).errors).toEqual([
      'pass: unknown field of a set (fields: title, passMark, exercises)',
      'title: 3 is not a non-empty string',
      'passMark: 120 is not a percentage 0…100',
    ]);
    expect(validateSetFields([{ id: 'x' }]).errors).toEqual([]); // a plain list has no fields of its own
    const got = await readExerciseSet({ passMark: '80', exercises: [] }, { source: 'set.json', schemaOf });
    expect(got.problems).toEqual([{ source: 'set.json', errors: ['passMark: "80" is not a percentage 0…100'] }]);
  });
  it('scores the share of points solved: 1 + 3 of 1 + 2 + 3 + 1 points is 57.14%', () => {
    const ids = ['a', 'b', 'c', 'd'];
    const progress = { a: { solved: true, attempts: 1 }, b: { solved: false, attempts: 2 }, c: { solved: true } };
    expect(scoreOf(ids, progress, { b: 2, c: 3 })).toEqual({ solved: 2, attempted: 3, total: 4, raw: 57.14 });
    expect(scoreOf(ids, progress).raw).toBe(50); // without points, each counts 1
  });
});

describe('the author form’s reading', () => {
  it('reads numbers as typed, with a decimal comma, and keeps what is no number for the validator', () => {
    expect(['0,5', ' 2 ', '1e-3', '', 'abc', '1.2.3'].map(readNumber)).toEqual([
      0.5,
      2,
      0.001,
      undefined,
      'abc',
      '1.2.3',
    ]);
    expect(readNumberList('0.1, 0.5 1; 2')).toEqual([0.1, 0.5, 1, 2]);
    expect(readNumberList('1e-4 x')).toEqual([1e-4, 'x']);
    expect(readNumberList('  ')).toBeUndefined();
    expect(setPath({}, 'domain.nh.range', [0, 1])).toEqual({ domain: { nh: { range: [0, 1] } } });
    expect(setPath({ a: 1 }, 'b', undefined)).toEqual({ a: 1 });
  });
  it('puts a message beside the field it names, else the nearest field enclosing it', () => {
    const paths = ['id', 'state', 'locked', 'params.target', 'domain.nh', 'domain.nh.range'];
    const at = (m) => fieldFor(pathOf(m) ?? '', paths);
    expect(at('params.target: missing (required by grader "smith-g1")')).toBe('params.target');
    expect(at('state.theta: 95 is outside 0…89')).toBe('state');
    expect(at('domain.nh.range: [1, 0] is not [min, max]')).toBe('domain.nh.range');
    expect(at('domain.nh.steps: 500 is not a whole number')).toBe('domain.nh');
    expect(at('locked: must include "material"')).toBe('locked');
    expect(at('my.json is not valid JSON (…)')).toBeNull();
  });
  it('keeps the widget state that differs from its defaults, and every locked value', async () => {
    const schema = await schemaOf('surfaces');
    const state = { material: 'water', theta: 40, alpha: 0.5 };
    expect(compactState(schema, state, ['material'])).toEqual({ material: 'water', alpha: 0.5 });
  });
  it('makes a new exercise of every kind that passes the validator once its words are filled in', async () => {
    for (const kind of Object.keys(KINDS)) {
      const raw = { ...newExercise(kind, 7), ...words };
      if (kind === 'number') raw.params = { channel: 'g' }; // transmittance-depth: every param has a default
      if (kind === 'choice') raw.params = {};
      if (kind === 'state') Object.assign(raw, { params: { target: 0.25 }, locked: ['material'] });
      if (kind !== 'shader') delete raw.sources;
      const { errors } = await validateExercise(raw, { schemaOf });
      expect([kind, errors]).toEqual([kind, []]);
      expect(kindOf(raw)).toBe(kind);
    }
    expect(setJson({ title: undefined, passMark: undefined, exercises: [] })).toEqual({ exercises: [] });
  });
});

describe('the progress file', () => {
  it('saves and loads a student’s progress, takes only this set’s ids, and refuses another file', () => {
    const exercises = [
      { id: 'a', title: 'A', points: 2 },
      { id: 'b', title: 'B', points: 1 },
    ];
    const progress = createProgress(memoryStorage());
    progress.record('a', false, '1');
    progress.record('a', true, '2');
    const file = progressFile({ name: ' Ada ', title: 'Week 3', exercises, progress, saved: new Date(0) });
    const got = readProgressFile(JSON.stringify(file));
    expect(got.file).toEqual({
      name: 'Ada',
      set: 'Week 3',
      saved: '1970-01-01T00:00:00.000Z',
      exercises: [
        { id: 'a', title: 'A', points: 2, solved: true, attempts: 2 },
        { id: 'b', title: 'B', points: 1, solved: false, attempts: 0 },
      ],
    });
    const other = createProgress(memoryStorage());
    expect(other.load(got.file.exercises, ['a'])).toBe(1);
    expect([other.of('a'), other.of('b')]).toEqual([
      { solved: true, attempts: 2 },
      { solved: false, attempts: 0 },
    ]);
    expect(readProgressFile('{"type":"x"}').error).toMatch(/not a Shading Lab progress file/);
    expect(readProgressFile('{').error).toMatch(/not valid JSON/);
    const forged = { ...file, exercises: [{ id: 'a', title: 'A', points: 1, solved: 'yes', attempts: 1 }] };
    expect(readProgressFile(JSON.stringify(forged)).error).toMatch(/not \{ id, title, points, solved, attempts \}/);
  });
});
