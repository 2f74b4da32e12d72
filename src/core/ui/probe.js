// The probe of a 3-D view: point at the surface and read the angles there and the value of each term.
import * as THREE from 'three';
import { TO_DEGREES } from '../../math/angles.js';

/** Angles at a surface point, all in view space: n, l, v unit vectors (arrays). */
export function probeAngles(n, l, v) {
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const hs = [l[0] + v[0], l[1] + v[1], l[2] + v[2]];
  const len = Math.hypot(...hs);
  const h = len > 1e-9 ? hs.map((x) => x / len) : n; // l = -v: no half vector, fall back to n
  return { nv: dot(n, v), nl: dot(n, l), nh: dot(n, h), lh: dot(l, h) };
}

/** Fills a probe panel with [[label, text], ...] as a two-column table. */
export function showProbeRows(panel, rows) {
  const table = document.createElement('table');
  for (const [k, v] of rows) {
    const tr = table.insertRow();
    tr.insertCell().textContent = k;
    tr.insertCell().textContent = v;
  }
  panel.replaceChildren(table);
}

export const angleText = (c) =>
  `${c.toFixed(4)} (${(Math.acos(Math.min(Math.max(c, -1), 1)) * TO_DEGREES).toFixed(1)}°)`;

/**
 * A panel that follows the pointer over `canvas`, raycasts `getMesh()` seen by `getCamera()`, and shows
 * the rows `describe(normalInViewSpace)` returns: [[label, text], ...].
 */
export function attachProbe(canvas, parent, { getMesh, getCamera, describe, isBusy }) {
  const panel = document.createElement('div');
  panel.className = 'probe';
  panel.setAttribute('aria-live', 'off');
  const idle = 'Probe: point at (or tap) the surface to read the angles and terms there.';
  panel.textContent = idle;
  parent.append(panel);
  const raycaster = new THREE.Raycaster();
  const ndc = new THREE.Vector2();
  const normal = new THREE.Vector3();
  const normalMatrix = new THREE.Matrix3();

  let last = null; // the point last read ([n, v] in view space), read again by refresh()
  const move = (e) => {
    if (isBusy?.()) return;
    const rect = canvas.getBoundingClientRect();
    ndc.set(((e.clientX - rect.left) / rect.width) * 2 - 1, -((e.clientY - rect.top) / rect.height) * 2 + 1);
    const camera = getCamera();
    raycaster.setFromCamera(ndc, camera);
    const hit = raycaster.intersectObject(getMesh(), false)[0];
    if (!hit?.normal) {
      panel.textContent = idle;
      last = null;
      return;
    }
    normalMatrix.getNormalMatrix(camera.matrixWorldInverse.clone().multiply(hit.object.matrixWorld));
    normal.copy(hit.normal).applyMatrix3(normalMatrix).normalize();
    const viewPos = hit.point.clone().applyMatrix4(camera.matrixWorldInverse);
    const v = camera.isOrthographicCamera ? [0, 0, 1] : viewPos.clone().negate().normalize().toArray();
    last = [normal.toArray(), v];
    showProbeRows(panel, describe(...last));
  };
  // phones have no hover: a tap (touch or pen) probes where it lands, and the reading stays when the finger lifts
  const tap = (e) => e.pointerType !== 'mouse' && move(e);
  const leave = (e) => {
    if (e.pointerType !== 'mouse') return;
    panel.textContent = idle;
    last = null;
  };
  canvas.addEventListener('pointermove', move);
  canvas.addEventListener('pointerup', tap);
  canvas.addEventListener('pointerleave', leave);
  return {
    /** Reads the same point again: after the state changed (the light moved), the rows follow it. */
    refresh: () => last && showProbeRows(panel, describe(...last)),
    dispose() {
      canvas.removeEventListener('pointermove', move);
      canvas.removeEventListener('pointerup', tap);
      canvas.removeEventListener('pointerleave', leave);
      panel.remove();
    },
  };
}
