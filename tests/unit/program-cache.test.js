import { describe, expect, it } from 'vitest';
import { createProgramCache, definesKey } from '../../src/core/gpu/program-cache.js';

describe('program cache', () => {
  it('makes one program per set of switches, whatever order they are written in', () => {
    const made = [];
    const cache = createProgramCache((defines) => {
      made.push(defines);
      return { defines, dispose() {} };
    });
    const a = cache.get({ NDF_GGX: 1, F_ONE: true });
    expect(cache.get({ F_ONE: true, NDF_GGX: 1 })).toBe(a);
    expect(cache.get({ NDF_BECKMANN: 1, F_ONE: true })).not.toBe(a);
    expect(made).toHaveLength(2);
    expect(cache.has({ F_ONE: true, NDF_GGX: 1 })).toBe(true);
    expect(cache.size).toBe(2);
  });

  it('tells switches with different values apart, and disposes of everything it made', () => {
    expect(definesKey({ N: 4 })).not.toBe(definesKey({ N: 8 }));
    let disposed = 0;
    const cache = createProgramCache(() => ({ dispose: () => disposed++ }));
    cache.get({ A: 1 });
    cache.get({ B: 1 });
    cache.dispose();
    expect(disposed).toBe(2);
    expect(cache.size).toBe(0);
  });
});
