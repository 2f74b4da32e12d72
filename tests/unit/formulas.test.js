// The formulas on the pages: every data-tex in every HTML page parses with KaTeX, and comes out as MathML.
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import katex from 'katex';
import { describe, expect, it } from 'vitest';

const ROOT = join(import.meta.dirname, '../..');
const decode = (s) =>
  s.replaceAll('&quot;', '"').replaceAll('&lt;', '<').replaceAll('&gt;', '>').replaceAll('&amp;', '&');
const formulas = readdirSync(ROOT)
  .filter((f) => f.endsWith('.html'))
  .flatMap((page) =>
    [...readFileSync(join(ROOT, page), 'utf8').matchAll(/data-tex="([^"]*)"/g)].map((m) => ({
      page,
      tex: decode(m[1]),
    })),
  );

describe('formulas', () => {
  it('there are some', () => expect(formulas.length).toBeGreaterThan(0));

  for (const { page, tex } of formulas) {
    it(`${page}: ${tex.slice(0, 60)}…`, () => {
      const html = katex.renderToString(tex, { output: 'mathml', displayMode: true, throwOnError: true });
      expect(html).toMatch(
        /^<span class="katex"><math xmlns="http:\/\/www.w3.org\/1998\/Math\/MathML" display="block">/,
      );
      expect(html).not.toMatch(/katex-error|style=/); // MathML only: nothing a strict style policy would block
    });
  }
});
