// The built-in exercises on the author page (public/exercises, read as exercises.html reads them), filtered by
// chapter and kind, each to add to the set as a copy to edit.
import { CHAPTERS } from '../../widgets/chapters.js';
import { fetchJson, loadExerciseSet } from '../load.js';
import { rawList } from '../scorm/package.js';
import { KINDS, kindOf } from './draft.js';
import { el, field, select } from './fields.js';

/** The built-in exercises as their files give them, in the index's order: [{ raw }] and any problems. */
export async function loadBuiltIns(schemaOf, url = 'exercises/index.json') {
  const raws = new Map();
  const load = async (href) => {
    const got = await fetchJson(href);
    if (got.json) raws.set(href, got.json);
    return got;
  };
  const href = new URL(url, location.href).href;
  const got = await loadExerciseSet(href, { schemaOf, load });
  const json = raws.get(href);
  const ok = new Set(got.exercises.map((e) => e.id));
  const list = json ? rawList(json, href, raws).filter((raw) => ok.has(raw?.id)) : [];
  return { list, problems: got.problems };
}

/** parent: where the list goes; list: [raw]; add(raw); has(id): whether the set holds that id already. */
export function createLibrary(parent, { list, add, has }) {
  const chapters = Object.fromEntries(CHAPTERS.map((c, i) => [c.key, `${i + 1}. ${c.title}`]));
  const chapter = select(chapters, '', 'every chapter');
  const kind = select(KINDS, '', 'every kind');
  const filters = el(
    'div',
    { className: 'author-filters' },
    field('chapter', 'Chapter', 'Show the exercises of one chapter.', chapter, () => chapter.value).box,
    field('kind', 'Kind', 'Show the exercises of one kind.', kind, () => kind.value).box,
  );
  const items = el('ul', { className: 'author-library-list' });
  parent.append(filters, items);
  const render = () => {
    const shown = list.filter(
      (raw) => (!chapter.value || raw.chapter === chapter.value) && (!kind.value || kindOf(raw) === kind.value),
    );
    items.replaceChildren(
      ...shown.map((raw) => {
        const added = has(raw.id);
        const b = el('button', { type: 'button', textContent: added ? 'Added' : 'Add', disabled: added });
        b.setAttribute('aria-label', `${added ? 'Added' : 'Add'}: ${raw.title}`);
        b.addEventListener('click', () => add(structuredClone(raw)));
        const where = `chapter ${CHAPTERS.findIndex((c) => c.key === raw.chapter) + 1} · ${KINDS[kindOf(raw)]}`;
        return el(
          'li',
          {},
          b,
          ' ',
          el('span', { textContent: raw.title }),
          el('span', { className: 'author-item-meta', textContent: ` ${where}` }),
        );
      }),
    );
    if (!shown.length) items.append(el('li', { textContent: 'No built-in exercise of this chapter and kind.' }));
  };
  chapter.addEventListener('change', render);
  kind.addEventListener('change', render);
  render();
  return { render };
}
