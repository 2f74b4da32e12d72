// .mtlx files in and out (src/lab/mtlx/mtlx.js): the round trip, the defaults, and every refusal with its words.
// MaterialX's own reading of what is saved is in mtlx-materialx.test.js.
import { describe, expect, it } from 'vitest';
import { MAX_MTLX_CHARS, MAX_MTLX_DEPTH, readMtlx, writeMtlx } from '../../src/lab/mtlx/mtlx.js';
import { LAB_MATERIAL_KEYS, OPENPBR_NODE_INPUTS } from '../../src/lab/mtlx/openpbr-inputs.js';
import { readXml } from '../../src/lab/mtlx/xml-reader.js';
import { seededRandom } from '../support/hostile-values.js';

/** A document around the given node and input lines. */
const doc = (inside, { root = '<materialx version="1.39">' } = {}) =>
  `<?xml version="1.0"?>\n${root}\n${inside}\n</materialx>\n`;
const node = (inputs = '', name = 'paint') =>
  `<open_pbr_surface name="${name}" type="surfaceshader">\n${inputs}\n</open_pbr_surface>`;
const refusal = (text) => {
  try {
    readMtlx(text, 'paint.mtlx');
  } catch (error) {
    return error.message;
  }
  return null;
};

/** A material with every key of the lab at a random value in its range (indices up to 3, like the UI's soft max). */
function randomMaterial(random) {
  const value = (def) => random() * Math.min(def.max, 3);
  return Object.fromEntries(
    LAB_MATERIAL_KEYS.map((k) => {
      const def = OPENPBR_NODE_INPUTS[k];
      return [k, def.type === 'color3' ? [value(def), value(def), value(def)] : value(def)];
    }),
  );
}

describe('saving and loading an OpenPBR material as .mtlx', () => {
  it('round trip is exact: 200 random materials (float64, any digits) read back bit for bit', () => {
    const random = seededRandom(29);
    for (let i = 0; i < 200; i++) {
      const material = randomMaterial(random);
      const { material: back, name, notKept } = readMtlx(writeMtlx(material, `m${i}`));
      expect(back).toEqual(material);
      expect(name).toBe(`m${i}`);
      expect(notKept).toEqual([]);
    }
  });

  it('round trip keeps the awkward numbers: 0.1 + 0.2, 1/3, the smallest double, 1 - 2⁻⁵³', () => {
    const material = {
      ...randomMaterial(seededRandom(1)),
      base_color: [0.1 + 0.2, 1 / 3, 5e-324],
      base_weight: 1 - 2 ** -53,
    };
    expect(readMtlx(writeMtlx(material)).material).toEqual(material);
  });

  it("a file's missing inputs take open_pbr_surface's defaults (node definition, OpenPBR 1.1.1)", () => {
    const { material } = readMtlx(doc(node('<input name="base_color" type="color3" value="0.5, 0.25, 0.125" />')));
    expect(material.base_color).toEqual([0.5, 0.25, 0.125]);
    for (const key of LAB_MATERIAL_KEYS.filter((k) => k !== 'base_color')) {
      expect(material[key]).toEqual(OPENPBR_NODE_INPUTS[key].value);
    }
    expect(Object.keys(material)).toEqual(LAB_MATERIAL_KEYS);
  });

  it('a material with keys left out is saved with their defaults; an unknown key is refused', () => {
    expect(readMtlx(writeMtlx({ coat_weight: 1 })).material.coat_ior).toBe(1.6);
    expect(() => writeMtlx({ specular_anisotropy: 0.5 })).toThrow(
      /not an input of the lab's material: specular_anisotropy/,
    );
    expect(() => writeMtlx({ base_color: [2, 0, 0] })).toThrow(/base_color.*outside \[0, 1\]/);
  });

  it('reads what is outside the subset and says so (transmission, emission), keeping only the lab keys', () => {
    const inputs = [
      '<input name="transmission_weight" type="float" value="0.5" />',
      '<input name="emission_luminance" type="float" value="0" />',
      '<input name="geometry_thin_walled" type="boolean" value="true" />',
    ].join('\n');
    const { material, notKept } = readMtlx(doc(node(inputs)));
    expect(notKept).toEqual(['transmission_weight', 'geometry_thin_walled']);
    expect(Object.keys(material)).toEqual(LAB_MATERIAL_KEYS);
  });

  it('reads entities and character references in values, comments and a surfacematerial', () => {
    const text = doc(
      [
        '<!-- a car paint -->',
        node('<input name="specular_roughness" type="float" value="&#48;.&#x32;5" />'),
        '<surfacematerial name="M_paint" type="material">',
        '  <input name="surfaceshader" type="surfaceshader" nodename="paint" />',
        '</surfacematerial>',
      ].join('\n'),
    );
    const { material, name } = readMtlx(text);
    expect(material.specular_roughness).toBe(0.25);
    expect(name).toBe('M_paint');
  });
});

describe('refusing a .mtlx file, in words that name what was refused', () => {
  const cases = [
    [
      'a texture',
      doc(
        '<image name="wood" type="color3"><input name="file" type="filename" value="wood.png" /></image>\n' +
          node('<input name="base_color" type="color3" nodename="wood" />'),
      ),
      /holds a <image> “wood” \(line 3\); only one open_pbr_surface is read/,
    ],
    [
      'an input from a texture node',
      doc(node('<input name="base_color" type="color3" nodename="wood" />')),
      /input “base_color” \(line 4\) takes its value from nodename “wood” \(a texture or a graph\)/,
    ],
    [
      'an input from a node graph',
      doc(node('<input name="coat_weight" type="float" nodegraph="NG_mask" output="out" />')),
      /takes its value from nodegraph “NG_mask”/,
    ],
    ['an unknown node', doc('<standard_surface name="ss" type="surfaceshader" />'), /holds a <standard_surface> “ss”/],
    ['an unknown input', doc(node('<input name="sheen_weight" type="float" value="1" />')), /no input “sheen_weight”/],
    ['a wrong type', doc(node('<input name="base_color" type="float" value="1" />')), /type “float”; .* is color3/],
    [
      'a malformed value',
      doc(node('<input name="base_color" type="color3" value="1, 0" />')),
      /no color3 value \(“1, 0”\)/,
    ],
    [
      'a value out of range',
      doc(node('<input name="coat_weight" type="float" value="1.5" />')),
      /is 1.5, outside \[0, 1\]/,
    ],
    ['a non-finite value', doc(node('<input name="specular_ior" type="float" value="1e999" />')), /no float value/],
    ['no shader', doc(''), /holds 0 open_pbr_surface nodes/],
    ['two shaders', doc(node('', 'a') + node('', 'b')), /holds 2 open_pbr_surface nodes/],
    [
      'a node of another type',
      doc('<open_pbr_surface name="p" type="color3" />'),
      /has type “color3”, not surfaceshader/,
    ],
    ['an input given twice', doc(node('<input name="coat_weight" type="float" value="1" />'.repeat(2))), /given twice/],
    [
      'sRGB colours',
      doc(node('<input name="base_color" type="color3" value="1, 0, 0" colorspace="srgb_texture" />')),
      /colour space “srgb_texture”/,
    ],
    [
      'a geometry input',
      doc(node('<input name="geometry_normal" type="vector3" value="0, 0, 1" />')),
      /comes from the geometry/,
    ],
    ['another document', '<?xml version="1.0"?><gltf />', /document element is <gltf>, not <materialx>/],
    ['no version', doc(node(), { root: '<materialx>' }), /no MaterialX version 1.x/],
    [
      'a surfacematerial of another shader',
      doc(
        `${node()}<surfacematerial name="M" type="material">` +
          '<input name="surfaceshader" type="surfaceshader" nodename="x" /></surfacematerial>',
      ),
      /does not take the open_pbr_surface as its shader/,
    ],
    // what would expand or fetch: a document type with entities (the "billion laughs"), an external entity
    [
      'a DOCTYPE with entities',
      '<?xml version="1.0"?><!DOCTYPE m [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;">]>' +
        '<materialx version="1.39" />',
      /not well-formed XML \(line 1: a document type, entity or CDATA section/,
    ],
    [
      'an undeclared entity',
      doc(node('<input name="base_color" type="color3" value="&xxe;" />')),
      /the entity &xxe; is not one XML defines/,
    ],
    ['a processing instruction', doc('<?xml-stylesheet href="x.xsl"?>'), /processing instruction/],
    [
      'mismatched tags',
      '<materialx version="1.39"><open_pbr_surface name="a"></materialx>',
      /line 1: <\/open_pbr_surface> was expected/,
    ],
    ['a duplicate attribute', '<materialx version="1.39" version="1.38" />', /the attribute version is given twice/],
    ['a file cut short', '<materialx version="1.39">\n<open_pbr_surface name="a">', /ends inside an element/],
  ];
  for (const [what, text, message] of cases) {
    it(`refuses ${what}`, () => {
      const said = refusal(text);
      expect(said).toMatch(/^“paint.mtlx” cannot be read as an OpenPBR material: /);
      expect(said).toMatch(message);
    });
  }

  it(`refuses a file over ${MAX_MTLX_CHARS / 1024} k characters before reading it`, () => {
    const big = doc(node(`<!-- ${'x'.repeat(MAX_MTLX_CHARS)} -->`));
    expect(refusal(big)).toMatch(/over 256 k characters/);
  });

  it(`refuses elements nested deeper than ${MAX_MTLX_DEPTH}, and deep nesting stops early (no stack overflow)`, () => {
    const nested = (n) => `${'<a>'.repeat(n)}${'</a>'.repeat(n)}`;
    expect(refusal(doc(nested(MAX_MTLX_DEPTH)))).toMatch(/nested deeper than 6/);
    const hostile = doc(nested(50_000)).slice(0, MAX_MTLX_CHARS - 1);
    expect(refusal(hostile)).toMatch(/nested deeper than 6/);
  });

  it('the XML reader reads attributes in either quote and refuses text beside the document element', () => {
    expect(readXml(`<a x='1' y="2"/>`).attributes).toEqual({ x: '1', y: '2' });
    expect(() => readXml('<a/>trailing')).toThrow(/text after the document/);
    expect(() => readXml('<a/><b/>')).toThrow(/a second document element/);
  });
});
