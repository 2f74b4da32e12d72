// The links saved from the build before one name per idea (saved-links.json, made by
// scripts/collect-saved-links.js from b048b6b) and the renames since: this table is the tests' own, not the schemas'.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

export const SAVED = JSON.parse(readFileSync(join(import.meta.dirname, 'saved-links.json'), 'utf8'));

/** Old key → new key, by widget: a term's choice under the catalogue's name (F, D, V, diffuse, compensation). */
export const RENAMED_KEYS = {
  'ndf-explorer': { ndfs: 'D' },
  'visibility-explorer': { terms: 'V' },
  'diffuse-explorer': { models: 'diffuse' },
  'material-lab': { fresnel: 'F', ndf: 'D', visibility: 'V', diffuseModel: 'diffuse', diffuse: 'cdiff' },
  'lighting-models': { diffuse: 'cdiff' },
};
/** New key → { old option: new option }: a material set by hand is `manual`; `custom` is the user's own GLSL. */
export const RENAMED_OPTIONS = {
  'material-lab': { material: { custom: 'manual' } },
  'lighting-models': { material: { custom: 'manual' } },
  'fresnel-curves': { materials: { custom: 'manual' } },
};

/** The old build's state under this build's names. */
export function renamed(widget, state) {
  const keys = RENAMED_KEYS[widget] ?? {};
  const options = RENAMED_OPTIONS[widget] ?? {};
  return Object.fromEntries(
    Object.entries(state).map(([k, v]) => {
      const key = keys[k] ?? k;
      const to = (x) => options[key]?.[x] ?? x;
      return [key, Array.isArray(v) ? v.map(to) : to(v)];
    }),
  );
}
