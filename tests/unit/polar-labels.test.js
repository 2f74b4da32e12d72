// The BRDF lobe's polar plot places its words (direction names, spoke degrees, ring values, "surface") so that
// no two boxes intersect, none covers a direction's dot, and all stay on the canvas: checked box against box over
// every light and view angle on a 5° grid, at the widths the plot has on a desktop and on a phone.
import { describe, expect, test } from 'vitest';
import {
  dialGeometry,
  layOutLabels,
  NAME_FONT,
  polarLabelSpecs,
  toXY,
} from '../../src/widgets/brdf-lobe/polar-labels.js';
import { DEG } from '../../src/math/angles.js';

// a generous width for system-ui: the bold 13 px names ~8.5 px a character, the 11 px words ~7 px
const measure = (text, font) => text.length * (font === NAME_FONT ? 8.5 : 7);
const intersect = (a, b) => a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
const NAMES = ['n', 'mirror', 'h', 'l', 'v'];

function layout(w, h, lightTheta, viewTheta) {
  const l = [-Math.sin(lightTheta * DEG), Math.cos(lightTheta * DEG)];
  const v = [Math.sin(viewTheta * DEG), Math.cos(viewTheta * DEG)];
  const sum = [l[0] + v[0], l[1] + v[1]];
  const halfTheta = Math.hypot(...sum) > 1e-9 ? Math.atan2(sum[0], sum[1]) / DEG : null; // h = (l + v) / |l + v|
  const spec = { lightTheta, viewTheta, halfTheta, max: 3.2 };
  const g = dialGeometry(w, h);
  return { g, spec, placed: layOutLabels(polarLabelSpecs(g, spec, measure), g, spec) };
}

describe('polar plot labels', () => {
  for (const [w, h] of [
    [470, 250], // the plot's canvas at 1280 px
    [360, 200], // at 390 px
  ]) {
    test(`${w}×${h}: no two words' boxes meet, none covers a dot, all on the canvas, every direction named`, () => {
      const bad = [];
      for (let lightTheta = 0; lightTheta <= 85; lightTheta += 5) {
        for (let viewTheta = -85; viewTheta <= 85; viewTheta += 5) {
          const { g, spec, placed } = layout(w, h, lightTheta, viewTheta);
          const at = `l ${lightTheta}°, v ${viewTheta}°`;
          const named = placed.map((p) => p.text).filter((t) => NAMES.includes(t));
          const want = NAMES.filter((n) => n !== 'h' || spec.halfTheta !== null);
          if (named.sort().join() !== want.sort().join()) bad.push(`${at}: named ${named}`);
          placed.forEach((a, i) => {
            if (a.x < 0 || a.y < 0 || a.x + a.w > w || a.y + a.h > h) bad.push(`${at}: ${a.text} off the canvas`);
            for (const b of placed.slice(i + 1)) if (intersect(a, b)) bad.push(`${at}: ${a.text} meets ${b.text}`);
          });
          const dots = [0, lightTheta, -lightTheta, viewTheta, ...(spec.halfTheta === null ? [] : [spec.halfTheta])];
          for (const theta of dots) {
            const [x, y] = toXY(g, theta, 1);
            const dot = { x: x - 3, y: y - 3, w: 6, h: 6 };
            for (const p of placed) if (intersect(p, dot)) bad.push(`${at}: ${p.text} covers the dot at ${theta}°`);
          }
        }
      }
      expect(bad).toEqual([]);
    });
  }

  test('where v lies on the mirror direction (l = v = 60°), both names and the 60° of the spoke are apart', () => {
    const { placed } = layout(470, 250, 60, 60);
    const names = Object.fromEntries(placed.map((p) => [p.text, p]));
    expect(intersect(names.v, names.mirror)).toBe(false);
    for (const p of placed.filter((q) => q.text === '60°')) {
      expect(intersect(p, names.v)).toBe(false);
      expect(intersect(p, names.mirror)).toBe(false);
    }
  });
});
