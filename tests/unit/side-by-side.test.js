// drawSideBySide: the cells' scissor columns tile the canvas in whole pixels (no seam, no overlap) and each
// viewport is the largest square centred in its column, checked against the canvas's own width and height.
import { describe, expect, it } from 'vitest';
import { drawSideBySide } from '../../src/core/ui/side-by-side.js';

const recordingRenderer = (width, height) => {
  const calls = [];
  return {
    calls,
    getSize: (v) => v.set(width, height),
    setScissorTest: (on) => calls.push(['scissorTest', on]),
    setViewport: (...r) => calls.push(['viewport', ...r]),
    setScissor: (...r) => calls.push(['scissor', ...r]),
  };
};

describe('drawSideBySide', () => {
  it('three cells over 1001 × 300 px: columns tile the width, squares centred, each drawn after its rects', () => {
    const renderer = recordingRenderer(1001, 300);
    const drawn = [];
    drawSideBySide(renderer, 3, (i) => drawn.push([i, renderer.calls.length]));
    const scissors = renderer.calls.filter((c) => c[0] === 'scissor');
    const viewports = renderer.calls.filter((c) => c[0] === 'viewport');
    expect(scissors.map(([, x, , w]) => [x, x + w])).toEqual([
      [0, 334],
      [334, 667],
      [667, 1001],
    ]);
    scissors.forEach(([, x, y, w, h], i) => {
      expect([y, h]).toEqual([0, 300]);
      const [, vx, vy, vw, vh] = viewports[i];
      expect([vw, vh]).toEqual([300, 300]);
      expect(vx + vw / 2).toBe(x + w / 2);
      expect(vy).toBe(0);
    });
    expect(drawn).toEqual([
      [0, 3],
      [1, 5],
      [2, 7],
    ]); // cell i drawn once its viewport and scissor are set
    expect(renderer.calls[0]).toEqual(['scissorTest', true]);
    expect(renderer.calls.at(-1)).toEqual(['scissorTest', false]);
  });
  it('a tall canvas: the square is the column’s width, centred vertically', () => {
    const renderer = recordingRenderer(200, 500);
    drawSideBySide(renderer, 2, () => {});
    expect(renderer.calls.filter((c) => c[0] === 'viewport')).toEqual([
      ['viewport', 0, 200, 100, 100],
      ['viewport', 100, 200, 100, 100],
    ]);
  });
  it('no cells: nothing drawn', () => {
    const renderer = recordingRenderer(200, 100);
    drawSideBySide(renderer, 0, () => expect.unreachable());
    expect(renderer.calls).toEqual([
      ['scissorTest', true],
      ['scissorTest', false],
    ]);
  });
});
