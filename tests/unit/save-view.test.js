import { describe, expect, it } from 'vitest';
import { pngFileName, viewName } from '../../src/core/framework/save-view.js';

// Descriptions as the widgets write them (brdf-lobe, material-lab, media): the name is their first clause.
describe('a saved view is named for its description', () => {
  it('takes the first clause: up to a colon, a full stop or a semicolon', () => {
    expect(viewName('3-D lobe of A: GGX + Smith GGX, height-correlated, Schlick F0 0.04')).toBe('3-D lobe of A');
    expect(viewName('Material lab. A sphere (F0 0.04, diffuse #b5532e) under the studio')).toBe('Material lab');
    expect(viewName('Spheres; α 0.1 to 1')).toBe('Spheres');
    expect(viewName('F0 0.04 head-on')).toBe('F0 0.04 head-on'); // a decimal point is not a full stop
  });
  it('cuts a long first clause to 60 characters, with an ellipsis', () => {
    const name = viewName(`A glass of clean water ${'very '.repeat(20)}deep, seen from the side`);
    expect(name).toHaveLength(60);
    expect(name.endsWith('…')).toBe(true);
  });
  it('makes a file name of the widget and the view, keeping letters of any script', () => {
    expect(pngFileName('brdf-lobe', 'A over (θh, θd)')).toBe('brdf-lobe-a-over-θh-θd.png');
    expect(pngFileName('material-lab', 'Material lab')).toBe('material-lab-material-lab.png');
    expect(pngFileName('', '')).toBe('view.png');
  });
});
