// GPU memory of one MERL table as the spheres' 3-D texture: 90 · 90 · 180 texels, RGBA half floats (8 bytes).
// Apart from spheres.js so that the bench reads it without three.js.
import { MERL_SAMPLES } from '../../measured/merl.js';

export const MERL_TEXTURE_BYTES = MERL_SAMPLES * 4 * 2;
