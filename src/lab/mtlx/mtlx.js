// OpenPBR materials in and out of MaterialX documents (.mtlx), the format Blender, Houdini, USD and MaterialX's
// own viewer read and write. The two functions of this module:
//   readMtlx(text, fileName) → { name, material, notKept }  a document holding one open_pbr_surface node with
//                               constant inputs (and, optionally, the surfacematerial that uses it), read into a
//                               material of the lab (LAB_MATERIAL_KEYS, OpenPBR's own names, the specification's
//                               default for every input the file leaves out). Anything else is refused: a texture
//                               or any node but those two, an input connected to a node or a graph, an unknown
//                               input, a value out of the definition's range, a file over MAX_MTLX_CHARS or nested
//                               deeper than MAX_MTLX_DEPTH. The Error's message names what was refused. `notKept`
//                               lists the inputs read but outside the lab's subset (transmission, subsurface, thin
//                               film, emission, opacity) that the file sets to other than their defaults.
//   writeMtlx(material, name) → text  the material as such a document, every key of the lab written with the
//                               shortest decimal that reads back to the same float64, so readMtlx(writeMtlx(m))
//                               gives m again; MaterialX's validate() accepts it (tests/unit/mtlx-materialx.test.js).
// The text is read by a small XML reader (xml-reader.js) that evaluates nothing and refuses DOCTYPE declarations.
import { readXml } from './xml-reader.js';
import { LAB_MATERIAL_KEYS, OPENPBR_GEOMETRY_INPUTS, OPENPBR_NODE_INPUTS } from './openpbr-inputs.js';

/** A material file is a few kilobytes; 256 k characters is room for comments and then some. */
export const MAX_MTLX_CHARS = 256 * 1024;
/** materialx › node › input is 3 deep; a little room for what a refusal can then name. */
export const MAX_MTLX_DEPTH = 6;
const MAX_ELEMENTS = 500;

const NUMBER = /^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/;
// what makes an input take its value from elsewhere than its `value`
const CONNECTIONS = ['nodename', 'nodegraph', 'output', 'interfacename', 'defaultgeomprop'];
const LINEAR = ['', 'lin_rec709'];

/** An input's value from its text: a number, [r, g, b] or a boolean; null when the text is not one. */
function parseValue(type, text) {
  const parts = text.split(',').map((s) => s.trim());
  if (type === 'boolean') return text.trim() === 'true' ? true : text.trim() === 'false' ? false : null;
  if (!parts.every((p) => NUMBER.test(p))) return null;
  const numbers = parts.map(Number);
  if (!numbers.every(Number.isFinite)) return null;
  if (type === 'float') return numbers.length === 1 ? numbers[0] : null;
  return numbers.length === 3 ? numbers : null;
}

const show = (value) => (Array.isArray(value) ? value.join(', ') : String(value));

/** The value of one <input> of the node, or an Error naming what is wrong with it. */
function readInput(input) {
  const { name, type, value } = input.attributes;
  const where = `input “${name}” (line ${input.line})`;
  if (input.name !== 'input') return new Error(`the node holds a <${input.name}> (line ${input.line}), not an input`);
  if (OPENPBR_GEOMETRY_INPUTS.includes(name)) return new Error(`${where} comes from the geometry; it is not read`);
  const def = OPENPBR_NODE_INPUTS[name];
  if (!def) return new Error(`open_pbr_surface has no input “${name}” (line ${input.line})`);
  const link = CONNECTIONS.find((a) => a in input.attributes);
  if (link) {
    const from = input.attributes[link];
    return new Error(`${where} takes its value from ${link} “${from}” (a texture or a graph): only constants are read`);
  }
  if (type !== def.type) return new Error(`${where} has type “${type}”; open_pbr_surface's is ${def.type}`);
  if (!LINEAR.includes(input.attributes.colorspace ?? '')) {
    return new Error(`${where} is in colour space “${input.attributes.colorspace}”; only lin_rec709 is read`);
  }
  const parsed = value === undefined ? null : parseValue(type, value);
  if (parsed === null) return new Error(`${where} has no ${type} value${value === undefined ? '' : ` (“${value}”)`}`);
  const outside = [parsed].flat().some((x) => typeof x === 'number' && !(x >= def.min && x <= def.max));
  if (outside) return new Error(`${where} is ${show(parsed)}, outside [${def.min}, ${def.max}]`);
  return parsed;
}

/** The document's elements: exactly one open_pbr_surface and at most one surfacematerial, which must use it. */
function documentNodes(root) {
  if (root.name !== 'materialx') throw new Error(`its document element is <${root.name}>, not <materialx>`);
  if (!/^1\.\d+(\.\d+)?$/.test(root.attributes.version ?? '')) {
    throw new Error(`it gives no MaterialX version 1.x (version “${root.attributes.version ?? ''}”)`);
  }
  if (!LINEAR.includes(root.attributes.colorspace ?? '')) {
    throw new Error(`its colour space is “${root.attributes.colorspace}”; only lin_rec709 is read`);
  }
  const other = root.children.find((c) => c.name !== 'open_pbr_surface' && c.name !== 'surfacematerial');
  if (other) {
    const named = other.attributes.name ? ` “${other.attributes.name}”` : '';
    throw new Error(`it holds a <${other.name}>${named} (line ${other.line}); only one open_pbr_surface is read`);
  }
  const shaders = root.children.filter((c) => c.name === 'open_pbr_surface');
  const materials = root.children.filter((c) => c.name === 'surfacematerial');
  if (shaders.length !== 1) throw new Error(`it holds ${shaders.length} open_pbr_surface nodes; one is read`);
  if (materials.length > 1) throw new Error(`it holds ${materials.length} surfacematerial nodes; one is read`);
  const [shader] = shaders;
  const [material] = materials;
  if ((shader.attributes.type ?? 'surfaceshader') !== 'surfaceshader') {
    throw new Error(
      `its open_pbr_surface (line ${shader.line}) has type “${shader.attributes.type}”, not surfaceshader`,
    );
  }
  if (material) {
    const inputs = material.children;
    const uses = inputs.length === 1 && inputs[0].attributes.name === 'surfaceshader' ? inputs[0] : null;
    if (!uses || uses.attributes.nodename !== shader.attributes.name) {
      throw new Error(`its surfacematerial (line ${material.line}) does not take the open_pbr_surface as its shader`);
    }
  }
  return { shader, material };
}

/** Each input's value by name, defaults for the rest; the first input that cannot be read throws. */
function nodeValues(shader) {
  const values = Object.fromEntries(Object.entries(OPENPBR_NODE_INPUTS).map(([k, d]) => [k, d.value]));
  const seen = new Set();
  for (const input of shader.children) {
    const value = readInput(input);
    if (value instanceof Error) throw value;
    const { name } = input.attributes;
    if (seen.has(name)) throw new Error(`input “${name}” is given twice (line ${input.line})`);
    seen.add(name);
    values[name] = value;
  }
  return values;
}

const same = (a, b) => show(a) === show(b);

/** The material in a .mtlx text (see the head of this file); throws an Error whose message says what is wrong. */
export function readMtlx(text, fileName = 'the file') {
  const refuse = (why) => new Error(`“${fileName}” cannot be read as an OpenPBR material: ${why}.`);
  if (typeof text !== 'string') throw refuse('it is not text');
  if (text.length > MAX_MTLX_CHARS) throw refuse(`it is over ${MAX_MTLX_CHARS / 1024} k characters`);
  let root;
  try {
    root = readXml(text, { maxDepth: MAX_MTLX_DEPTH, maxElements: MAX_ELEMENTS });
  } catch (error) {
    throw refuse(`it is not well-formed XML (${error.message})`);
  }
  try {
    const { shader, material } = documentNodes(root);
    const values = nodeValues(shader);
    const kept = Object.fromEntries(LAB_MATERIAL_KEYS.map((k) => [k, values[k]]));
    const notKept = Object.keys(values).filter(
      (k) => !LAB_MATERIAL_KEYS.includes(k) && !same(values[k], OPENPBR_NODE_INPUTS[k].value),
    );
    return { name: (material ?? shader).attributes.name ?? '', material: kept, notKept };
  } catch (error) {
    throw refuse(error.message);
  }
}

const XML_ESCAPES = { '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&apos;' };
const escape = (s) => s.replace(/[&<>"']/g, (ch) => XML_ESCAPES[ch]);

/** A MaterialX element name from any text: letters, digits and underscores, not starting with a digit. */
export function mtlxName(text) {
  const name = String(text).replace(/[^A-Za-z0-9_]/g, '_');
  return /^[A-Za-z_]/.test(name) ? name : `_${name}`;
}

/**
 * The material (LAB_MATERIAL_KEYS; a key left out takes its default) as a .mtlx document: one open_pbr_surface
 * named `${name}_shader` and the surfacematerial `name` that uses it. An unknown key or a value that readMtlx would
 * refuse throws.
 */
export function writeMtlx(material, name = 'openpbr_material') {
  const unknown = Object.keys(material).filter((k) => !LAB_MATERIAL_KEYS.includes(k));
  if (unknown.length) throw new Error(`writeMtlx: not an input of the lab's material: ${unknown.join(', ')}`);
  const material_ = mtlxName(name);
  const shader = `${material_}_shader`;
  const inputs = LAB_MATERIAL_KEYS.map((key) => {
    const { type, value: fallback } = OPENPBR_NODE_INPUTS[key];
    const value = material[key] ?? fallback;
    const text = show(value);
    const check = readInput({ name: 'input', line: 0, attributes: { name: key, type, value: text } });
    if (check instanceof Error) throw new Error(`writeMtlx: ${check.message}`);
    return `    <input name="${key}" type="${type}" value="${escape(text)}" />`;
  });
  return [
    '<?xml version="1.0"?>',
    '<materialx version="1.39">',
    `  <open_pbr_surface name="${shader}" type="surfaceshader">`,
    ...inputs,
    '  </open_pbr_surface>',
    `  <surfacematerial name="${material_}" type="material">`,
    `    <input name="surfaceshader" type="surfaceshader" nodename="${shader}" />`,
    '  </surfacematerial>',
    '</materialx>',
    '',
  ].join('\n');
}
