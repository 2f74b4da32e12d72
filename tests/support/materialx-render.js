// What the MaterialX comparison (tests/browser/materialx.test.js) and its bench part (bench/openpbr-materialx.js)
// share: MaterialX's own GLSL ES 3.00 for open_pbr_surface (scripts/materialx-shaders.py) and the app's GLSL
// (shaders/openpbr.glsl's openPbrBRDF), each run in Chromium over the same grid of light and view directions. Each
// sample is one point (one pixel of an RGBA32F target) whose vertex hands it a view direction (the normal is z, the
// tangent x); the light is a directional one of irradiance 1, so the value read back is L = f (n·l).
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { DEG } from '../../src/math/angles.js';
import { OPENPBR_DEFAULTS, openPbrMaterial } from '../../src/math/openpbr.js';
import { openPbrAlbedoTable } from '../../src/math/openpbr-albedo.js';

/** Light directions (in the plane xz, from the normal) and view directions: θv 0…85° by 5°, φ 0…180° by 22.5°. */
export const LIGHTS = [0, 30, 60, 75].map((t) => [Math.sin(t * DEG), 0, Math.cos(t * DEG)]);
export const VIEWS = Array.from({ length: 18 }, (_, i) => i * 5 * DEG).flatMap((t) =>
  Array.from({ length: 9 }, (_, j) => j * 22.5 * DEG).map((p) => [
    Math.sin(t) * Math.cos(p),
    Math.sin(t) * Math.sin(p),
    Math.cos(t),
  ]),
);

/**
 * The relative difference per channel is taken against the larger of the reference and a floor of 1 % of the
 * material's brightest sample, so that a near-black sample is held to an absolute 1 % of the picture's scale.
 */
export const FLOOR = 0.01;

/** MaterialX's shaders for `materials` ([{ name, inputs }]): scripts/materialx-shaders.py's JSON, parsed. */
export function generateMaterialx(python, materials, root = process.cwd()) {
  const dir = mkdtempSync(join(tmpdir(), 'materialx-'));
  try {
    writeFileSync(join(dir, 'materials.json'), JSON.stringify(materials.map(({ name, inputs }) => ({ name, inputs }))));
    const script = join(root, 'scripts/materialx-shaders.py');
    execFileSync(python, [script, join(dir, 'materials.json'), '--out', join(dir, 'out.json')]);
    return JSON.parse(readFileSync(join(dir, 'out.json'), 'utf8'));
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

/** MaterialX's programs: its light loop's one directional light, u_lightData[0], travelling along −l. */
export function materialxPrograms(generated) {
  return generated.materials.map(({ name, fragment, uniforms }) => ({
    name,
    fragment,
    uniforms: {
      ...uniforms,
      u_viewPosition: [0, 0, 0],
      u_numActiveLightSources: 1,
      'u_lightData[0].type': generated.lightType,
      'u_lightData[0].color': [1, 1, 1],
      'u_lightData[0].intensity': 1,
    },
    light: { name: 'u_lightData[0].direction', sign: -1 },
  }));
}

const KEYS = Object.keys(OPENPBR_DEFAULTS);
const FLOATS = KEYS.reduce((n, k) => n + (Array.isArray(OPENPBR_DEFAULTS[k]) ? 3 : 1), 0);

/** The app's fragment shader: openPbrBRDF at (l, v) times n·l, the material from a float array in KEYS' order. */
function appFragment(assembleGlsl) {
  let i = 0;
  const parts = KEYS.map((k) => {
    if (!Array.isArray(OPENPBR_DEFAULTS[k])) return `u_material[${i++}]`;
    i += 3;
    return `vec3(u_material[${i - 3}], u_material[${i - 2}], u_material[${i - 1}])`;
  });
  const main = `#include "openpbr.glsl"
in vec3 positionWorld;
uniform vec3 u_light;
uniform float u_material[${FLOATS}];
out vec4 fragColor;
void main() {
  vec3 v = normalize(-positionWorld);
  OpenPbrMaterial m = openPbrClamp(OpenPbrMaterial(${parts.join(', ')}));
  fragColor = vec4(openPbrBRDF(u_light, v, m) * max(u_light.z, 0.0), 1.0);
}`;
  return `#version 300 es\nprecision highp float;\nprecision highp int;\n${assembleGlsl(main)}`;
}

/**
 * The app's programs for `materials` ([{ name, inputs }]). `assembleGlsl`: src/core/gpu/glsl.js's, passed in, since
 * it reads the shaders through Vite (import.meta.glob), which a script in plain Node loads through Vite's runner.
 */
export function appPrograms(materials, assembleGlsl) {
  const fragment = appFragment(assembleGlsl);
  return materials.map(({ name, inputs }) => {
    const m = openPbrMaterial(inputs);
    return {
      name,
      fragment,
      uniforms: { u_material: KEYS.flatMap((k) => m[k]) },
      light: { name: 'u_light', sign: 1 },
    };
  });
}

/** The albedo table the app's shader reads (uOpenPbrAlbedo), as plain numbers for the page. */
const albedoTexture = () => {
  const { width, height, data } = openPbrAlbedoTable();
  return { name: 'uOpenPbrAlbedo', width, height, data: Array.from(data) };
};

/**
 * Renders every program under every light in `page`: one row of points per light, RGBA32F, read back. Returns a
 * Map name → radiance (RGBA per sample, the lights' rows one after another, VIEWS along each).
 */
export async function renderPrograms(page, programs) {
  const out = await page.evaluate(renderInPage, { programs, lights: LIGHTS, views: VIEWS, texture: albedoTexture() });
  if (out.error) throw new Error(out.error);
  return new Map(out.map((m) => [m.name, m.radiance]));
}

/** In the page: see renderPrograms. */
function renderInPage({ programs, lights, views, texture }) {
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
      positionWorld = -a_view; // the camera at 0 (u_viewPosition), so V = normalize(0 - positionWorld) = a_view
      gl_Position = vec4((a_index + 0.5) / u_columns * 2.0 - 1.0, (u_row + 0.5) / u_rows * 2.0 - 1.0, 0.0, 1.0);
      gl_PointSize = 1.0;
    }`;
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl || !gl.getExtension('EXT_color_buffer_float')) return { error: 'no WebGL2 float render target' };
  const compile = (type, source) => {
    const s = gl.createShader(type);
    gl.shaderSource(s, source);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
    return s;
  };
  const [w, h] = [views.length, lights.length];
  const target = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, target);
  gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA32F, w, h);
  gl.bindFramebuffer(gl.FRAMEBUFFER, gl.createFramebuffer());
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, target, 0);
  gl.viewport(0, 0, w, h);
  gl.activeTexture(gl.TEXTURE1); // the app's albedo table, on unit 1 (unit 0 holds the target)
  gl.bindTexture(gl.TEXTURE_2D, gl.createTexture());
  gl.texImage2D(
    gl.TEXTURE_2D,
    0,
    gl.RGBA32F,
    texture.width,
    texture.height,
    0,
    gl.RGBA,
    gl.FLOAT,
    new Float32Array(texture.data),
  );
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST); // no mipmaps: complete as it is
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  gl.activeTexture(gl.TEXTURE0);
  gl.bindBuffer(gl.ARRAY_BUFFER, gl.createBuffer());
  gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(views.flatMap((v, i) => [...v, i])), gl.STATIC_DRAW);
  const linked = new Map(); // fragment text → program: the inputs are uniforms, so one text serves all
  const link = (fragment) => {
    const program = gl.createProgram();
    gl.attachShader(program, compile(gl.VERTEX_SHADER, vertex));
    gl.attachShader(program, compile(gl.FRAGMENT_SHADER, fragment));
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(program));
    return program;
  };
  return programs.map(({ name, fragment, uniforms, light }) => {
    if (!linked.has(fragment)) linked.set(fragment, link(fragment));
    const program = linked.get(fragment);
    gl.useProgram(program);
    const types = new Map();
    for (let i = 0; i < gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS); i++) {
      const u = gl.getActiveUniform(program, i);
      types.set(u.name.replace(/\[0\]$/, ''), u);
    }
    const set = (key, value) => {
      const at = gl.getUniformLocation(program, key);
      if (!at) return;
      const { type, size } = types.get(key);
      if (type === gl.FLOAT_VEC3) gl.uniform3fv(at, value);
      else if (type === gl.FLOAT && size > 1) gl.uniform1fv(at, value);
      else if (type === gl.FLOAT) gl.uniform1f(at, value);
      else gl.uniform1i(at, Number(value)); // int, bool, a sampler's unit
    };
    Object.entries(uniforms).forEach(([key, value]) => set(key, value));
    set(texture.name, 1);
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
        light.name,
        l.map((x) => x * light.sign),
      );
      set('u_row', row);
      gl.drawArrays(gl.POINTS, 0, w);
    });
    const out = new Float32Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.FLOAT, out);
    return { name, radiance: Array.from(out) };
  });
}

/** The samples of one material: (l, v), the reference's radiance and the compared one's, RGB. */
export function samplesOf(reference, compared) {
  return LIGHTS.flatMap((l, row) => VIEWS.map((v, i) => ({ l, v, ref: reference(row, i), got: compared(row, i) })));
}

/** The radiance of sample (row, i) of a rendered program, RGB. */
export const radianceAt = (radiance) => (row, i) =>
  radiance.slice(4 * (row * VIEWS.length + i), 4 * (row * VIEWS.length + i) + 3);

/** The radiance f (n·l) of a JS BRDF at sample (row, i), RGB. */
export const brdfRadiance = (brdf, inputs) => (row, i) =>
  brdf(LIGHTS[row], VIEWS[i], inputs).map((x) => x * LIGHTS[row][2]);

/**
 * The relative differences of `samples` per channel (against the larger of the reference and FLOOR × its
 * brightest sample): the largest and the mean per channel, and where the largest of all is.
 */
export function relativeDifferences(samples) {
  const peak = Math.max(...samples.flatMap((s) => s.ref));
  const [max, sum] = [
    [0, 0, 0],
    [0, 0, 0],
  ];
  let worst = { error: 0 };
  for (const s of samples) {
    for (let c = 0; c < 3; c++) {
      const error = Math.abs(s.got[c] - s.ref[c]) / Math.max(s.ref[c], FLOOR * peak);
      sum[c] += error;
      max[c] = Math.max(max[c], error);
      if (!(error <= worst.error)) worst = { error, channel: c, l: s.l, v: s.v };
    }
  }
  return { max, mean: sum.map((x) => x / samples.length), worst, peak };
}

/** Where a sample is, in whole degrees: θl, θv, φv. */
export const anglesOf = ({ l, v }) => ({
  thetaL: Math.round(Math.acos(l[2]) / DEG),
  thetaV: Math.round(Math.acos(v[2]) / DEG),
  phiV: Math.round(Math.atan2(v[1], v[0]) / DEG),
});

/** Where the worst sample is, in words. */
export const where = (worst) => {
  const { thetaL, thetaV, phiV } = anglesOf(worst);
  return `at θl ${thetaL}°, θv ${thetaV}°, φv ${phiV}°, channel ${'rgb'[worst.channel]}`;
};
