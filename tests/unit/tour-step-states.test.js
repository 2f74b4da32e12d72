// Every tour step's state, put through the widget's own schema as a URL or a message would be
// (coerceState, src/core/framework/state.js): each key must be a field of that widget, and each value must come
// out as written, neither clamped, nor refused, nor trimmed. A step whose state the widget would change shows
// another picture than its words describe.
import { describe, expect, it } from 'vitest';
import { TOUR_STEPS } from '../../src/tour/steps.js';
import { WIDGETS } from '../../src/widgets/registry.js';
import { coerceState } from '../../src/core/framework/state.js';

const schemas = Object.fromEntries(
  await Promise.all(
    Object.keys(WIDGETS).map(async (name) => [name, (await import(`../../src/widgets/${name}/schema.js`)).schema]),
  ),
);

describe('tour step states, coerced by the widget schema (coerceState)', () => {
  it.each(TOUR_STEPS.map((s) => [s.id, s]))('%s: known keys, values kept as written', (id, step) => {
    const schema = schemas[step.widget];
    expect(schema, `${id}: widget ${step.widget}`).toBeTruthy();
    const unknown = Object.keys(step.state).filter((key) => !Object.hasOwn(schema, key));
    expect(unknown, `${id}: keys the widget ${step.widget} does not have`).toEqual([]);
    const { state, notices } = coerceState(schema, step.state);
    expect(notices, id).toEqual([]);
    for (const [key, value] of Object.entries(step.state)) expect(state[key], `${id}: ${key}`).toEqual(value);
  });

  it('would catch an unknown key, a clamped number and an unknown option (checked on a copy of a step)', () => {
    const step = TOUR_STEPS.find((s) => s.widget === 'brdf-lobe');
    const schema = schemas['brdf-lobe'];
    expect(Object.hasOwn(schema, 'lightTheeta')).toBe(false);
    expect(coerceState(schema, { lightTheta: 120 }).notices[0]).toMatch(/clamped/);
    expect(coerceState(schema, { ...step.state, D: 'banana' }).notices.length).toBe(1);
  });
});
