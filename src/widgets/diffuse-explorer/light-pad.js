// A square pad for placing the light of a row of spheres: the shared light control (drag, or focus and use
// the arrow keys) on a canvas of its own, since a row of spheres has no single centre to drag around.
import { attachLightControl } from '../../core/light-control.js';

export function createLightPad(container, { get, set, label }) {
  const holder = document.createElement('div');
  holder.className = 'light-pad';
  const canvas = document.createElement('canvas');
  canvas.tabIndex = 0;
  canvas.setAttribute('role', 'application');
  canvas.setAttribute('aria-label', label);
  const caption = document.createElement('p');
  caption.className = 'light-pad-caption';
  caption.textContent = 'Light: drag here, or focus and use the arrow keys. Centre = behind the viewer; ring = 90°.';
  holder.append(canvas);
  container.append(holder, caption);
  const control = attachLightControl(canvas, holder, { get, set });
  const resize = new ResizeObserver(() => control.draw());
  resize.observe(holder);
  return {
    draw: control.draw,
    dispose() {
      resize.disconnect();
      control.dispose();
      holder.remove();
      caption.remove();
    },
  };
}
