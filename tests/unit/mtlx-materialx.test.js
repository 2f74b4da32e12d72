// The .mtlx files against MaterialX itself (PyPI `materialx` 1.39.5, run through scripts/materialx-validate.py):
// its node definition of open_pbr_surface is the one src/lab/mtlx/openpbr-inputs.js transcribes, MaterialX's
// validate() accepts what writeMtlx saves and reads the same values from it, and readMtlx reads what MaterialX
// writes. Skipped, saying why, where the package is not installed (.ci/run installs it).
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { readMtlx, writeMtlx } from '../../src/lab/mtlx/mtlx.js';
import { LAB_MATERIAL_KEYS, OPENPBR_GEOMETRY_INPUTS, OPENPBR_NODE_INPUTS } from '../../src/lab/mtlx/openpbr-inputs.js';
import { MATERIALX_MATERIALS } from '../support/materialx-materials.js';
import { materialxPython, MATERIALX_MISSING } from '../support/materialx-python.js';
import { seededRandom } from '../support/hostile-values.js';

const python = materialxPython();
if (!python) console.warn(`mtlx-materialx.test.js skipped: ${MATERIALX_MISSING}`);

const run = (...args) =>
  JSON.parse(execFileSync(python, ['scripts/materialx-validate.py', ...args], { encoding: 'utf8' }));
const float32 = (x) => (Array.isArray(x) ? x.map(Math.fround) : typeof x === 'number' ? Math.fround(x) : x);

describe.skipIf(!python)('.mtlx files as MaterialX 1.39.5 reads and writes them', () => {
  let dir;
  beforeAll(() => {
    dir = mkdtempSync(join(tmpdir(), 'mtlx-'));
  });
  afterAll(() => dir && rmSync(dir, { recursive: true, force: true }));

  it("the input table is open_pbr_surface's node definition (ND_open_pbr_surface_surfaceshader 1.1.1)", () => {
    const { version, inputs } = run('nodedef');
    expect(version).toBe('1.1.1');
    const geometry = Object.keys(inputs).filter((k) => inputs[k].defaultgeomprop);
    expect(geometry).toEqual(OPENPBR_GEOMETRY_INPUTS);
    const rest = Object.keys(inputs).filter((k) => !geometry.includes(k));
    expect(rest).toEqual(Object.keys(OPENPBR_NODE_INPUTS));
    for (const name of rest) {
      const ours = OPENPBR_NODE_INPUTS[name];
      const theirs = inputs[name];
      expect([name, theirs.type, theirs.value]).toEqual([name, ours.type, float32(ours.value)]);
      if (ours.type === 'boolean') continue;
      const bound = (b) => (Array.isArray(b) ? b[0] : b); // a colour's range is the same for each channel
      expect([name, bound(theirs.uimin), bound(theirs.uimax) ?? Infinity]).toEqual([name, ours.min, ours.max]);
    }
  });

  it("validate() accepts every saved material and reads the same values (float32, MaterialX's precision)", () => {
    const random = seededRandom(7);
    const materials = [
      ...MATERIALX_MATERIALS.filter((m) => !m.layers.includes('fuzz')).map((m) => ({ name: m.name, inputs: m.inputs })),
      ...Array.from({ length: 8 }, (_, i) => ({
        name: `random ${i}`,
        inputs: Object.fromEntries(
          LAB_MATERIAL_KEYS.map((k) => {
            const { type, max } = OPENPBR_NODE_INPUTS[k];
            const x = () => random() * Math.min(max, 3);
            return [k, type === 'color3' ? [x(), x(), x()] : x()];
          }),
        ),
      })),
    ];
    const paths = materials.map((m, i) => {
      const path = join(dir, `saved-${i}.mtlx`);
      writeFileSync(path, writeMtlx(m.inputs, m.name));
      return path;
    });
    const checked = run('check', ...paths);
    checked.forEach((result, i) => {
      const saved = readMtlx(writeMtlx(materials[i].inputs, materials[i].name));
      expect([result.valid, result.message, result.nodes, result.materials]).toEqual([true, '', 1, [saved.name]]);
      const ours = Object.fromEntries(LAB_MATERIAL_KEYS.map((k) => [k, float32(saved.material[k])]));
      expect(result.inputs).toEqual(ours);
    });
  });

  it('readMtlx reads the documents MaterialX writes itself (writeToXmlString), to its 6 digits', () => {
    const materials = [
      { name: 'written', inputs: { base_color: [0.3, 0.2, 0.1], specular_roughness: 0.123456789, coat_weight: 1 } },
      { name: 'gold', inputs: MATERIALX_MATERIALS.find((m) => m.name === 'gold').inputs },
    ];
    writeFileSync(join(dir, 'to-write.json'), JSON.stringify(materials));
    for (const [i, { text }] of run('write', join(dir, 'to-write.json')).entries()) {
      const { name, material } = readMtlx(text);
      expect(name).toBe(materials[i].name);
      for (const [key, value] of Object.entries(materials[i].inputs)) {
        [material[key]].flat().forEach((x, c) => expect(x).toBeCloseTo([value].flat()[c], 6));
      }
    }
  });
});
