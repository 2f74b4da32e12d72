// MaterialX's own shader for OpenPBR Surface against the app's evaluation of the same materials.
// scripts/materialx-shaders.py has MaterialX (PyPI `materialx`, installed by .ci/run) generate GLSL ES 3.00 from the
// specification's reference node graph, with one directional light and no environment. Here that fragment shader
// runs unchanged in Chromium: each sample is one point (one pixel) whose vertex hands it a view direction, the
// light is the shader's u_lightData[0], and the radiance is read back from a float target. It is compared with
// the app's float64 BRDF at the same (l, v): L = f (n·l) E for a light of irradiance E = 1. docs/accuracy.md says
// the tolerance and the figures ("OpenPBR against MaterialX").
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, rmSync, writeFileSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { launchBrowser } from './harness.js';
import { MATERIALX_MATERIALS } from '../support/materialx-materials.js';
import { materialxPython, MATERIALX_MISSING } from '../support/materialx-python.js';
import { DEG } from '../../src/math/angles.js';
import { openPbrBaseBRDF } from '../support/openpbr-base.js';
import { openPbrBRDF } from '../../src/math/openpbr.js';

const python = materialxPython();
if (!python) console.warn(`materialx.test.js skipped: ${MATERIALX_MISSING}`);

// The references. The base-only materials: the catalogue's terms composed as MaterialX composes them
// (tests/support/openpbr-base.js), Turquin's multiple-scattering compensation included. The coated and fuzzy
// ones (over smooth bases): the app's openPbrBRDF (src/math/openpbr.js).
// openPbrBRDF is single-scattering, the talk's model: against MaterialX it differs by up to 25 % on the rough metal
// for that reason alone, so the base-only materials stay on the composition.
const baseReference = openPbrBaseBRDF;
const layeredReference = openPbrBRDF;

/** Light directions (in the plane xz, from the normal) and view directions: θv 0…85° by 5°, φ 0…180° by 22.5°. */
const LIGHTS = [0, 30, 60, 75].map((t) => [Math.sin(t * DEG), 0, Math.cos(t * DEG)]);
const VIEWS = Array.from({ length: 18 }, (_, i) => i * 5 * DEG).flatMap((t) =>
  Array.from({ length: 9 }, (_, j) => j * 22.5 * DEG).map((p) => [
    Math.sin(t) * Math.cos(p),
    Math.sin(t) * Math.sin(p),
    Math.cos(t),
  ]),
);

/**
 * The relative tolerance, per channel, against the larger of the reference and a floor of 1 % of the material's
 * brightest sample (so that a near-black sample is held to an absolute 1 % of the picture's scale).
 */
const MATERIALX_TOLERANCE = 0.04;
const FLOOR = 0.01;

/** Renders every material under every light in the page: one row of points per light, RGBA32F, read back. */
async function renderInPage(page, generated) {
  return page.evaluate(
    ({ materials, lights, views, lightType }) => {
      const vertex = `#version 300 es
        in vec3 a_view;
        in float a_index;
        uniform float u_row, u_rows, u_columns;
        out vec3 normalWorld;
        out vec3 tangentWorld;
        out vec3 positionWorld;
        void main() {
          normalWorld = vec3(0.0, 0.0, 1.0);
          tangentWorld = vec3(1.0, 0.0, 0.0);
          positionWorld = -a_view; // u_viewPosition is 0, so V = normalize(0 - positionWorld) = a_view
          gl_Position = vec4((a_index + 0.5) / u_columns * 2.0 - 1.0, (u_row + 0.5) / u_rows * 2.0 - 1.0, 0.0, 1.0);
          gl_PointSize = 1.0;
        }`;
      const canvas = document.createElement('canvas');
      const gl = canvas.getContext('webgl2');
      if (!gl || !gl.getExtension('EXT_color_buffer_float')) return { error: 'no WebGL2 float render target' };
      const compile = (type, source) => {
        const s = gl.createShader(type);
        gl.shaderSource(s, source);
        gl.compileShader(s);
        if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
        return s;
      };
      const [w, h] = [views.length, lights.length];
      const texture = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA32F, w, h);
      const fbo = gl.createFramebuffer();
      gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
      gl.viewport(0, 0, w, h);
      const buffer = gl.createBuffer();
      gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
      gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(views.flatMap((v, i) => [...v, i])), gl.STATIC_DRAW);
      const programs = new Map(); // fragment text → program: the inputs are uniforms, so one text serves all
      const link = (fragment) => {
        const program = gl.createProgram();
        gl.attachShader(program, compile(gl.VERTEX_SHADER, vertex));
        gl.attachShader(program, compile(gl.FRAGMENT_SHADER, fragment));
        gl.linkProgram(program);
        if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(program));
        return program;
      };
      return materials.map(({ name, fragment, uniforms }) => {
        if (!programs.has(fragment)) programs.set(fragment, link(fragment));
        const program = programs.get(fragment);
        gl.useProgram(program);
        const types = new Map();
        for (let i = 0; i < gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS); i++) {
          const u = gl.getActiveUniform(program, i);
          types.set(u.name, u.type);
        }
        const set = (key, value) => {
          const at = gl.getUniformLocation(program, key);
          if (!at) return;
          const type = types.get(key);
          if (type === gl.FLOAT_VEC3) gl.uniform3fv(at, value);
          else if (type === gl.FLOAT) gl.uniform1f(at, value);
          else gl.uniform1i(at, Number(value)); // int, bool
        };
        Object.entries(uniforms).forEach(([key, value]) => set(key, value));
        set('u_viewPosition', [0, 0, 0]);
        set('u_numActiveLightSources', 1);
        set('u_lightData[0].type', lightType);
        set('u_lightData[0].color', [1, 1, 1]);
        set('u_lightData[0].intensity', 1);
        set('u_columns', w);
        set('u_rows', h);
        const stride = 16;
        const view = gl.getAttribLocation(program, 'a_view');
        const index = gl.getAttribLocation(program, 'a_index');
        gl.enableVertexAttribArray(view);
        gl.vertexAttribPointer(view, 3, gl.FLOAT, false, stride, 0);
        gl.enableVertexAttribArray(index);
        gl.vertexAttribPointer(index, 1, gl.FLOAT, false, stride, 12);
        gl.clearColor(-1, -1, -1, -1);
        gl.clear(gl.COLOR_BUFFER_BIT);
        lights.forEach((l, row) => {
          set(
            'u_lightData[0].direction',
            l.map((x) => -x),
          ); // the light travels along -l
          set('u_row', row);
          gl.drawArrays(gl.POINTS, 0, w);
        });
        const out = new Float32Array(w * h * 4);
        gl.readPixels(0, 0, w, h, gl.RGBA, gl.FLOAT, out);
        return { name, radiance: Array.from(out) };
      });
    },
    { ...generated, lights: LIGHTS, views: VIEWS },
  );
}

/** Per material: the worst relative error (see MATERIALX_TOLERANCE) and where, against `brdf`. */
function compare(material, radiance, brdf) {
  const samples = LIGHTS.flatMap((l, row) =>
    VIEWS.map((v, i) => {
      const f = brdf(l, v, material.inputs);
      return {
        l,
        v,
        ref: f.map((x) => x * l[2]),
        got: radiance.slice(4 * (row * VIEWS.length + i), 4 * (row * VIEWS.length + i) + 3),
      };
    }),
  );
  const peak = Math.max(...samples.flatMap((s) => s.ref));
  let worst = { error: 0 };
  for (const s of samples) {
    for (let c = 0; c < 3; c++) {
      const error = Math.abs(s.got[c] - s.ref[c]) / Math.max(s.ref[c], FLOOR * peak);
      if (!(error <= worst.error)) worst = { error, channel: c, ...s };
    }
  }
  return worst;
}

describe.skipIf(!python)('OpenPBR Surface against MaterialX 1.39.5 (its reference graph, its GLSL ES)', () => {
  let browser;
  let rendered;
  let dir;

  beforeAll(async () => {
    dir = mkdtempSync(join(tmpdir(), 'materialx-'));
    writeFileSync(join(dir, 'materials.json'), JSON.stringify(MATERIALX_MATERIALS));
    execFileSync(python, ['scripts/materialx-shaders.py', join(dir, 'materials.json'), '--out', join(dir, 'out.json')]);
    const generated = JSON.parse(readFileSync(join(dir, 'out.json'), 'utf8'));
    browser = await launchBrowser();
    const page = await browser.newPage();
    const out = await renderInPage(page, { materials: generated.materials, lightType: generated.lightType });
    if (out.error) throw new Error(out.error);
    rendered = new Map(out.map((m) => [m.name, m.radiance]));
    // SwiftShader compiles the 2100-line shader at its first draw: about 50 s at a load average of 26 (one program
    // for every material), hence the longer wait than the suite's 120 s for a hook
  }, 400_000);

  afterAll(async () => {
    await browser?.close();
    if (dir && existsSync(dir)) rmSync(dir, { recursive: true, force: true });
  });

  for (const material of MATERIALX_MATERIALS) {
    const title = `${material.name} (${material.source}) within ${MATERIALX_TOLERANCE * 100} %`;
    const reference = material.layers.length ? layeredReference : baseReference;
    it(title, () => {
      const worst = compare(material, rendered.get(material.name), reference);
      expect(worst.error, where(worst)).toBeLessThan(MATERIALX_TOLERANCE);
    });
  }

  // The check can fail: MaterialX compensates the lobes' multiple scattering (Turquin 2019), and the talk's
  // single-scattering model without it is 25 % darker on a rough metal (measured 25.2 %).
  it("rough-aluminium without Turquin's compensation is more than 10 % off: MaterialX compensates", () => {
    const material = MATERIALX_MATERIALS.find((m) => m.name === 'rough-aluminium');
    const singleScattering = (l, v, inputs) => openPbrBaseBRDF(l, v, inputs, { turquin: false });
    expect(compare(material, rendered.get(material.name), singleScattering).error).toBeGreaterThan(0.1);
  });
});

/** Where the worst sample is, in degrees: θl, θv, φv and the channel. */
const where = ({ l, v, channel }) =>
  `at θl ${Math.round(Math.acos(l[2]) / DEG)}°, θv ${Math.round(Math.acos(v[2]) / DEG)}°, ` +
  `φv ${Math.round(Math.atan2(v[1], v[0]) / DEG)}°, channel ${'rgb'[channel]}`;
