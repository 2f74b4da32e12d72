// The value rules of the browser fuzz (tests/browser/fuzz.test.js), checked in Node on the functions the embed calls:
// a link's query through coerceState, a parent's `set` through what the embed replies (the widget's coerceState
// notices, then unknownKeys) and the state coerceState keeps. The browser fuzz sends fewer of them and checks what
// only a page shows: notices, replies over postMessage from another origin, nothing injected, the picture kept.
// Rules: tests/support/hostile-values.js.
import { describe, expect, it } from 'vitest';
import { unknownKeys } from '../../src/core/framework/embed-protocol.js';
import { coerceState, defaultState, paramsToObject } from '../../src/core/framework/state.js';
import { WIDGETS } from '../../src/widgets/registry.js';
import {
  encodeNumbers,
  hostileQuery,
  prototypeNames,
  refusedPartial,
  seededRandom,
  stateProblems,
} from '../support/hostile-values.js';

const SEED = 17;
const SETS_PER_WIDGET = 200;
const schemas = Object.fromEntries(
  await Promise.all(Object.entries(WIDGETS).map(async ([n, w]) => [n, (await w.load()).widget.schema])),
);

describe('fuzz rules in Node: every widget, a hostile link and hostile `set`s', () => {
  for (const [name, schema] of Object.entries(schemas)) {
    const labelOf = (k) => schema[k].label ?? k;
    it(`${name}: a link refusing every field names each in a notice and keeps the defaults`, () => {
      const query = hostileQuery(schema, seededRandom(SEED + name.length * 101 + name.charCodeAt(0)));
      const { state, notices } = coerceState(schema, paramsToObject(query));
      for (const key of Object.keys(schema))
        expect(notices.join('\n'), `URL ${key}=${query.get(key).slice(0, 40)}`).toContain(`${labelOf(key)}:`);
      expect(state).toEqual(defaultState(schema));
      expect(stateProblems(schema, state)).toEqual([]);
    });

    it(`${name}: ${SETS_PER_WIDGET} sets of refused values get an error naming each key, and move nothing`, () => {
      const random = seededRandom(SEED * 31 + name.length);
      const before = prototypeNames();
      const current = defaultState(schema);
      for (let i = 0; i < SETS_PER_WIDGET; i++) {
        const partial = refusedPartial(schema, random, i % 2 === 0);
        const { state, notices } = coerceState(schema, partial, current);
        const errors = [...notices, ...unknownKeys(schema, partial)].join('\n');
        const unknown = Object.keys(partial).filter((k) => !Object.hasOwn(schema, k));
        for (const key of Object.keys(partial).filter((k) => Object.hasOwn(schema, k)))
          expect(errors, `${encodeNumbers(partial).slice(0, 200)}: ${key}`).toContain(`${labelOf(key)}:`);
        // one notice names the first four unknown keys and counts the rest
        for (const key of unknown.slice(0, 4)) expect(errors).toContain(`“${key.slice(0, 20)}`);
        if (unknown.length) expect(errors).toMatch(/(is not a setting|are not settings) of this widget/);
        expect(state).toEqual(current);
      }
      expect(prototypeNames()).toBe(before);
    });
  }
});
