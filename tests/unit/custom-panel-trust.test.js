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

  it('the hash is cyrb53 (bryc 2018; its published values for "a", "b", "revenge", "revenue")', () => {
    const published = {
      a: 7929297801672961,
      b: 8684336938537663,
      revenge: 4051478007546757,
      revenue: 8309097637345594,
    };
    for (const [text, value] of Object.entries(published)) expect(parseInt(codeHash(text), 36)).toBe(value);
  });
});
