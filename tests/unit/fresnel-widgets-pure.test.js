// STYLE.md's widget shape for the Fresnel chapter's widgets and the microsurface: schema.js, model.js and
// words.js load in Node with three.js made unloadable (vi.mock throws) and with no DOM, and the schema the
// registry's widget carries is schema.js's own.
import { describe, expect, it, vi } from 'vitest';

vi.mock('three', () => {
  throw new Error('three.js was loaded');
});

const WIDGETS = ['fresnel-zones', 'microfacets', 'fresnel-curves', 'f0-tables', 'radiance'];
const PURE = ['schema', 'model', 'words'];

describe('the Fresnel widgets’ data and derivations are pure', () => {
  it('has no DOM here to lean on (the test would prove nothing with one)', () => {
    expect(typeof document).toBe('undefined');
  });
  it.each(WIDGETS.flatMap((w) => PURE.map((file) => [w, file])))(
    '%s/%s.js loads without three.js or the DOM',
    async (widget, file) => {
      const mod = await import(`../../src/widgets/${widget}/${file}.js`);
      expect(Object.keys(mod).length).toBeGreaterThan(0);
    },
  );
  it.each(WIDGETS)('%s: schema.js declares a default for every field, within its options or range', async (w) => {
    const { schema } = await import(`../../src/widgets/${w}/schema.js`);
    for (const field of Object.values(schema)) {
      if (field.type === 'enum') expect(Object.keys(field.options)).toContain(field.default);
      if (field.type === 'set') field.default.forEach((d) => expect(Object.keys(field.options)).toContain(d));
      if (field.type === 'number') expect(field.default).toBeGreaterThanOrEqual(field.min);
      if (field.type === 'number') expect(field.default).toBeLessThanOrEqual(field.max);
    }
  });
});
