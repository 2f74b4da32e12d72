// fresnel-zones, the 3-D view: the shape under the light, drawn by one program per set of switches (made on
// first use and kept), seen by an orthographic or a perspective camera that keeps the unit sphere in frame.
import * as THREE from 'three';
import { createProgramCache } from '../../core/gpu/program-cache.js';
import { buildShader } from '../../core/gpu/shader-builder.js';
import { DEG, TO_DEGREES } from '../../math/angles.js';
import { programDefines, uniformValues } from './model.js';
import { createShapeGeometry } from './shapes.js';

const HALF = 1.1; // half the shorter side of the view, in scene units: the unit sphere and a margin
const FOV_DEG = 30; // the perspective camera's field across the shorter side

function createCameras() {
  const cameras = {
    orthographic: new THREE.OrthographicCamera(),
    perspective: new THREE.PerspectiveCamera(FOV_DEG, 1, 0.1, 20),
  };
  cameras.perspective.position.set(0, 0, HALF / Math.sin((FOV_DEG / 2) * DEG));
  cameras.orthographic.position.set(0, 0, 5);
  return cameras;
}

/** Frames the unit sphere, with a margin, across the shorter side of a w × h view. */
function fitCameras({ orthographic: o, perspective: p }, w, h) {
  const aspect = w / h;
  [o.left, o.right, o.top, o.bottom] =
    aspect >= 1 ? [-HALF * aspect, HALF * aspect, HALF, -HALF] : [-HALF, HALF, HALF / aspect, -HALF / aspect];
  o.near = 0.1;
  o.far = 10;
  o.updateProjectionMatrix();
  p.aspect = aspect;
  p.fov = aspect >= 1 ? FOV_DEG : 2 * Math.atan(Math.tan((FOV_DEG / 2) * DEG) / aspect) * TO_DEGREES;
  p.updateProjectionMatrix();
}

function createUniforms() {
  return {
    uLightDir: { value: new THREE.Vector3() },
    uEta: { value: new THREE.Vector3() },
    uK: { value: new THREE.Vector3() },
    uF0: { value: new THREE.Vector3() },
    uAlphaPair: { value: new THREE.Vector2(0.3, 0.3) },
    uExposure: { value: 1 },
    uZoneColors: { value: [new THREE.Color(), new THREE.Color(), new THREE.Color()] },
  };
}

function setUniforms(uniforms, values) {
  uniforms.uLightDir.value.set(...values.lightDir);
  uniforms.uEta.value.set(...values.eta);
  uniforms.uK.value.set(...values.k);
  uniforms.uF0.value.set(...values.f0);
  uniforms.uAlphaPair.value.set(values.alpha, values.alpha); // the microfacet input's α pair, isotropic
  uniforms.uExposure.value = values.exposure;
  values.zoneColors.forEach((rgb, i) => uniforms.uZoneColors.value[i].setRGB(...rgb));
}

/** The view of the state `getState()` returns: `render` draws the picture, `renderStats` the zones to sum. */
export function createZonesScene(getState) {
  const uniforms = createUniforms();
  const programs = createProgramCache((defines) =>
    buildShader('fresnel-zones.frag.glsl', { vertex: 'surface.vert.glsl', uniforms, defines }),
  );
  const scene = new THREE.Scene();
  scene.background = new THREE.Color('#22252b');
  const mesh = new THREE.Mesh(createShapeGeometry(getState().shape), undefined);
  scene.add(mesh);
  const cameras = createCameras();
  const camera = () => cameras[getState().camera];
  return {
    mesh,
    camera,
    fit: (w, h) => fitCameras(cameras, w, h),
    setShape(name) {
      mesh.geometry.dispose();
      mesh.geometry = createShapeGeometry(name);
    },
    /** Puts the state into the uniforms; `lightFrom(direction)` then moves only the light (a unit vector). */
    applyState: () => setUniforms(uniforms, uniformValues(getState())),
    lightFrom: (direction) => uniforms.uLightDir.value.set(...direction),
    render(renderer) {
      mesh.material = programs.get(programDefines(getState(), false));
      renderer.render(scene, camera());
    },
    /** Draws the one-hot zone coverage into `target`, on a transparent background, for the GPU sum. */
    renderStats(renderer, target) {
      mesh.material = programs.get(programDefines(getState(), true));
      const background = scene.background;
      scene.background = null;
      renderer.setRenderTarget(target);
      renderer.setClearColor(0x000000, 0);
      renderer.clear();
      renderer.render(scene, camera());
      renderer.setRenderTarget(null);
      scene.background = background;
    },
    programInfo: () => ({ variants: programs.size, fragmentShader: mesh.material?.fragmentShader ?? '' }),
    dispose() {
      programs.dispose();
      mesh.geometry.dispose();
    },
  };
}
