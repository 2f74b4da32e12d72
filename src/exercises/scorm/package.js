// The SCORM 1.2 package of a checked set, the same from the command line (scripts/scorm.js, the files of dist/)
// and from the author page (src/exercises/author/export.js, the files the service worker lists): the app's built
// files, the set as one file, the launch page and imsmanifest.xml, zipped with fflate.
import { zipSync } from 'fflate';
import { launchPage, scormManifest } from './manifest.js';
import { setFingerprint } from './suspend.js';

export const SET_PATH = 'set/exercises.json';
export const LAUNCH = 'scorm-launch.html';

/**
 * The set's exercises as the file gave them, in order: an index's file names replaced by the files read
 * (`raws`: URL → parsed JSON, as the loader fetched them against `baseUrl`).
 */
export function rawList(json, baseUrl = null, raws = new Map()) {
  const list = Array.isArray(json) ? json : Array.isArray(json?.exercises) ? json.exercises : [json];
  return list.map((item) => (typeof item === 'string' ? raws.get(new URL(item, baseUrl ?? undefined).href) : item));
}

/** The title a package shows: the set's, else a one-exercise set's exercise's, else a general one. */
export const packageTitle = (title, exercises) =>
  title ?? (exercises.length === 1 ? exercises[0].title : 'Shading Lab exercises');

/**
 * app: { path: bytes } of the built app; exercises: the checked exercises (their ids name the package); raw: the
 * same as the file gives them; title; passMark (percent or null). Returns the zip's bytes and its file count.
 */
export function buildPackage({ app, exercises, raw, title, passMark = null }) {
  const text = (s) => new TextEncoder().encode(s);
  const set = { title, ...(passMark === null ? {} : { passMark }), exercises: raw };
  const entries = {
    ...app,
    [SET_PATH]: text(JSON.stringify(set, null, 2)),
    [LAUNCH]: text(launchPage({ title, set: SET_PATH })),
  };
  const identifier = `shading-lab-${setFingerprint(exercises.map((e) => e.id))}`;
  const files = Object.keys(entries).sort();
  entries['imsmanifest.xml'] = text(scormManifest({ identifier, title, launch: LAUNCH, files, mastery: passMark }));
  return { zip: zipSync(entries, { level: 6 }), files: files.length + 1 };
}
