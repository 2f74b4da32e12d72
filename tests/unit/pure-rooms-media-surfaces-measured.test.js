// The pure rooms of the media, subsurface-scale, surfaces and measured-brdf widgets (schema, model, words) load
// in Node with three.js and the DOM out of reach: importing 'three' here throws, and Node has no document.
import { describe, expect, it, vi } from 'vitest';

vi.mock('three', () => {
  throw new Error('three.js imported by a pure room');
});

const ROOMS = {
  media: ['schema', 'model', 'words'],
  'subsurface-scale': ['schema', 'model', 'words'],
  surfaces: ['schema', 'model', 'words'],
  'measured-brdf': ['schema', 'model', 'words'],
};

describe('pure widget rooms load in Node without three.js or the DOM', () => {
  for (const [widget, rooms] of Object.entries(ROOMS)) {
    it(`${widget}: ${rooms.join(', ')}`, async () => {
      expect(globalThis.document).toBeUndefined();
      for (const room of rooms) await import(`../../src/widgets/${widget}/${room}.js`);
      const { schema } = await import(`../../src/widgets/${widget}/schema.js`);
      expect(Object.keys(schema).length).toBeGreaterThan(0);
    });
  }

  it('the mock bites: three.js itself, and a view that draws with it, do not load', async () => {
    await expect(import('three')).rejects.toThrow(/mock/);
    await expect(import('../../src/widgets/media/glasses-view.js')).rejects.toThrow(/mock/);
  });
});
