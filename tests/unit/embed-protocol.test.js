// The message and origin parsing of the embed protocol: what is accepted, what is ignored, what is reported.
import { describe, expect, it } from 'vitest';
import { parseAllowedOrigins, parseMessage, unknownKeys } from '../../src/core/framework/embed-protocol.js';

const OWN = 'https://lab.example.org';

describe('allowed origins (origins= in the iframe URL)', () => {
  it('defaults to the widget’s own origin only', () => {
    expect(parseAllowedOrigins(null, OWN)).toEqual({ origins: new Set([OWN]), notices: [] });
    expect(parseAllowedOrigins('', OWN).origins).toEqual(new Set([OWN]));
  });

  it('adds each listed origin, normalised, and keeps the own origin', () => {
    const { origins, notices } = parseAllowedOrigins(
      ' https://slides.example.com/ ,http://localhost:8080,HTTPS://Notes.Example.net',
      OWN,
    );
    expect(origins).toEqual(
      new Set([OWN, 'https://slides.example.com', 'http://localhost:8080', 'https://notes.example.net']),
    );
    expect(notices).toEqual([]);
  });

  it('reports and ignores what is not an origin: wildcards, paths, other schemes, garbage', () => {
    const { origins, notices } = parseAllowedOrigins(
      '*,https://a.example/page,file:///x,javascript:alert(1),nonsense,https://ok.example',
      OWN,
    );
    expect(origins).toEqual(new Set([OWN, 'https://ok.example']));
    expect(notices).toHaveLength(5);
    expect(notices[0]).toMatch(/“\*” is not an origin/);
  });
});

describe('messages from the parent', () => {
  it('accepts get and set, with an optional string or number id', () => {
    expect(parseMessage({ type: 'shading-lab:get' })).toEqual({ kind: 'get', id: undefined });
    expect(parseMessage({ type: 'shading-lab:get', id: 7 })).toEqual({ kind: 'get', id: 7 });
    expect(parseMessage({ type: 'shading-lab:set', id: 'a', state: { alpha: 0.5 } })).toEqual({
      kind: 'set',
      id: 'a',
      state: { alpha: 0.5 },
    });
  });

  it('returns null for every other shape', () => {
    const bad = [
      null,
      undefined,
      'shading-lab:get',
      42,
      [],
      [{ type: 'shading-lab:get' }],
      {},
      { type: 'get' },
      { type: 'shading-lab:unknown' },
      { type: 'shading-lab:state', state: {} },
      { type: 'shading-lab:set' },
      { type: 'shading-lab:set', state: null },
      { type: 'shading-lab:set', state: [1] },
      { type: 'shading-lab:set', state: 'alpha=0.5' },
      { type: 'shading-lab:get', id: {} },
      { type: 'shading-lab:get', id: NaN },
      { type: 'shading-lab:get', id: 'x'.repeat(201) },
      Object.assign(Object.create({ type: 'shading-lab:get' })),
      new Date(),
    ];
    for (const data of bad) expect(parseMessage(data), JSON.stringify(data)).toBeNull();
  });
});

describe('a state sent by message', () => {
  const schema = {
    alpha: { type: 'number', min: 0.01, max: 1, default: 0.3, label: 'α' },
    mode: { type: 'enum', options: { a: 'A', b: 'B' }, default: 'a', label: 'Mode' },
  };
  it("names the unknown keys (the bad values are the widget's own coercion to report), none for a good state", () => {
    expect(unknownKeys(schema, { alpha: 0.5, mode: 'b' })).toEqual([]);
    const unknown = unknownKeys(schema, { alpha: 7, mode: 'z', colour: 'red' });
    expect(unknown).toHaveLength(1);
    expect(unknown[0]).toMatch(/“colour” is not a setting of this widget \(it has: alpha, mode\)/);
  });

  it('reports 100,000 unknown keys in one notice naming four, not one notice per key (bounded reply)', () => {
    const state = Object.fromEntries(Array.from({ length: 100_000 }, (_, i) => [`k${i}`, i]));
    const unknown = unknownKeys(schema, state);
    expect(unknown).toHaveLength(1);
    expect(unknown[0]).toBe(
      '“k0”, “k1”, “k2”, “k3” and 99996 more are not settings of this widget (it has: alpha, mode); ' + 'ignored.',
    );
  });
});
