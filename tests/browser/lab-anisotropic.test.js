// The material lab's anisotropic lobe (issue 28), in Chromium, against float64 integrals computed here: GGX
// stretched by (αx, αy) along a tangent field written out again in lab-aniso-truth.js (circles around a pole:
// b = axis × n, t = b × n, turned by the rotation), with the height-correlated anisotropic Smith V and F = 1, the
// specular layer alone.
// - the punctual light: the approximation (exact for it) against π f c_light (n·l) at sphere points;
// - the sphere light: the converged Monte Carlo reference against ∫ over the light's cone of f (n·l) L dω;
// - the white furnace: the reference against the directional albedo ∫ f (n·l) dω over the hemisphere.
// Each truth is also computed for the isotropic lobe at α, and the test asserts that it is far outside the
// tolerance, so the test tells the stretched lobe from the isotropic one.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { launchBrowser, open, widget } from './helpers.js';
import { anisotropicAlphas } from '../../src/math/anisotropic.js';
import {
  DEG,
  RES,
  TEXELS,
  blockMean,
  cross,
  frameAround,
  lobeCos,
  normalAt,
  spherical,
  unit,
} from './lab-aniso-truth.js';

const ALPHA = 0.25;
const A = 0.8; // the anisotropy, Burley's mapping
const POLE = { theta: 50, phi: 90 };
const ROTATION = 20; // degrees
const BASE =
  `lab.material=custom&lab.f0=1&lab.fresnel=one&lab.layers=specular&lab.alpha=${ALPHA}&lab.anisotropy=${A}` +
  `&lab.anisotropyModel=burley2012&lab.tangentField=around&lab.tangentTheta=${POLE.theta}` +
  `&lab.tangentPhi=${POLE.phi}&lab.tangentRotation=${ROTATION}&lab.ambient=0`;

/** The frame (t, b, n) of the brushing around the pole, turned by ROTATION about n. */
const frameAt = frameAround(POLE, ROTATION);

/** ∫ over the cone of half-angle asin(sin) about `dir` of g(l) dω, by the midpoint rule in (cos θ, φ). */
function coneIntegral(dir, sin, g, [nc, np] = [160, 320]) {
  const cosMax = Math.sqrt(1 - sin * sin);
  const e1 = unit(cross(Math.abs(dir[2]) < 0.9 ? [0, 0, 1] : [1, 0, 0], dir));
  const e2 = cross(dir, e1);
  let sum = 0;
  for (let a = 0; a < nc; a++) {
    const c = 1 - ((a + 0.5) / nc) * (1 - cosMax);
    const s = Math.sqrt(1 - c * c);
    for (let b = 0; b < np; b++) {
      const phi = ((b + 0.5) / np) * 2 * Math.PI;
      const l = [0, 1, 2].map((k) => c * dir[k] + s * (Math.cos(phi) * e1[k] + Math.sin(phi) * e2[k]));
      sum += g(l);
    }
  }
  return (sum * (1 - cosMax) * 2 * Math.PI) / (nc * np);
}

const PAIR = anisotropicAlphas(ALPHA, A, 'burley2012');
const ISO = [ALPHA, ALPHA];

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

/** Opens the lab at `query` and waits for its reference to converge; returns its float images' reader. */
async function lab(query) {
  const page = await open(browser, `rendering.html?${query}`, { width: 1200, height: 900 });
  await widget(page, 'lab');
  await page.waitForFunction(
    () => {
      const p = globalThis.__shadingLab.widgets.lab.getProgress();
      return p.frame >= p.target;
    },
    { timeout: 240_000, polling: 500 },
  );
  /** The red channel of image `which`, averaged over the 3 × 3 texels around each of `texels`. */
  const read = (which, texels) =>
    page.evaluate(
      (which, texels, res) => {
        const image = globalThis.__shadingLab.widgets.lab.read(which);
        return texels.map(([i, j]) => {
          let sum = 0;
          for (let dj = -1; dj <= 1; dj++) for (let di = -1; di <= 1; di++) sum += image[((j + dj) * res + i + di) * 4];
          return sum / 9;
        });
      },
      which,
      texels,
      RES,
    );
  return { page, read };
}

const CONVERGE_MS = 300_000;

describe('material lab: anisotropic GGX along a tangent field, against float64 integrals', () => {
  it('punctual light: the approximation is π f c_light (n·l) of the stretched lobe (3e-3 relative)', async () => {
    const light = { theta: 40, phi: 20 };
    const l = spherical(light.theta, light.phi);
    const { page, read } = await lab(
      `${BASE}&lab.env=0&lab.area=0&lab.punctual=1&lab.lightTheta=${light.theta}&lab.lightPhi=${light.phi}` +
        '&lab.cLight=1&lab.refSamples=128',
    );
    const got = await read('approx', TEXELS);
    const truth = (pair) => TEXELS.map((t) => blockMean(t, (x) => Math.PI * lobeCos(frameAt(normalAt(x)), l, pair)));
    const [want, iso] = [truth(PAIR), truth(ISO)];
    console.log(`punctual: lab ${got.map((x) => x.toFixed(4))}; float64 ${want.map((x) => x.toFixed(4))}`);
    got.forEach((x, k) => expect(Math.abs(x - want[k])).toBeLessThan(3e-3 * want[k] + 2e-4));
    expect(want.some((x, k) => Math.abs(x - iso[k]) > 0.1 * x)).toBe(true); // the isotropic lobe would fail
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it(
    'sphere light: the converged reference is ∫cone f (n·l) L dω of the stretched lobe (within 4 %)',
    async () => {
      const light = { theta: 30, phi: 150, radius: 8 };
      const { page, read } = await lab(
        `${BASE}&lab.env=0&lab.punctual=0&lab.area=1&lab.areaTheta=${light.theta}&lab.areaPhi=${light.phi}` +
          `&lab.areaRadius=${light.radius}&lab.areaCLight=1&lab.refSamples=512`,
      );
      const got = await read('reference', TEXELS);
      const sin = Math.sin(light.radius * DEG);
      const radiance = 1 / (sin * sin); // c_light kept as the radius changes (lab-scene.js)
      const dir = spherical(light.theta, light.phi);
      const truth = (pair) =>
        TEXELS.map((t) =>
          blockMean(t, (x) => {
            const frame = frameAt(normalAt(x));
            return radiance * coneIntegral(dir, sin, (ld) => lobeCos(frame, ld, pair), [24, 48]);
          }),
        );
      const [want, iso] = [truth(PAIR), truth(ISO)];
      console.log(`sphere light: reference ${got.map((x) => x.toFixed(4))}; float64 ${want.map((x) => x.toFixed(4))}`);
      got.forEach((x, k) => expect(Math.abs(x - want[k])).toBeLessThan(0.04 * want[k] + 2e-3));
      expect(want.some((x, k) => Math.abs(x - iso[k]) > 0.15 * x + 2e-3)).toBe(true);
      expect(page.errors).toEqual([]);
      await page.close();
    },
    CONVERGE_MS,
  );

  it(
    'white furnace: the converged reference is the lobe’s albedo ∫ f (n·l) dω at each point (within 2 %)',
    async () => {
      const { page, read } = await lab(`${BASE}&lab.env=1&lab.environment=furnace&lab.punctual=0&lab.refSamples=128`);
      const got = await read('reference', TEXELS);
      // the hemisphere around n as a cone of half-angle 90°: within 4e-4 of a 900 × 1800 grid for αy = 0.13
      const albedo = (pair) => (t) => {
        const n = normalAt(t);
        const frame = frameAt(n);
        return coneIntegral(n, 1, (l) => lobeCos(frame, l, pair), [150, 300]);
      };
      const [want, iso] = [PAIR, ISO].map((pair) => TEXELS.map(albedo(pair))); // smooth: the block's centre
      console.log(`furnace: reference ${got.map((x) => x.toFixed(4))}; float64 ${want.map((x) => x.toFixed(4))}`);
      got.forEach((x, k) => expect(Math.abs(x - want[k])).toBeLessThan(0.02 * want[k] + 2e-3));
      expect(want.some((x, k) => Math.abs(x - iso[k]) > 0.06 * x)).toBe(true);
      expect(page.errors).toEqual([]);
      await page.close();
    },
    CONVERGE_MS,
  );
});
