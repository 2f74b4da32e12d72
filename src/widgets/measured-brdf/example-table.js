// A synthetic example's table and fits, in Node or the fit worker: the table writeMerl makes from the example's
// model (read back as a file would be), and the five models fitted to it with the fitter's defaults.
import { FIT_MODELS, fitMeasured, fitSamples, modelBRDF } from '../../measured/fit.js';
import { parseMerl, writeMerl } from '../../measured/merl.js';
import { EXAMPLES } from './model.js';

/** The example's table as parseMerl reads it: { table, missing }. */
export const exampleTable = (key) => parseMerl(writeMerl(modelBRDF(EXAMPLES[key].model, EXAMPLES[key].params)));

/** { model: fitMeasured result } for the five models, fitted to the example's table. */
export function fitExample(key) {
  const measured = exampleTable(key);
  const samples = fitSamples(measured);
  return Object.fromEntries(Object.keys(FIT_MODELS).map((m) => [m, fitMeasured(measured, m, { samples })]));
}
