// The measured-BRDF part of the bench: on a full-size synthetic MERL file (written by writeMerl from the GGX
// example, 34,992,012 bytes), the time to write and to parse it, each model's fit time with the page's
// default options, and the GPU memory of the 3-D texture a table takes (its size by format: the GPU gives
// WebGL no way to ask). Run alone with `npm run bench -- --only measured`.
import { MERL_BYTES, parseMerl, writeMerl } from '../src/measured/merl.js';
import { FIT_MODELS, fitMeasured, fitSamples, modelBRDF } from '../src/measured/fit.js';
import { EXAMPLES } from '../src/widgets/measured-brdf/model.js';
import { MERL_TEXTURE_BYTES } from '../src/widgets/measured-brdf/texture-size.js';

const median = (x) => x.sort((a, b) => a - b)[Math.floor(x.length / 2)];
const time = (f) => {
  const t = performance.now();
  const value = f();
  return [performance.now() - t, value];
};

export function measureMeasured({ quick = false } = {}) {
  const { model, params } = EXAMPLES.ggx;
  const [writeMs, buffer] = time(() => writeMerl(modelBRDF(model, params)));
  const parseRuns = Array.from({ length: quick ? 1 : 5 }, () => time(() => parseMerl(buffer)));
  const measured = parseRuns[0][1];
  // --quick (the bench's test): every model fitted on a coarse grid of samples (630), one step past its start
  const options = quick ? { strideD: 30, strideP: 60, maxEvaluations: 1 } : {};
  const [samplesMs, samples] = time(() => fitSamples(measured, options));
  const fits = Object.keys(FIT_MODELS).map((key) => {
    const [ms, r] = time(() => fitMeasured(measured, key, { ...options, samples }));
    return { model: key, ms, evaluations: r.evaluations, error: r.error, params: r.params };
  });
  return {
    file: { example: EXAMPLES.ggx.label, bytes: MERL_BYTES },
    writeMs,
    parseMs: median(parseRuns.map(([ms]) => ms)),
    parseRuns: parseRuns.length,
    fitSamples: { count: samples.count, ms: samplesMs, options },
    fits,
    texture: { format: 'RGBA16F, 180 × 90 × 90 texels', bytes: MERL_TEXTURE_BYTES },
  };
}

export function printMeasured(m) {
  const pad = (s, n) => String(s).padEnd(n);
  const ms = (x) => `${x.toFixed(0)} ms`;
  console.log(`\nMeasured BRDF (a ${m.file.bytes.toLocaleString('en')}-byte synthetic MERL file):`);
  console.log(`  written in ${ms(m.writeMs)}, parsed in ${ms(m.parseMs)} (median of ${m.parseRuns})`);
  console.log(`  ${m.fitSamples.count} fit samples in ${ms(m.fitSamples.ms)}`);
  console.log(`  ${pad('model', 16)}${pad('fit (ms)', 11)}${pad('evaluations', 13)}error (1/sr)^(1/3)`);
  for (const f of m.fits) {
    const row = `${pad(FIT_MODELS[f.model].label, 16)}${pad(f.ms.toFixed(0), 11)}${pad(f.evaluations, 13)}`;
    console.log(`  ${row}${f.error.toExponential(2)}`);
  }
  console.log(`  3-D texture on the GPU: ${m.texture.format} = ${(m.texture.bytes / 1e6).toFixed(2)} MB per table`);
}
