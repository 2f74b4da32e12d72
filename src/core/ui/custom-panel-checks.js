// @ts-check
// The live checks beside the editor, in words and one plot: non-finite and negative values with the first input
// that gives one, D's normalisation, an anisotropic D's weak furnace, the range of V's G, a whole BRDF's reciprocity
// and white-furnace albedo, and the largest difference from a catalogue term the user picks, with the two curves
// (checks.js computes them all).
import { createPlot } from './plot.js';
import { referenceOptions } from '../custom/references.js';

/** @param {number} x */
const num = (x) => (Number.isFinite(x) ? Number(x.toPrecision(4)).toString() : String(x));

/** `n·h = 1, α = 0.0001` from an input record, with the slot's labels for its argument names. */
/**
 * @param {import('../custom/slots.js').Slot} slot
 * @param {Record<string, number> | undefined} inputs
 */
function inputsText(slot, inputs) {
  const labels = Object.fromEntries(slot.args.map((a) => [a.name, a.label]));
  return Object.entries(inputs ?? {})
    .map(([name, x]) => `${labels[name] ?? name} = ${num(x)}`)
    .join(', ');
}

/**
 * Each check as [passed, text]; passed null for a figure with no pass mark (the difference from a reference).
 * @param {import('../custom/slots.js').Slot} slot
 * @param {any} r  runChecks' result
 * @returns {[boolean | null, string][]}
 */
function checkLines(slot, r) {
  /** @type {[boolean | null, string][]} */
  const lines = [];
  const nf = r.nonFinite;
  lines.push(
    nf.count || nf.negative
      ? [
          false,
          `${nf.count} NaN or Inf, ${nf.negative} negative; ` +
            `first at ${inputsText(slot, nf.first?.inputs)}: ${num(nf.first?.value)}`,
        ]
      : [true, 'No NaN, Inf or negative value over the grid (stress inputs included)'],
  );
  if (r.normalisation) {
    const ok = Math.abs(r.normalisation.worst - 1) <= 1e-3;
    const each = r.normalisation.byAlpha
      .map((/** @type {{ alpha: number, integral: number }} */ x) => `α ${num(x.alpha)}: ${num(x.integral)}`)
      .join(', ');
    lines.push([ok, `∫ D(m)(n·m) dω should be 1; worst ${num(r.normalisation.worst)} (${each})`]);
  }
  if (r.weakFurnace) {
    const { worst, at, lambda } = r.weakFurnace; // an anisotropic D's, with the Λ of the reference compared with
    lines.push([
      Math.abs(worst - 1) <= 3e-3,
      `Weak white furnace (Heitz 2014) with ${lambda}: G1(v) ∫ D(h) ⟨v·h⟩ dω / (n·v) should be 1 at every v; ` +
        `worst ${num(worst)} at θv = ${num(at.thetaV)}°, φv = ${num(at.phiV)}°`,
    ]);
  }
  if (r.gRange) {
    const g = r.gRange;
    const where = g.first ? `; first at ${inputsText(slot, g.first.inputs)}: ${num(g.first.value)}` : '';
    lines.push([
      !g.outside,
      `G = V (n·l)(n·v) from ${num(g.min)} to ${num(g.max)}; ${g.outside} outside [0, 1]${where}`,
    ]);
  }
  if (r.reciprocity) {
    const ok = r.reciprocity.maxRel <= 1e-3;
    lines.push([ok, `Reciprocity: largest relative |f(l, v) − f(v, l)| ${num(r.reciprocity.maxRel)}`]);
  }
  if (r.furnace) {
    const at = Number.isFinite(r.furnace.at?.thetaV) ? ` at θv = ${num(r.furnace.at.thetaV)}°` : '';
    lines.push([r.furnace.max <= 1 + 1e-3, `White furnace: largest albedo ${num(r.furnace.max)}${at} (at most 1)`]);
  }
  const ref = r.reference;
  // the largest absolute and relative differences are usually at different inputs: the one named is the farthest
  // outside the parity tolerance |Δ| ≤ atol + rtol |reference|
  const worst = ref.worst
    ? `. Farthest from it for float32: at ${inputsText(slot, ref.worst.inputs)} yours ${num(ref.worst.value)}, ` +
      `it ${num(ref.worst.reference)}`
    : '';
  lines.push([
    null,
    `Against ${ref.label}: largest difference ${num(ref.maxAbs)}, largest relative difference ${num(ref.maxRel)}` +
      `${worst}`,
  ]);
  return lines;
}

/** @param {any} r  runChecks' result */
function curveSpec(r) {
  const { curve } = r;
  return {
    title: `Yours and ${r.reference.label}`,
    xLabel: curve.xLabel,
    yLabel: 'value',
    x: { min: curve.x[0], max: curve.x[curve.x.length - 1] },
    y: null,
    series: [
      { label: 'Yours', stroke: '#d55e00' },
      { label: r.reference.label, stroke: '#0072b2', dash: [6, 4] },
    ],
    data: [curve.x, curve.custom, curve.reference],
    filename: 'custom-term',
    height: 180,
  };
}

/**
 * @param {HTMLElement} container
 * @param {import('../custom/slots.js').Slot} slot
 * @param {(reference: string) => void} onReference  the user picked another catalogue term to compare with
 */
export function createChecksView(container, slot, onReference) {
  const box = document.createElement('section');
  box.className = 'custom-checks';
  box.setAttribute('aria-label', 'Checks of your code');
  const picker = document.createElement('label');
  const select = document.createElement('select');
  for (const [key, label] of Object.entries(referenceOptions(slot.key))) select.append(new Option(label, key));
  select.value = slot.reference;
  select.addEventListener('change', () => onReference(select.value));
  picker.append('Compare with ', select);
  const list = document.createElement('ul');
  list.setAttribute('aria-live', 'polite');
  const plotHolder = document.createElement('div');
  box.append(picker, list, plotHolder);
  container.append(box);
  /** @type {ReturnType<typeof createPlot> | null} */
  let plot = null;

  return {
    get reference() {
      return select.value;
    },
    /** @param {any} result  runChecks' result ({ errors } when it could not compile), or a sentence in its place */
    show(result) {
      if (typeof result === 'string' || result.errors) {
        const text = typeof result === 'string' ? result : `The checks could not compile: ${result.errors[0]?.message}`;
        list.replaceChildren(Object.assign(document.createElement('li'), { textContent: text }));
        return;
      }
      list.replaceChildren(
        ...checkLines(slot, result).map(([passed, text]) => {
          const li = document.createElement('li');
          li.className = passed === null ? 'check-figure' : passed ? 'check-pass' : 'check-fail';
          li.textContent = `${passed === null ? '' : passed ? '✓ ' : '✗ '}${text}`;
          return li;
        }),
      );
      if (plot) plot.setData(curveSpec(result));
      else plot = createPlot(plotHolder, curveSpec(result));
    },
    dispose() {
      plot?.dispose();
      box.remove();
    },
  };
}
