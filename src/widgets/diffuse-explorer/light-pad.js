// A square pad for placing the light of a row of spheres: the shared light control (drag, or focus and use
// the arrow keys) on a canvas of its own, since a row of spheres has no single centre to drag around.
import { attachLightControl } from '../../core/ui/light-control.js';
import { describeCanvas } from '../../core/framework/describe.js';

export function createLightPad(container, { get, set, label }) {
  const box = document.createElement('div');
  box.className = 'light-pad-box';
  const holder = document.createElement('div');
  holder.className = 'light-pad';
  const canvas = document.createElement('canvas');
  canvas.tabIndex = 0;
  const caption = document.createElement('p');
  caption.className = 'light-pad-caption';
  holder.append(canvas);
  box.append(holder, caption);
  container.append(box);
  const control = attachLightControl(canvas, holder, { get, set });
  // the angles go in the caption: a pad this small has no room for the marker's own label
  const draw = () => {
    control.draw();
    const { lightTheta, lightPhi } = get();
    caption.textContent =
      `Light θ ${lightTheta}°, φ ${lightPhi}°: drag, or focus and use the arrow keys ` +
      '(centre = behind the viewer, ring = 90°).';
    describeCanvas(
      canvas,
      `${label}: the light is ${lightTheta}° from the viewing direction, at ${lightPhi}° around it. ` +
        'Arrow keys move it 5° at a time.',
      { save: false }, // a control, not a picture
    );
  };
  const resize = new ResizeObserver(draw);
  resize.observe(holder);
  return {
    draw,
    dispose() {
      resize.disconnect();
      control.dispose();
      box.remove();
    },
  };
}
