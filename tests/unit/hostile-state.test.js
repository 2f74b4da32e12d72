// Hostile values through the one coercion function (src/core/framework/state.js) and the embed protocol's checks:
// one test per class of crash seen (an enum or list value naming an inherited property, numbers that are not plain
// decimals), then a seeded fuzz of every registered widget's schema against the rules in
// tests/support/hostile-values.js.
import { describe, expect, it } from 'vitest';
import { coerceState, defaultState } from '../../src/core/framework/state.js';
import { parseMessage, unknownKeys } from '../../src/core/framework/embed-protocol.js';
import { WIDGETS } from '../../src/widgets/registry.js';
import {
  NUMBERS,
  NUMBER_TEXTS,
  PROTOTYPE_NAMES,
  hostilePartial,
  isClean,
  prototypeNames,
  seededRandom,
  stateProblems,
} from '../support/hostile-values.js';

const schemas = Object.fromEntries(
  await Promise.all(Object.entries(WIDGETS).map(async ([name, w]) => [name, (await w.load()).widget.schema])),
);
const fieldsOf = (type) =>
  Object.entries(schemas).flatMap(([w, s]) =>
    Object.entries(s)
      .filter(([, f]) => f.type === type)
      .map(([k, f]) => [w, k, f]),
  );

describe(
  'an enum or list value naming an inherited property is refused (the ' + 'brdf-lobe, visibility and zones crashes)',
  () => {
    it('every enum field of every widget keeps its value for __proto__, constructor, toString, … and says so', () => {
      for (const [widget, key] of fieldsOf('enum')) {
        const base = defaultState(schemas[widget]);
        for (const name of PROTOTYPE_NAMES) {
          const { state, notices } = coerceState(schemas[widget], { [key]: name }, base);
          expect(state[key], `${widget}.${key}=${name}`).toBe(base[key]);
          expect(notices.join(' ')).toContain(`"${name}" is not one of`);
        }
      }
      // the three links of the issue
      expect(coerceState(schemas['brdf-lobe'], { F: '__proto__' }).state.F).toBe('schlick');
      expect(coerceState(schemas['fresnel-zones'], { shape: '__proto__' }).state.shape).toBe('sphere');
    });

    it('every list field drops inherited names, keeps its own options, and refuses a list of nothing else', () => {
      for (const [widget, key, f] of fieldsOf('set')) {
        const base = defaultState(schemas[widget]);
        const first = Object.keys(f.options)[0];
        const only = coerceState(schemas[widget], { [key]: PROTOTYPE_NAMES.join(',') }, base);
        expect(only.state[key], `${widget}.${key}`).toEqual(base[key]);
        expect(only.notices[0]).toMatch(/not recognised/);
        const mixed = coerceState(schemas[widget], { [key]: [first, '__proto__', first, 'constructor'] }, base);
        expect(mixed.state[key]).toEqual([first]);
        expect(mixed.notices[0]).toMatch(/ignored unknown "__proto__", "constructor"/);
      }
      const terms = coerceState(schemas['visibility-explorer'], { terms: '__proto__' });
      expect(terms.state.terms).toEqual(defaultState(schemas['visibility-explorer']).terms);
    });
  },
);

describe('a number that is not a plain decimal is refused, whether text (URL) or typed (postMessage)', () => {
  const schema = { a: { type: 'number', min: -1, max: 1, default: 0.5, label: 'A' } };
  it('NaN, ±Infinity, 1e309, hex, binary, octal, Arabic-Indic and full-width digits keep the last good value', () => {
    for (const raw of [...NUMBER_TEXTS, NaN, Infinity, -Infinity]) {
      const { state, notices } = coerceState(schema, { a: raw }, { a: 0.25 });
      expect(state.a, String(raw)).toBe(0.25);
      expect(notices[0]).toMatch(/^A: .* is not a (decimal|finite) number; kept 0\.25\.$/);
    }
  });
  it(
    'decimals are taken as written (ECMAScript Number of the text), ' + 'clamped to the range, and −0 is stored as 0',
    () => {
      expect(coerceState(schema, { a: ' .5 ' }).state.a).toBe(0.5);
      expect(coerceState(schema, { a: '-1e-3' }).state.a).toBe(-0.001);
      expect(coerceState(schema, { a: '+7' })).toEqual({
        state: { a: 1 },
        notices: ['A: 7 is outside -1…1; clamped to 1.'],
      });
      expect(Object.is(coerceState(schema, { a: '-0' }).state.a, 0)).toBe(true);
      expect(Object.is(coerceState(schema, { a: -0 }).state.a, 0)).toBe(true);
    },
  );
  it('a value echoed in a notice is cut to 60 characters and its length given (a 5,000-character string)', () => {
    const { notices } = coerceState(schema, { a: 'x'.repeat(5000) });
    expect(notices[0].length).toBeLessThan(200);
    expect(notices[0]).toContain('(5002 characters)');
  });
});

describe('a message whose state carries a prototype key (as JSON.parse makes it)', () => {
  it('is reported as an unknown setting and changes neither the state nor Object.prototype', () => {
    const before = prototypeNames();
    const msg = parseMessage(
      JSON.parse('{"type":"shading-lab:set","state":{"__proto__":{"polluted":1},"mode":"zones-lh"}}'),
    );
    const schema = schemas['fresnel-zones'];
    const { state } = coerceState(schema, msg.state);
    expect(state.mode).toBe('zones-lh');
    expect(unknownKeys(schema, msg.state)[0]).toMatch(/“__proto__” is not a setting/);
    expect({}.polluted).toBeUndefined();
    expect(prototypeNames()).toBe(before);
  });
});

describe('seeded fuzz of the coercion over every registered widget', () => {
  it(
    'never throws; every value stays one the field may hold; ' + 'a notice names each field given a value it refused',
    () => {
      const random = seededRandom(17);
      const before = prototypeNames();
      let tried = 0;
      let refused = 0;
      for (const [widget, schema] of Object.entries(schemas)) {
        let state = defaultState(schema);
        for (let i = 0; i < 400; i++) {
          const partial = hostilePartial(schema, random, i % 2 === 0);
          const next = coerceState(schema, partial, state);
          tried++;
          expect(stateProblems(schema, next.state), `${widget} after ${JSON.stringify(partial).slice(0, 200)}`).toEqual(
            [],
          );
          for (const [key, raw] of Object.entries(partial)) {
            if (!Object.hasOwn(schema, key)) continue;
            const label = schema[key].label ?? key;
            const named = next.notices.some((n) => n.startsWith(`${label}:`));
            expect(named, `${widget}.${key} = ${String(raw).slice(0, 40)}`).toBe(!isClean(schema[key], raw));
            if (named) refused++;
          }
          state = next.state;
        }
      }
      expect(prototypeNames()).toBe(before);
      expect({}.pwned).toBeUndefined();
      console.log(
        `coercion fuzz: ${Object.keys(schemas).length} widgets, ${tried} partial states, ${refused} refusals reported`,
      );
      expect(refused).toBeGreaterThan(tried / 2);
    },
  );

  it('typed numbers from postMessage: NaN, ±Infinity, MAX_VALUE, −0, 5e-324 end finite and in range', () => {
    for (const [widget, key, f] of fieldsOf('number')) {
      for (const x of NUMBERS) {
        const v = coerceState(schemas[widget], { [key]: x }).state[key];
        expect(Number.isFinite(v) && v >= f.min && v <= f.max && !Object.is(v, -0), `${widget}.${key} ← ${x}`).toBe(
          true,
        );
      }
    }
  });
});
