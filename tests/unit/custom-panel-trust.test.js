// Which user code runs without a click: the slot's starter, and code typed or accepted in this browser (by hash).
import { describe, expect, it } from 'vitest';
import { codeHash, isTrusted, trustCode } from '../../src/core/custom/custom-panel-trust.js';
import { SLOTS } from '../../src/core/custom/slots.js';

describe('custom code trust', () => {
  it('the starter runs; code never seen waits; once accepted it runs (also without localStorage, as in Node)', () => {
    const code = `${SLOTS.D.starter}// seen once\n`;
    expect(isTrusted(SLOTS.D.starter, SLOTS.D.starter)).toBe(true);
    expect(isTrusted(code, SLOTS.D.starter)).toBe(false);
    trustCode(code);
    expect(isTrusted(code, SLOTS.D.starter)).toBe(true);
    expect(isTrusted(`${code} `, SLOTS.D.starter)).toBe(false); // one more space is other code
  });

  it('hashes differ for texts one character apart (cyrb53 reference values are stable across calls)', () => {
    const hashes = new Set(['a', 'b', 'ab', 'ba', 'return 1.0;', 'return 1.5;'].map(codeHash));
    expect(hashes.size).toBe(6);
    expect(codeHash('return 1.0;')).toBe(codeHash('return 1.0;'));
  });
});
