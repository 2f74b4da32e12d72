import { describe, expect, it } from 'vitest';
import { createProgramCache, definesKey, programKey } from '../../src/core/gpu/program-cache.js';

describe('program cache', () => {
  it('makes one program per set of switches, whatever order they are written in', () => {
    const made = [];
    const cache = createProgramCache((defines) => {
      made.push(defines);
      return { defines, dispose() {} };
    });
    const a = cache.get({ NDF_GGX: 1, F_ONE: 1 });
    expect(cache.get({ F_ONE: 1, NDF_GGX: 1 })).toBe(a);
    expect(cache.get({ NDF_BECKMANN: 1, F_ONE: 1 })).not.toBe(a);
    expect(made).toHaveLength(2);
    expect(cache.has({ F_ONE: 1, NDF_GGX: 1 })).toBe(true);
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

  it('keys a program with chunks of its own by their name too, and lets go only of those keepOnly refuses', () => {
    const disposed = [];
    const cache = createProgramCache((defines, own) => ({ own, dispose: () => disposed.push(own?.key ?? 'app') }));
    const app = cache.get({ NDF_GGX: 1 });
    const mine = cache.get({ NDF_GGX: 1 }, { key: 'code A' });
    expect(mine).not.toBe(app);
    expect(mine.own.key).toBe('code A');
    expect(cache.get({ NDF_GGX: 1 }, { key: 'code A' })).toBe(mine);
    cache.get({ NDF_GGX: 1 }, { key: 'code B' });
    cache.keepOnly((key) => key === programKey({ NDF_GGX: 1 }, { key: 'code B' }));
    expect(disposed).toEqual(['code A']); // the app's own program is never let go by keepOnly
    expect([cache.has({ NDF_GGX: 1 }), cache.has({ NDF_GGX: 1 }, { key: 'code A' }), cache.size]).toEqual([
      true,
      false,
      2,
    ]);
  });
});
