// The parity page's report, plain text a user can copy or save and send: which browser and GPU ran the check, and
// each function's worst case. No DOM here beyond the WebGL context it is given (the page and the engines runner
// read the same text).

/**
 * The GPU behind a WebGL context: the unmasked vendor and renderer when the browser gives them
 * (WEBGL_debug_renderer_info), else the masked ones (Firefox and Safari may say only "WebKit WebGL").
 * @param {WebGL2RenderingContext} gl
 */
export function rendererInfo(gl) {
  const ext = gl.getExtension('WEBGL_debug_renderer_info');
  return ext
    ? {
        vendor: String(gl.getParameter(ext.UNMASKED_VENDOR_WEBGL)),
        renderer: String(gl.getParameter(ext.UNMASKED_RENDERER_WEBGL)),
        unmasked: true,
      }
    : { vendor: String(gl.getParameter(gl.VENDOR)), renderer: String(gl.getParameter(gl.RENDERER)), unmasked: false };
}

const num = (x) => (Number.isFinite(x) ? x.toPrecision(7) : String(x));
const exp = (x) => (Number.isFinite(x) ? x.toExponential(2) : String(x));

/** One line of the report per function: its verdict, its errors and where the largest one is. */
function resultLine(r) {
  const verdict = r.pass ? 'ok  ' : 'FAIL';
  const { atol, rtol } = r.tolerance;
  const w = r.worst;
  return (
    `${verdict} ${r.name}: ${r.count} inputs, ${r.failures} beyond tolerance, ${r.invalid} NaN/Inf/out of range; ` +
    `max abs ${exp(r.maxAbs)}, max rel ${exp(r.maxRel)} (tolerance ${atol} + ${rtol}·|js|); worst at ` +
    `(${w.args.map(num).join(', ')}) output ${w.output}: GPU ${num(w.gpu)}, JS ${num(w.js)}`
  );
}

/**
 * The report: a header (the app's page, browser, GL vendor and renderer, when), the count beyond tolerance, then
 * one line per function, the failing ones first.
 * @param {object[]} results compareCase rows
 * @param {{ url: string, browser: string, vendor: string, renderer: string, unmasked: boolean, date: Date }} where
 */
export function parityReport(results, where) {
  const failed = results.filter((r) => !r.pass);
  return [
    'Shading Lab parity report (GLSL float32 on this GPU against the float64 JavaScript reference)',
    `Page: ${where.url}`,
    `Browser: ${where.browser}`,
    `GL vendor: ${where.vendor}`,
    `GL renderer: ${where.renderer}${where.unmasked ? '' : ' (the browser hides the real GPU name)'}`,
    `Date: ${where.date.toISOString()}`,
    `Result: ${failed.length} of ${results.length} functions beyond tolerance`,
    '',
    ...[...failed, ...results.filter((r) => r.pass)].map(resultLine),
    '',
  ].join('\n');
}
