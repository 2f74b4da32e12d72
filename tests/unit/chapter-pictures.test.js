// The landing page's chapter pictures: one per chapter, shipped in public/, small.
import { readFileSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { CHAPTERS } from '../../src/pages/chapters.js';
import { CHAPTER_PICTURES, chapterPictureUrl } from '../../src/pages/chapter-pictures.js';

const file = (key) => join(import.meta.dirname, '../../public', chapterPictureUrl(key));

describe('chapter pictures', () => {
  it('every chapter has one, with alt text, and no picture is left without a chapter', () => {
    expect(Object.keys(CHAPTER_PICTURES).sort()).toEqual(CHAPTERS.map((c) => c.key).sort());
    for (const alt of Object.values(CHAPTER_PICTURES)) expect(alt.length).toBeGreaterThan(20);
  });

  it('each is a WebP file (RIFF….WEBP) under 30 KB', () => {
    for (const { key } of CHAPTERS) {
      const head = readFileSync(file(key)).subarray(0, 12).toString('latin1');
      expect(head.slice(0, 4) + head.slice(8), key).toBe('RIFFWEBP');
      expect(statSync(file(key)).size, key).toBeLessThan(30 * 1024);
    }
  });
});
