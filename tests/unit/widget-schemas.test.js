// Every registered widget mounts with the schema its folder's schema.js exports (docs/architecture.md: a widget's
// state fields live there), the very object: tests/browser/fuzz.test.js builds its hostile values from those files
// alone, without loading each widget's views (three.js and all) into Node.
import { describe, expect, it } from 'vitest';
import { WIDGETS } from '../../src/widgets/registry.js';

describe("each widget's schema is its schema.js", () => {
  for (const [name, entry] of Object.entries(WIDGETS)) {
    it(`${name}: the schema it mounts with is src/widgets/${name}/schema.js's export`, async () => {
      const [{ widget }, { schema }] = await Promise.all([entry.load(), import(`../../src/widgets/${name}/schema.js`)]);
      expect(widget.name).toBe(name);
      expect(schema).toBeTypeOf('object');
      expect(widget.schema).toBe(schema);
    });
  }
});
