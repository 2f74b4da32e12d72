// The BRDF lobe's two (θh, θd) images side by side: A, and B when it is overlaid (else one image fills the row).
import { createHalfDiffImage } from './half-diff-image.js';
import { halfDiffFunction } from './model.js';
import { describeImage } from './words.js';

export function createHalfDiffPair(container) {
  const row = document.createElement('div');
  row.className = 'half-diff-row';
  container.append(row);
  const imageA = createHalfDiffImage(row, 'A over (θh, θd)');
  const imageB = createHalfDiffImage(row, 'B over (θh, θd)');
  return {
    draw(state, { A, B }) {
      imageA.draw(halfDiffFunction(state, A), describeImage(state, A, state.alpha));
      if (B) imageB.draw(halfDiffFunction(state, B), describeImage(state, B, state.alpha2));
      else imageB.draw(() => 0, 'not shown (no overlay)');
      row.classList.toggle('single', !B);
    },
    dispose() {
      imageA.dispose();
      imageB.dispose();
    },
  };
}
