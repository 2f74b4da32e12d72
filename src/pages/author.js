// The authoring page: a lecturer builds an exercise set with no JSON to write. Built-in exercises are added from
// a filtered list, new ones made with a form for each kind; the validator checks the set as they type, its
// messages beside the fields they name; the exercise being edited is previewed in exercises.html itself. The set
// is saved as JSON, opened again from a file, shared as a link or exported as a SCORM 1.2 package. Nothing typed
// runs: text is shown by exercises.html's inert `$…$` formatting, code only ever compiled on a student's GPU.
import '../styles.css';
import '../exercises/author/author.css';
import { WIDGETS, isWidgetName } from '../widgets/registry.js';
import { parseJson, readExerciseSet } from '../exercises/load.js';
import { onFileDrop } from '../core/ui/file-drop.js';
import { download } from '../core/framework/download.js';
import { rawList, packageTitle } from '../exercises/scorm/package.js';
import { KINDS, newExercise, kindOf } from '../exercises/author/draft.js';
import { el, select } from '../exercises/author/fields.js';
import { createExerciseForm } from '../exercises/author/exercise-form.js';
import { createSetPanel } from '../exercises/author/set-panel.js';
import { createLibrary, loadBuiltIns } from '../exercises/author/library.js';
import { createPreview } from '../exercises/author/preview.js';
import { scormPackage, setJson, shareLink } from '../exercises/author/export.js';
import { readStudentFile } from '../exercises/author/progress-view.js';

const $ = (id) => document.getElementById(id);
const schemaOf = async (name) => (isWidgetName(name) ? (await WIDGETS[name].load()).widget.schema : null);

/** @type {{ raw: object, errors: string[] }[]} */
let items = [];
let selected = -1;
let setErrors = [];
let checked = { exercises: [], title: null, passMark: null };
let checks = 0;
const status = $('author-status');
const editHint = $('author-edit-hint');
const rest = $('author-other-problems');

const panel = createSetPanel($('author-set-fields'), {
  select: (i) => pick(i, { focus: true }),
  async move(i, by) {
    const j = i + by;
    [items[i], items[j]] = [items[j], items[i]];
    if (selected === i || selected === j) selected = selected === i ? j : i;
    await check();
    // the focus follows the moved exercise, on the same arrow unless it reached the end
    const tools = [...document.querySelectorAll('.author-items li')[j].querySelectorAll('.author-item-tools button')];
    /** @type {HTMLButtonElement} */ (
      tools[by < 0 ? 0 : 1].disabled ? tools[by < 0 ? 1 : 0] : tools[by < 0 ? 0 : 1]
    ).focus();
  },
  remove(i) {
    items.splice(i, 1);
    if (selected >= items.length || selected === i) pick(Math.min(i, items.length - 1));
    else if (selected > i) selected -= 1;
    check();
  },
  change: () => check(),
});
const form = createExerciseForm($('author-form'), {
  schemaOf,
  onInput(raw) {
    if (selected < 0) return;
    items[selected].raw = raw;
    check();
  },
});
const preview = createPreview($('author-preview'));

/** The set as its file will hold it. */
const currentSet = () => setJson({ ...panel.read(), exercises: items.map((it) => it.raw) });

function pick(i, { focus = false } = {}) {
  selected = i;
  const shown = i >= 0;
  $('author-form').hidden = !shown;
  editHint.hidden = shown;
  if (!shown) {
    preview.clear();
    return;
  }
  preview.clear(); // the frame showed another exercise
  form.edit(items[i].raw, kindOf(items[i].raw));
  check();
  if (focus) /** @type {HTMLElement} */ ($('author-form').querySelector('input, select, textarea'))?.focus();
}

function add(raw) {
  items.push({ raw, errors: [] });
  pick(items.length - 1, { focus: true });
  library?.render();
}

let pending = 0;
/** Checks the whole set (ids unique across it), then shows each message where it belongs. */
async function check() {
  const mine = ++pending;
  const got = await readExerciseSet(currentSet(), { source: 'set', schemaOf });
  if (mine !== pending) return; // a newer edit is being checked
  checked = got;
  setErrors = [];
  for (const it of items) it.errors = [];
  for (const { source, errors } of got.problems) {
    const n = Number(source.match(/^set #(\d+)$/)?.[1]);
    if (n) items[n - 1].errors = errors;
    else setErrors.push(...errors);
  }
  panel.render(items, selected, setErrors);
  const problems = setErrors.length + items.reduce((n, it) => n + it.errors.length, 0);
  if (selected >= 0) {
    const left = form.show(items[selected].errors);
    rest.replaceChildren(...left.map((e) => el('li', { textContent: e })));
    if (items[selected].errors.length) preview.stale();
    else preview.show(items[selected].raw);
  }
  const ready = items.length > 0 && problems === 0;
  for (const b of document.querySelectorAll('[data-needs-valid]')) b.toggleAttribute('disabled', !ready);
  status.textContent = !items.length
    ? 'Add an exercise to start a set.'
    : problems
      ? `${problems} problem${problems > 1 ? 's' : ''} to fix before the set can be saved, shared or exported.`
      : `${items.length} exercise${items.length > 1 ? 's' : ''}, ready to save, share or export.`;
  status.dataset.checks = String(++checks);
}

const say = (text, bad = false) => {
  const out = $('author-output');
  out.className = bad ? 'notice notice-error' : 'notice';
  out.replaceChildren(...[text].flat());
};
const stem = () =>
  (currentSet().title ?? 'exercise-set')
    .replace(/[^\p{L}\p{N}]+/gu, '-')
    .replace(/^-+|-+$/g, '')
    .toLowerCase() || 'exercise-set';

$('author-new').addEventListener('click', () => add(newExercise($('author-new-kind').value, items.length + 1)));
$('author-new-kind').replaceWith(Object.assign(select(KINDS, 'number'), { id: 'author-new-kind' }));

$('author-save').addEventListener('click', () => {
  const text = JSON.stringify(currentSet(), null, 2);
  download(`${stem()}.json`, new Blob([text], { type: 'application/json' }));
  say(`Saved ${stem()}.json: open it with exercises.html?src=its-address, or on this page again.`);
});

$('author-share').addEventListener('click', async () => {
  const got = shareLink(currentSet());
  if (got.error) return say(got.error, true);
  const box = el('input', { type: 'text', readOnly: true, value: got.url, id: 'author-link' });
  const label = el('label', {
    htmlFor: 'author-link',
    textContent: `A link to the set (${got.bytes.toLocaleString('en')} bytes of set)`,
  });
  say([label, box]);
  box.select();
  await navigator.clipboard?.writeText(got.url).then(
    () => label.append(': copied'),
    () => {}, // no clipboard (permissions): the link is selected to copy by hand
  );
});

$('author-export').addEventListener('click', async () => {
  const button = $('author-export');
  button.disabled = true;
  try {
    const { exercises, title, passMark } = checked;
    const raw = items.map((it) => it.raw);
    const got = await scormPackage(
      { exercises, raw, title: packageTitle(title, exercises), passMark },
      { onProgress: (n, of) => say(`Fetching the app’s files: ${n} of ${of}…`) },
    );
    download(`${stem()}-scorm.zip`, new Blob([got.zip], { type: 'application/zip' }));
    const mb = (got.zip.length / 1024 / 1024).toFixed(2);
    say(
      `SCORM 1.2 package ${stem()}-scorm.zip: ${got.files} files, ${mb} MB, made in ${(got.ms / 1000).toFixed(1)} s.`,
    );
  } catch (e) {
    say(`The package could not be made: ${e.message}.`, true);
  } finally {
    button.disabled = false;
  }
});

onFileDrop(
  $('author-open'),
  async (file) => {
    const got = parseJson(await file.text());
    if (got.error) return say(`${file.name} ${got.error}.`, true);
    const raws = rawList(got.json);
    const names = raws.filter((r) => typeof r !== 'object' || r === null);
    items = raws.filter((r) => typeof r === 'object' && r !== null).map((raw) => ({ raw, errors: [] }));
    panel.fill(got.json ?? {});
    pick(items.length ? 0 : -1);
    check();
    library?.render();
    const left = names.length ? ` ${names.length} entries are file names, which a file cannot fetch: left out.` : '';
    say(`Opened ${file.name}: ${items.length} exercises.${left}`, Boolean(names.length));
  },
  { input: /** @type {HTMLInputElement} */ ($('author-open-file')) },
);

onFileDrop(
  $('author-student'),
  async (file) => {
    const mark = checked.passMark ?? null;
    $('author-student-view').replaceChildren(...(await readStudentFile(file, mark)));
  },
  { input: /** @type {HTMLInputElement} */ ($('author-student-file')) },
);

pick(-1);
check();
let library = null;
const builtIns = await loadBuiltIns(schemaOf);
library = createLibrary($('author-library'), {
  list: builtIns.list,
  add,
  has: (id) => items.some((it) => it.raw.id === id),
});
