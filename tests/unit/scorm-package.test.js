// The SCORM package that `npm run scorm` writes, checked against the SCORM 1.2 Content Aggregation Model's
// structure (a manifest identifier, schema "ADL SCORM" 1.2, an organization whose item points at one resource of
// adlcp:scormtype "sco", the launch file present, every file of the zip listed) and the zip's contents, read back
// with fflate's unzip. A stand-in dist/ keeps it to the packaging (the browser test uses the real build).
import { afterAll, describe, expect, it } from 'vitest';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { strFromU8, unzipSync } from 'fflate';
import { readExerciseSet } from '../../src/exercises/load.js';
import { WIDGETS } from '../../src/widgets/registry.js';
import { LAUNCH, SET_PATH, packageSet } from '../../scripts/scorm.js';

const INDEX = join(import.meta.dirname, '../../public/exercises/index.json');
const schemaOf = async (name) => (Object.hasOwn(WIDGETS, name) ? (await WIDGETS[name].load()).widget.schema : null);
const validate = { readExerciseSet, schemaOf };
const tmp = mkdtempSync(join(tmpdir(), 'scorm-'));
const dist = join(tmp, 'dist');
mkdirSync(join(dist, 'assets'), { recursive: true });
writeFileSync(join(dist, 'exercises.html'), '<!doctype html><title>x</title>');
writeFileSync(join(dist, 'assets', 'page one.js'), 'export {};'); // a space: listed URI-encoded
afterAll(() => rmSync(tmp, { recursive: true, force: true }));

const attr = (tag, name) => tag.match(new RegExp(`\\s${name}="([^"]*)"`))?.[1];
const tags = (xml, name) => xml.match(new RegExp(`<${name}(\\s[^>]*)?>`, 'g')) ?? [];

describe('npm run scorm’s package', { timeout: 60_000 }, () => {
  it('has a SCORM 1.2 manifest with one SCO that lists every file of the zip, and the launch file', async () => {
    const outFile = join(tmp, 'set.zip');
    const got = await packageSet({ setFile: INDEX, outFile, dist, validate });
    expect(got.errors).toBeUndefined();
    const zip = unzipSync(readFileSync(outFile));
    const xml = strFromU8(zip['imsmanifest.xml']);
    expect(attr(tags(xml, 'manifest')[0], 'identifier')).toMatch(/^shading-lab-[0-9a-z]+$/);
    expect(xml).toMatch(/<schema>ADL SCORM<\/schema>\s*<schemaversion>1\.2<\/schemaversion>/);
    expect(attr(tags(xml, 'manifest')[0], 'xmlns:adlcp')).toBe('http://www.adlnet.org/xsd/adlcp_rootv1p2');
    const [org] = tags(xml, 'organization');
    expect(attr(tags(xml, 'organizations')[0], 'default')).toBe(attr(org, 'identifier'));
    const items = tags(xml, 'item');
    const resources = tags(xml, 'resource');
    expect([items.length, resources.length]).toEqual([1, 1]);
    expect(attr(items[0], 'identifierref')).toBe(attr(resources[0], 'identifier'));
    expect(attr(resources[0], 'adlcp:scormtype')).toBe('sco');
    expect(attr(resources[0], 'href')).toBe(LAUNCH);
    const listed = tags(xml, 'file').map((t) => decodeURI(attr(t, 'href')));
    expect(listed.sort()).toEqual(
      Object.keys(zip)
        .filter((f) => f !== 'imsmanifest.xml')
        .sort(),
    );
    expect(listed).toContain('assets/page one.js');
    expect(strFromU8(zip[LAUNCH])).toContain('url=exercises.html?scorm=1&amp;src=set%2Fexercises.json');
    expect(zip['exercises.html']).toBeDefined();
    expect(xml).not.toContain('masteryscore');
  });

  it('holds the set as one file, the built-in exercises in their order, byte-for-byte the app’s files', async () => {
    const outFile = join(tmp, 'set2.zip');
    await packageSet({ setFile: INDEX, outFile, dist, validate });
    const zip = unzipSync(readFileSync(outFile));
    const names = JSON.parse(readFileSync(INDEX, 'utf8')).exercises;
    const ids = names.map((n) => JSON.parse(readFileSync(join(INDEX, '..', n), 'utf8')).id);
    const set = JSON.parse(strFromU8(zip[SET_PATH]));
    expect(set.exercises.map((e) => e.id)).toEqual(ids);
    expect(strFromU8(zip['assets/page one.js'])).toBe('export {};');
  });

  it('writes the set’s passMark as the item’s adlcp:masteryscore', async () => {
    const setFile = join(tmp, 'marked.json');
    const one = JSON.parse(readFileSync(join(INDEX, '..', 'lake-mirror.json'), 'utf8'));
    writeFileSync(setFile, JSON.stringify({ title: 'Week 3 & 4', passMark: 80, exercises: [one] }));
    await packageSet({ setFile, outFile: join(tmp, 'marked.zip'), dist, validate });
    const xml = strFromU8(unzipSync(readFileSync(join(tmp, 'marked.zip')))['imsmanifest.xml']);
    expect(xml).toContain('<adlcp:masteryscore>80</adlcp:masteryscore>');
    expect(xml).toContain('<title>Week 3 &amp; 4</title>');
  });

  it('refuses an invalid set with the validator’s messages and writes nothing', async () => {
    const setFile = join(tmp, 'bad.json');
    writeFileSync(setFile, JSON.stringify({ passMark: 120, exercises: [{ id: 'x', chapter: 'nope' }] }));
    const outFile = join(tmp, 'bad.zip');
    const got = await packageSet({ setFile, outFile, dist, validate });
    expect(got.errors).toContain(
      'bad.json #1: chapter: "nope" is not a chapter (chapters: ' +
        'media, surfaces, brdf, microfacets, fresnel, ndf, visibility, diffuse, rendering, today, performance)',
    );
    expect(got.errors).toContain('bad.json: passMark: 120 is not a percentage 0…100'); // the validator's format
    expect(existsSync(outFile)).toBe(false);
  });
});
