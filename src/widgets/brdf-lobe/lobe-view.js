// The BRDF as a 3-D lobe over a surface patch: for the current light, each direction v is pushed out by
// f(l, v) (scaled to the largest value); A is solid orange, B a green wire grid, as in the polar plot. Drag to
// orbit. n, l, v, h and the mirror direction are drawn as arrows, in the plane of incidence (a translucent pane);
// the plane turns about n from the tangent t (a dark red arrow fixed on the patch) to the light's azimuth, and
// everything in it turns with it (the model computes in the plane's frame: azimuths.js); the view may stand off it.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { createViewport } from '../../core/framework/viewport.js';
import { describeCanvas } from '../../core/framework/describe.js';

const THETA_STEPS = 45;
const PHI_STEPS = 96;

/** Directions of the hemisphere grid, local frame (n = z). */
function hemisphereDirections() {
  const dirs = [];
  for (let i = 0; i <= THETA_STEPS; i++) {
    const t = (i / THETA_STEPS) * (Math.PI / 2);
    for (let j = 0; j <= PHI_STEPS; j++) {
      const p = (j / PHI_STEPS) * 2 * Math.PI;
      dirs.push([Math.sin(t) * Math.cos(p), Math.sin(t) * Math.sin(p), Math.cos(t)]);
    }
  }
  return dirs;
}

function gridIndex() {
  const idx = [];
  const row = PHI_STEPS + 1;
  for (let i = 0; i < THETA_STEPS; i++) {
    for (let j = 0; j < PHI_STEPS; j++) {
      const a = i * row + j;
      idx.push(a, a + row, a + 1, a + 1, a + row, a + row + 1);
    }
  }
  return idx;
}

const RING_EVERY = 3; // lobe B's wires: every third ring of constant θ and every fourth meridian of the grid
const MERIDIAN_EVERY = 4;

/** Lobe B's wire grid over the hemisphere grid's vertices: rings and meridians, as line segments. */
function wireIndex() {
  const idx = [];
  const row = PHI_STEPS + 1;
  for (let i = RING_EVERY; i <= THETA_STEPS; i += RING_EVERY)
    for (let j = 0; j < PHI_STEPS; j++) idx.push(i * row + j, i * row + j + 1);
  for (let j = 0; j < PHI_STEPS; j += MERIDIAN_EVERY)
    for (let i = 0; i < THETA_STEPS; i++) idx.push(i * row + j, (i + 1) * row + j);
  return idx;
}

const ARROW_COLORS = { n: '#333333', l: '#e6a700', v: '#0072b2', h: '#cc79a7', mirror: '#888888' };
const TANGENT_COLOR = '#8b1a1a';

/** The plane of incidence: a translucent pane through n along x (the plane's frame), above the patch. */
function incidencePlane() {
  const pane = new THREE.Mesh(
    new THREE.PlaneGeometry(2.5, 1.25),
    new THREE.MeshBasicMaterial({ color: '#0072b2', transparent: true, opacity: 0.12, side: THREE.DoubleSide }),
  );
  pane.rotation.x = Math.PI / 2; // the xy pane stood up into xz
  pane.position.z = 0.625;
  return pane;
}

/** The scene: lights, the surface patch, lobe A (solid) and B (wireframe) over `dirs`, and the arrows. */
function createLobeScene(dirs) {
  const makeGeometry = () => {
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(new Float32Array(dirs.length * 3), 3));
    g.setIndex(gridIndex());
    return g;
  };
  const scene = new THREE.Scene();
  scene.background = new THREE.Color('#f4f5f7');
  const local = new THREE.Group(); // local frame n = z shown with three's y up
  local.rotation.x = -Math.PI / 2;
  scene.add(local, new THREE.HemisphereLight('#ffffff', '#888888', 2.2), new THREE.AmbientLight('#ffffff', 0.6));
  const sun = new THREE.DirectionalLight('#ffffff', 1.5);
  sun.position.set(2, 4, 3);
  scene.add(sun);

  const patch = new THREE.Mesh(
    new THREE.CircleGeometry(1.25, 64),
    new THREE.MeshLambertMaterial({ color: '#c8ccd2', side: THREE.DoubleSide }),
  );
  const lobeA = new THREE.Mesh(
    makeGeometry(),
    new THREE.MeshLambertMaterial({ color: '#d55e00', side: THREE.DoubleSide }),
  );
  const wire = makeGeometry();
  wire.setIndex(wireIndex());
  const lobeB = new THREE.LineSegments(
    wire,
    new THREE.LineBasicMaterial({ color: '#009e73', transparent: true, opacity: 0.7 }),
  );
  const plane = new THREE.Group(); // the plane of incidence's frame, turned by φ about n
  const pane = incidencePlane();
  plane.add(lobeA, lobeB, pane);
  const tangent = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 1.45, TANGENT_COLOR, 0.1);
  local.add(patch, plane, tangent);
  const arrows = {};
  for (const [key, color] of Object.entries(ARROW_COLORS)) {
    arrows[key] = new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(), 1.3, color, 0.1, 0.06);
    plane.add(arrows[key]);
  }
  return { scene, patch, lobeA, lobeB, arrows, plane, pane, tangent };
}

/** The keyboard orbits as a drag does: ←/→ around the normal, ↑/↓ up and down (Shift: finer). */
function keyOrbit(camera, controls) {
  const spherical = new THREE.Spherical();
  const offset = new THREE.Vector3();
  return (e) => {
    const step = (e.shiftKey ? 2 : 10) * (Math.PI / 180);
    const turn = { ArrowLeft: [-step, 0], ArrowRight: [step, 0], ArrowUp: [0, -step], ArrowDown: [0, step] }[e.key];
    if (!turn) return;
    e.preventDefault();
    spherical.setFromVector3(offset.copy(camera.position).sub(controls.target));
    spherical.theta += turn[0];
    spherical.phi = Math.min(Math.max(spherical.phi + turn[1], 0.05), Math.PI - 0.05);
    camera.position.copy(controls.target).add(offset.setFromSpherical(spherical));
    controls.update();
  };
}

/** Pushes each vertex of `mesh` out along its direction by f(direction) / max. */
function fillLobe(mesh, dirs, f, max) {
  const pos = mesh.geometry.attributes.position;
  dirs.forEach((d, i) => {
    const r = f(d) / max;
    pos.setXYZ(i, d[0] * r, d[1] * r, d[2] * r);
  });
  pos.needsUpdate = true;
  if (mesh.isMesh) mesh.geometry.computeVertexNormals(); // lines (lobe B) are unlit
  mesh.geometry.computeBoundingSphere();
}

/** options.onContextChange(): the view's WebGL context was lost or has come back (its renderer with it). */
export function createLobeView(container, { onContextChange } = {}) {
  const dirs = hemisphereDirections();
  let lost = false;
  const { scene, patch, lobeA, lobeB, arrows, plane, pane, tangent } = createLobeScene(dirs);
  const camera = new THREE.PerspectiveCamera(35, 1, 0.1, 50);
  camera.position.set(2.6, 2.2, 3.2);
  let controls = null;
  let orbitByKey = null;
  let scale = 1; // the value a lobe's radius 1 stands for
  const viewport = createViewport(container, {
    draw: (renderer) => {
      if (lost) {
        lost = false;
        onContextChange?.();
      }
      renderer.render(scene, camera);
    },
    onContextLost: () => {
      lost = true;
      onContextChange?.();
    },
    onResize: (w, h) => {
      camera.aspect = w / h;
      camera.updateProjectionMatrix();
    },
    label: 'BRDF lobe in 3-D',
    antialias: 'settled', // multisampling doubles its frame on software WebGL: a drag's frames go without
  });
  if (viewport) {
    controls = new OrbitControls(camera, viewport.canvas);
    controls.target.set(0, 0.35, 0);
    controls.update();
    controls.addEventListener('change', viewport.invalidate);
    orbitByKey = keyOrbit(camera, controls);
    viewport.canvas.addEventListener('keydown', orbitByKey);
  }

  return {
    /** The view directions the lobes are evaluated at (local frame), for a caller that scales to their maximum. */
    directions: dirs,
    canvas: viewport?.canvas ?? null,
    /** The view's three.js renderer (null without WebGL2), also the one user-written terms are evaluated with. */
    renderer: viewport?.renderer ?? null,
    /**
     * fA(v), fB(v) | null: the lobes for the current light; directions: { n, l, v, h, mirror } as arrays (h may
     * be null), in the plane of incidence's frame; phi: its x axis' azimuth from the tangent (°); description: the
     * view in words.
     */
    update({ fA, fB, max, directions, phi = 0, description }) {
      describeCanvas(viewport?.canvas, description);
      plane.rotation.z = (phi * Math.PI) / 180;
      scale = max;
      fillLobe(lobeA, dirs, fA, max);
      lobeB.visible = Boolean(fB);
      if (fB) fillLobe(lobeB, dirs, fB, max);
      for (const [key, d] of Object.entries(directions)) {
        arrows[key].visible = Boolean(d);
        if (d) arrows[key].setDirection(new THREE.Vector3(...d).normalize());
      }
      viewport?.invalidate();
    },
    /**
     * For tests, what is drawn, in the patch's frame (n = z, x along t): each vertex of lobe A as its direction and
     * its distance from the centre times the scale, and the arrows' directions.
     */
    drawn() {
      const pos = lobeA.geometry.attributes.position;
      const inPatch = (w) => w.applyEuler(plane.rotation).toArray();
      const lobe = dirs.map((d, i) => ({
        dir: inPatch(new THREE.Vector3(...d)),
        value: new THREE.Vector3().fromBufferAttribute(pos, i).length() * scale,
      }));
      const shown = Object.entries(arrows).filter(([, a]) => a.visible);
      return {
        lobe,
        arrows: Object.fromEntries(
          shown.map(([k, a]) => [k, inPatch(new THREE.Vector3(0, 1, 0).applyQuaternion(a.quaternion))]),
        ),
      };
    },
    dispose() {
      controls?.dispose();
      viewport?.canvas.removeEventListener('keydown', orbitByKey);
      [patch, lobeA, lobeB, pane].forEach((m) => {
        m.geometry.dispose();
        m.material.dispose();
      });
      [...Object.values(arrows), tangent].forEach((a) => a.dispose());
      viewport?.dispose();
    },
  };
}
