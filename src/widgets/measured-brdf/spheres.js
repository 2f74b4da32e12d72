// Spheres of tabulated BRDFs under one punctual light, side by side: the measured table and a fit tabulated
// the same way, each a 3-D texture (90 θh × 90 θd × 180 φd texels, RGBA half floats) read by measured.glsl, on a
// ray-traced impostor (sphere-impostor.js).
import * as THREE from 'three';
import { createViewport } from '../../core/framework/viewport.js';
import { drawSideBySide } from '../../core/ui/side-by-side.js';
import { buildShader } from '../../core/gpu/shader-builder.js';
import { createImpostorView } from '../../core/ui/sphere-impostor.js';
import { MERL_DIMS } from '../../measured/merl.js';

/** A table (RGBA half floats, MERL order) as the 3-D texture measured.glsl reads. */
export function tableTexture(half) {
  const [NH, ND, NP] = MERL_DIMS;
  const t = new THREE.Data3DTexture(half, NP, ND, NH);
  Object.assign(t, {
    format: THREE.RGBAFormat,
    type: THREE.HalfFloatType,
    minFilter: THREE.LinearFilter,
    magFilter: THREE.LinearFilter,
    wrapS: THREE.RepeatWrapping,
    wrapT: THREE.ClampToEdgeWrapping,
    wrapR: THREE.ClampToEdgeWrapping,
    unpackAlignment: 1,
    needsUpdate: true,
  });
  return t;
}

const BACKGROUND = '#16181d';

export function createMeasuredSpheres(container, { label }) {
  const slots = [null, null]; // { texture, name }
  const view = createImpostorView(BACKGROUND);
  const material = buildShader('measured-sphere.frag.glsl', {
    vertex: 'sphere-impostor.vert.glsl',
    uniforms: {
      uMeasured: { value: null },
      uLightDir: { value: new THREE.Vector3(0, 0, 1) },
      uExposure: { value: 1 },
      uBackground: { value: new THREE.Vector3(...view.background) },
    },
  });
  view.mesh.material = material;
  const names = document.createElement('div');
  names.className = 'sphere-labels';

  const draw = (renderer) =>
    drawSideBySide(renderer, slots.length, (i) => {
      if (slots[i]) {
        material.uniforms.uMeasured.value = slots[i].texture;
        renderer.render(view.scene, view.camera);
      } else {
        renderer.setClearColor(BACKGROUND);
        renderer.clear();
      }
    });
  const viewport = createViewport(container, {
    draw,
    label,
    antialias: false, // the spheres smooth their own silhouettes
    onContextLost: () => slots.forEach((s) => s && (s.texture.needsUpdate = true)),
  });
  if (viewport) {
    viewport.holder.classList.add('sphere-grid');
    viewport.holder.append(names);
  }
  const relabel = () => {
    names.replaceChildren(
      ...slots.map((s) => Object.assign(document.createElement('span'), { textContent: s?.name ?? '' })),
    );
  };

  return {
    canvas: viewport?.canvas ?? null,
    /** Puts a table (RGBA half floats, MERL order) into slot 0 (measured) or 1 (a fit), or empties the slot. */
    setTable(i, half, name) {
      slots[i]?.texture.dispose();
      slots[i] = half ? { texture: tableTexture(half), name } : null;
      relabel();
      viewport?.invalidate();
    },
    setLight(dir, exposure) {
      material.uniforms.uLightDir.value.set(...dir);
      material.uniforms.uExposure.value = exposure;
      viewport?.invalidate();
    },
    dispose() {
      slots.forEach((s) => s?.texture.dispose());
      material.dispose();
      view.dispose();
      viewport?.dispose();
    },
  };
}
