// A synthetic example's table and fits, as the fit worker makes them (src/measured/fit-worker.js): the table
// writeMerl makes from the example's model, read back as a file would be, and the five models fitted to it with
// the fitter's defaults (what the widget asks the worker for).
import { FIT_MODELS, fitModels, synthesizeTable } from '../../measured/fit.js';
import { EXAMPLES } from './model.js';

/** The example's table as parseMerl reads it: { table, missing, … }. */
export const exampleTable = (key) => synthesizeTable(EXAMPLES[key].model, EXAMPLES[key].params);

/** { model: fitMeasured result } for the five models, fitted to the example's table. */
export const fitExample = (key) => fitModels(exampleTable(key), Object.keys(FIT_MODELS));
