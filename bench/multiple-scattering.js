// node bench/multiple-scattering.js: the multiple-scattering bench family's errors against the random walk,
// broken down by F0 (max |error| and RMS of the albedo for each compensation), for the notes and docs/performance.md.
import { MULTIPLE_SCATTERING_FAMILY as family } from './multiple-scattering-family.js';

const f0Label = (f0, channel) => (channel < 3 ? String(f0) : `gold ${'RGB'[channel - 3]} (${f0})`);
const [reference, ...approximations] = family.variants;
const rows = new Map();
for (const args of family.inputs) {
  const [, , f0, channel] = args;
  const ref = reference.js(...args);
  const row =
    rows.get(channel) ??
    rows.set(channel, { label: f0Label(f0, channel), errors: approximations.map(() => []) }).get(channel);
  approximations.forEach((v, i) => row.errors[i].push(v.js(...args) - ref));
}
const pad = (s, n) => String(s).padEnd(n);
console.log(`Albedo error against the ${reference.label} (${family.referenceNote()}), over ${family.domain}.`);
console.log(`${pad('F0', 18)}${approximations.map((v) => pad(`${v.label}: max, RMS`, 34)).join('')}`);
for (const { label, errors } of rows.values()) {
  const cells = errors.map((e) => {
    const max = e.reduce((m, x) => (Math.abs(x) > Math.abs(m) ? x : m), 0);
    const rms = Math.sqrt(e.reduce((s, x) => s + x * x, 0) / e.length);
    return pad(`${max >= 0 ? '+' : ''}${max.toFixed(4)}, ${rms.toFixed(4)}`, 34);
  });
  console.log(`${pad(label, 18)}${cells.join('')}`);
}
