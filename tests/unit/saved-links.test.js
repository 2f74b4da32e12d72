// Every link saved from the build before one name per idea (b048b6b: tests/support/saved-links.json, made by
// scripts/collect-saved-links.js from that tree) opens the same view in this one: a share link, a chapter page's
// link and an embed `set` of each widget, every field set, and that build's widget exercises. "The same view" is
// the state that build opened the link at, with the renames of tests/support/saved-links.js (not the schemas').
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { coerceState, currentNames, defaultState, stateToParams } from '../../src/core/framework/state.js';
import { widgetParams } from '../../src/core/framework/widget-host.js';
import { unknownKeys } from '../../src/core/framework/embed-protocol.js';
import { validateExercise } from '../../src/exercises/validate.js';
import { WIDGETS } from '../../src/widgets/registry.js';
import { RENAMED_KEYS, SAVED, renamed } from '../support/saved-links.js';

const schemaOf = async (name) => (Object.hasOwn(WIDGETS, name) ? (await WIDGETS[name].load()).widget.schema : null);

/** How this build reads a saved link: the URL's parameters (under the page's prefix) or the `set` message's state. */
function opened(schema, saved) {
  if (saved.form === 'set') return coerceState(schema, saved.message.state);
  const search = saved.link.slice(saved.link.indexOf('?'));
  return coerceState(schema, widgetParams(search, saved.prefix));
}

const OLD_NAMES = new Set(Object.values(RENAMED_KEYS).flatMap(Object.keys));

describe('a link saved from b048b6b opens the same view (state), old key names read as the new ones', () => {
  it('the fixture holds a share link, a page link where a page keeps the state, and a set of every widget', () => {
    const addedSince = ['anisotropic-microsurface']; // widgets added since b048b6b have no links saved from it
    const widgets = Object.keys(WIDGETS)
      .filter((w) => !addedSince.includes(w))
      .toSorted();
    expect([...new Set(SAVED.links.map((l) => l.widget))].toSorted()).toEqual(widgets);
    for (const w of widgets)
      expect(SAVED.links.filter((l) => l.widget === w && l.what === 'every field')).not.toEqual([]);
    const renamedLinks = SAVED.links.filter((l) => RENAMED_KEYS[l.widget] && l.what !== 'defaults');
    expect(renamedLinks.some((l) => /[?&](vis\.)?terms=/.test(l.link ?? ''))).toBe(true);
  });

  for (const saved of SAVED.links) {
    const where = saved.link ?? `set ${Object.keys(saved.message.state).join(',')}`;
    it(`${saved.widget}, ${saved.what}, ${saved.form}: ${where.slice(0, 90)}`, async () => {
      const schema = await schemaOf(saved.widget);
      const { state, notices } = opened(schema, saved);
      expect(notices).toEqual([]);
      const want = renamed(saved.widget, saved.state);
      for (const [k, v] of Object.entries(want)) expect(state[k], k).toEqual(v);
      // a key added since (another branch's control) is at its default
      const base = defaultState(schema);
      for (const k of Object.keys(schema).filter((key) => !(key in want))) expect(state[k], k).toEqual(base[k]);
      if (saved.form === 'set') expect(unknownKeys(schema, saved.message.state)).toEqual([]);
      // and the link this build writes of it says only the new names, and opens at the same state again
      const params = stateToParams(schema, state);
      expect([...params.keys()].filter((k) => OLD_NAMES.has(k) && !Object.hasOwn(schema, k))).toEqual([]);
      expect(coerceState(schema, Object.fromEntries(params)).state).toEqual(state);
    });
  }
});

describe('an exercise file of b048b6b is still valid and fixes the same settings', () => {
  for (const raw of SAVED.exercises) {
    it(`${raw.id} (${raw.widget})`, async () => {
      const { exercise, errors } = await validateExercise(raw, { schemaOf });
      expect(errors).toEqual([]);
      expect(exercise.state).toEqual(renamed(raw.widget, raw.state ?? {}));
      const keys = RENAMED_KEYS[raw.widget] ?? {};
      expect(exercise.locked).toEqual((raw.locked ?? []).map((k) => keys[k] ?? k));
    });
  }
});

describe('where a name is both a field and an old name, the value decides', () => {
  it('material lab: `diffuse` with a colour is the old colour (cdiff), with a term key the new term', async () => {
    const schema = await schemaOf('material-lab');
    expect(coerceState(schema, { diffuse: 'ffffff' }).state).toMatchObject({ cdiff: '#ffffff', diffuse: 'lambert' });
    const both = coerceState(schema, { diffuse: 'orenNayar', cdiff: '#102030', diffuseModel: 'lambert' });
    expect(both).toEqual({ state: expect.objectContaining({ diffuse: 'orenNayar', cdiff: '#102030' }), notices: [] });
    const bad = coerceState(schema, { diffuse: 'chalk' });
    expect(bad.notices).toEqual([expect.stringMatching(/^Diffuse term: "chalk" is not one of lambert/)]);
  });
});

/** The attributes of the element of page `file` (its HTML source) that holds widget `name` under `prefix`. */
function slotOf(file, name, prefix) {
  const html = readFileSync(new URL(`../../${file}`, import.meta.url), 'utf8');
  const tags = html.match(/<[^>]*\bdata-slot="[^"]*"[^>]*>/g) ?? [];
  const attr = (tag, key) => tag.match(new RegExp(`\\b${key}="([^"]*)"`))?.[1];
  const tag = tags.find((t) => attr(t, 'data-slot') === name && attr(t, 'data-prefix') === prefix);
  const initial = tag && attr(tag, 'data-initial')?.replaceAll('&quot;', '"').replaceAll('&amp;', '&');
  return tag ? { initial: initial ? JSON.parse(initial) : {} } : null;
}

/** What a page gives its widget's create: the slot's starting state under the URL's keys (widget-host.js mount). */
const first = (schema, search, prefix, initial = {}) =>
  coerceState(schema, {
    ...currentNames(schema, initial),
    ...currentNames(schema, widgetParams(search, prefix)),
  });

// tests/browser/saved-links.test.js opens the share links in Chromium and reads the widget's state there; a chapter
// page's link differs from its share link only in how the page reads its URL, checked here
describe('a chapter page’s saved link gives its widget the state the share link of that view gives', () => {
  for (const saved of SAVED.links.filter((l) => l.form === 'page')) {
    it(`${saved.widget}, ${saved.what}: ${saved.link.slice(0, 90)}`, async () => {
      const schema = await schemaOf(saved.widget);
      const share = SAVED.links.find((l) => l.form === 'share' && l.widget === saved.widget && l.what === saved.what);
      expect(share, 'the share link of the same view').toBeTruthy();
      const file = saved.link.slice(0, saved.link.indexOf('?'));
      const slot = slotOf(file, saved.widget, saved.prefix);
      expect(slot, `${file} holds ${saved.widget} under the prefix "${saved.prefix}"`).not.toBeNull();
      const page = first(schema, saved.link.slice(file.length), saved.prefix, slot.initial);
      const shared = first(schema, share.link.slice(share.link.indexOf('?')), '');
      expect(page.notices).toEqual([]);
      expect(page).toEqual(shared);
    });
  }
});
