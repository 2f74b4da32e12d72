// The lighting-models widget's state: the material (a dark, fairly smooth dielectric by default), what the images
// show, the reference's samples and the display. Pure data: loads in Node without three.js.
import { MATERIAL_FIELDS } from '../../lab/lab-scene.js';

export const schema = {
  ...MATERIAL_FIELDS,
  // a dark, fairly smooth dielectric by default: the sun's highlight is where the models differ most
  cdiff: { ...MATERIAL_FIELDS.cdiff, default: '#2f4f7f' },
  alpha: { ...MATERIAL_FIELDS.alpha, default: 0.1 },
  show: { type: 'enum', options: { images: 'Images', errors: 'Error images' }, default: 'images', label: 'Show' },
  refSamples: {
    type: 'enum',
    options: { 128: '128', 512: '512', 2048: '2048' },
    default: '512',
    label: 'Reference samples / pixel',
  },
  exposure: { type: 'number', min: 0.1, max: 8, step: 0.05, default: 0.8, label: 'Exposure' },
  errorScale: { type: 'number', min: 0.005, max: 1, step: 0.005, default: 0.1, label: 'Error image: full scale' },
};
