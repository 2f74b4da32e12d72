// Placing a directional light by hand. The light is given in view space by two angles: theta, from the
// viewing direction (0° = light behind the viewer, 90° = from the side, 180° = from behind the object),
// and phi, around the viewing direction (0° = right, 90° = up). Dragging maps the pointer's distance from
// the canvas centre to theta (the dashed ring is 90°); the arrow keys move the light 5° at a time.
import { DEG } from '../../math/angles.js';

/** Radius, in CSS pixels, of the ring that stands for theta = 90°. */
const ringRadius = (w, h) => 0.42 * Math.min(w, h);

/** The light's marker over the canvas: the 90° ring, the ray from the centre and the sun, with its label. */
function createOverlay(canvas, overlayParent, get, active) {
  const svg = document.createElementNS('http://www.w3.org/2000/svg', 'svg');
  svg.classList.add('light-overlay');
  svg.setAttribute('aria-hidden', 'true');
  svg.innerHTML =
    '<circle class="ring" /><line class="ray" /><circle class="sun" r="7" /><text class="sun-label">light</text>';
  overlayParent.append(svg);
  const [ring, ray, sun, label] = svg.children;

  const draw = () => {
    svg.style.display = active() ? '' : 'none';
    const w = canvas.clientWidth;
    const h = canvas.clientHeight;
    svg.setAttribute('viewBox', `0 0 ${w} ${h}`);
    const R = ringRadius(w, h);
    const { lightTheta, lightPhi } = get();
    const r = (lightTheta / 90) * R;
    const clampTo = (v, max) => Math.min(Math.max(v, 12), max - 12); // beyond 90° the marker may leave the canvas
    const x = clampTo(w / 2 + r * Math.cos(lightPhi * DEG), w);
    const y = clampTo(h / 2 - r * Math.sin(lightPhi * DEG), h);
    ring.setAttribute('cx', w / 2);
    ring.setAttribute('cy', h / 2);
    ring.setAttribute('r', R);
    ray.setAttribute('x1', w / 2);
    ray.setAttribute('y1', h / 2);
    ray.setAttribute('x2', x);
    ray.setAttribute('y2', y);
    sun.setAttribute('cx', x);
    sun.setAttribute('cy', y);
    sun.classList.toggle('behind', lightTheta > 90);
    label.setAttribute('x', x > w - 110 ? x - 100 : x + 10);
    label.setAttribute('y', y < 24 ? y + 22 : y - 10);
    label.textContent = `light θ ${lightTheta.toFixed(0)}°`;
  };
  return { draw, remove: () => svg.remove() };
}

/** The light moved by an arrow key (Shift: 1° instead of 5°), or null for any other key. */
function keyMove(e, { lightTheta, lightPhi }) {
  const step = e.shiftKey ? 1 : 5;
  const moves = {
    ArrowUp: { lightTheta: lightTheta - step },
    ArrowDown: { lightTheta: lightTheta + step },
    ArrowLeft: { lightPhi: ((lightPhi + step + 540) % 360) - 180 },
    ArrowRight: { lightPhi: ((lightPhi - step + 540) % 360) - 180 },
  };
  return Object.hasOwn(moves, e.key) ? moves[e.key] : null;
}

/**
 * `get()`/`set(partial)` read and move the light; `active()` says whether the light matters to the picture now:
 * when it does not, the handle is hidden and drags and keys leave the light alone.
 */
export function attachLightControl(canvas, overlayParent, { get, set, active = () => true }) {
  const overlay = createOverlay(canvas, overlayParent, get, active);

  const fromPointer = (e) => {
    const rect = canvas.getBoundingClientRect();
    const dx = e.clientX - rect.left - rect.width / 2;
    const dy = rect.top + rect.height / 2 - e.clientY;
    const R = ringRadius(rect.width, rect.height);
    const theta = Math.min((Math.hypot(dx, dy) / R) * 90, 180);
    const phi = Math.atan2(dy, dx) / DEG;
    set({ lightTheta: Math.round(theta * 10) / 10, lightPhi: Math.round(phi * 10) / 10 });
  };

  let dragging = false;
  const up = (e) => {
    dragging = false;
    if (canvas.hasPointerCapture(e.pointerId)) canvas.releasePointerCapture(e.pointerId);
  };
  const listeners = {
    pointerdown(e) {
      if (e.button !== 0 || !active()) return;
      dragging = true;
      canvas.setPointerCapture(e.pointerId);
      fromPointer(e);
    },
    pointermove: (e) => dragging && fromPointer(e),
    pointerup: up,
    pointercancel: up,
    keydown(e) {
      const move = active() ? keyMove(e, get()) : null;
      if (!move) return;
      e.preventDefault();
      set(move);
    },
  };
  for (const [type, listener] of Object.entries(listeners)) canvas.addEventListener(type, listener);

  return {
    draw: overlay.draw,
    get dragging() {
      return dragging;
    },
    dispose() {
      for (const [type, listener] of Object.entries(listeners)) canvas.removeEventListener(type, listener);
      overlay.remove();
    },
  };
}
