// Rewrites the measured part of docs/performance.md from bench/results/latest.json
// (npm run bench:readme), between the markers <!-- bench:begin --> and <!-- bench:end -->.
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { ROOT } from '../tests/browser/harness.js';
import { measuredLines } from './readme-lines.js';

const report = JSON.parse(readFileSync(join(ROOT, 'bench/results/latest.json'), 'utf8'));
const lines = measuredLines(report);

const path = join(ROOT, 'docs/performance.md');
const readme = readFileSync(path, 'utf8');
const [begin, end] = ['<!-- bench:begin -->', '<!-- bench:end -->'];
if (!readme.includes(begin) || !readme.includes(end)) throw new Error(`${path} has no ${begin} … ${end} block`);
writeFileSync(
  path,
  `${readme.slice(0, readme.indexOf(begin) + begin.length)}\n${lines.join('\n')}\n${readme.slice(readme.indexOf(end))}`,
);
console.log('docs/performance.md: measured tables rewritten from bench/results/latest.json');
