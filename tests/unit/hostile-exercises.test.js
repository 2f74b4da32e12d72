// Hostile exercise files and links: names of inherited properties wherever a file selects something, nested
// lists, a set too large to read, a malformed #hash. Each is refused in words; nothing throws.
import { describe, expect, it, vi } from 'vitest';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { validateExercise } from '../../src/exercises/validate.js';
import {
  MAX_SET_BYTES,
  MAX_SET_ENTRIES,
  fetchJson,
  readExerciseFile,
  readExerciseSet,
} from '../../src/exercises/load.js';
import { GRADERS } from '../../src/exercises/graders.js';
import { isOption } from '../../src/core/framework/state.js';
import { hashId } from '../../src/core/framework/url-hash.js';
import { WIDGETS } from '../../src/widgets/registry.js';
import { PROTOTYPE_NAMES, prototypeNames } from '../support/hostile-values.js';

const DIR = join(import.meta.dirname, '../../public/exercises');
const schemaOf = async (name) => (Object.hasOwn(WIDGETS, name) ? (await WIDGETS[name].load()).widget.schema : null);
const file = (name) => JSON.parse(readFileSync(join(DIR, name), 'utf8'));
const errorsOf = async (raw) => (await validateExercise(raw, { schemaOf })).errors;

describe('an exercise file that names inherited properties', () => {
  it(
    'is refused wherever it selects something: widget, grader, chapter, ' + 'state key and value, params, locked',
    async () => {
      const before = prototypeNames();
      for (const name of PROTOTYPE_NAMES) {
        const good = file('water-red-depth.json');
        const variants = [
          { widget: name },
          { grader: name },
          { chapter: name },
          { state: { ...good.state, medium: name } },
          { params: { channel: name } },
          { locked: [name] },
          { state: JSON.parse(`{"${name}": 1}`) },
          { params: JSON.parse(`{"${name}": 1}`) },
        ];
        for (const change of variants) {
          const errors = await errorsOf({ ...good, ...change });
          expect(errors.length, `${name}: ${JSON.stringify(change)}`).toBeGreaterThan(0);
          expect(errors.join(' ')).toContain(name);
        }
      }
      expect(prototypeNames()).toBe(before);
    },
  );

  it('a list item that is not a string is refused even when it would print as an option ([["water"]])', async () => {
    const worst = file('schlick-worst.json');
    expect(worst.widget).toBe('fresnel-curves');
    const errors = await errorsOf({ ...worst, state: { ...worst.state, materials: [['water']] } });
    expect(errors).toEqual([
      'state.materials: ["water"] not among gold, silver, copper, iron, aluminum, water, ' +
        'glass-low, plastic-high, glass-high, diamond, manual',
    ]);
  });

  it('a choice answer counts only when it is one of the grader’s own choices (ndf-profile)', () => {
    const choices = GRADERS['ndf-profile'].answer.choices({});
    expect(isOption(choices, 'ggx')).toBe(true);
    for (const name of PROTOTYPE_NAMES) expect(isOption(choices, name)).toBe(false);
  });
});

describe('an exercise set too large to read', () => {
  const big = new Uint8Array(MAX_SET_BYTES + 1).fill(32);
  const respond = (body, headers = {}) => vi.fn(async () => new Response(body, { headers }));

  it('is refused from a Content-Length that claims gigabytes, without reading the body', async () => {
    const body = new ReadableStream({
      pull: () => {
        throw new Error('the body was read');
      },
    });
    vi.stubGlobal('fetch', respond(body, { 'content-length': String(5 * 2 ** 30) }));
    expect(await fetchJson('https://x.example/set.json')).toEqual({
      error: 'is 5,368,709,120 bytes; the limit is 1,048,576 bytes (1 MB)',
    });
    vi.unstubAllGlobals();
  });

  it('is refused when the body runs past 1 MB with no length given (the read stops there)', async () => {
    vi.stubGlobal('fetch', respond(new Blob([big]).stream()));
    expect(await fetchJson('https://x.example/set.json')).toEqual({
      error: 'is larger than the limit of 1,048,576 bytes (1 MB)',
    });
    vi.unstubAllGlobals();
  });

  it('a dropped file over the limit is refused by its size; an empty or truncated one is not valid JSON', async () => {
    const refuse = async (name, bytes) =>
      (await readExerciseFile(new File([bytes], name), { schemaOf })).problems[0].errors[0];
    expect(await refuse('big.json', big)).toBe('big.json is 1,048,577 bytes; the limit is 1,048,576 bytes (1 MB)');
    expect(await refuse('empty.json', '')).toMatch(/^empty\.json is not valid JSON/);
    const text = readFileSync(join(DIR, 'red-zone.json'), 'utf8');
    expect(await refuse('cut.json', text.slice(0, text.length / 2))).toMatch(/^cut\.json is not valid JSON/);
    expect(await refuse('magic.json', '\x89PNG\r\n\x1a\n')).toMatch(/^magic\.json is not valid JSON/);
  });

  it(`a set listing more than ${MAX_SET_ENTRIES} exercises is refused as a whole`, async () => {
    const { exercises, problems } = await readExerciseSet(Array(MAX_SET_ENTRIES + 1).fill({}), {
      source: 'many.json',
      schemaOf,
    });
    expect(exercises).toEqual([]);
    expect(problems).toEqual([
      {
        source: 'many.json',
        errors: [`many.json lists ${MAX_SET_ENTRIES + 1} exercises; a set holds at most ${MAX_SET_ENTRIES}`],
      },
    ]);
  });
});

describe('a link’s #hash', () => {
  it('is decoded, and a malformed escape is kept as written instead of throwing (decodeURIComponent would)', () => {
    expect(hashId('#red%20zone')).toBe('red zone');
    expect(() => decodeURIComponent('%E0%A4%A')).toThrow(URIError);
    expect(hashId('#%E0%A4%A')).toBe('%E0%A4%A');
    expect(hashId('')).toBe('');
  });
});
