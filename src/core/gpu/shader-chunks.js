// Every file in shaders/, by file name, as text (bundled at build time), and the term dispatch chunks generated
// from the catalogue ('ndf-term.glsl', 'visibility-term.glsl', 'fresnel-term.glsl': see term-chunks.js).
import { CATALOGUE } from '../../math/catalogue/index.js';
import { termDispatchChunks } from './term-chunks.js';

const files = import.meta.glob('../../../shaders/*.glsl', { query: '?raw', import: 'default', eager: true });

export const SHADER_CHUNKS = {
  ...Object.fromEntries(Object.entries(files).map(([path, text]) => [path.slice(path.lastIndexOf('/') + 1), text])),
  ...termDispatchChunks(CATALOGUE),
};
