// A small XML reader for the material files a user brings (.mtlx): elements, attributes and comments, nothing
// more. It runs the same in Node and in the browser (the unit tests read with it what the page reads), and what it
// does not read it refuses: a document type declaration (where entities are declared, the way to a file that
// expands to gigabytes), CDATA and processing instructions beyond the opening <?xml …?>. Text between elements is
// skipped: a MaterialX document carries its values in attributes. Caps on size, depth and element count are the
// caller's (readXml's `limits`). Nothing in the text is evaluated.

const NAME = /[A-Za-z_:][-\w.:]*/y;
const SPACE = /\s*/y;
const ENTITIES = { lt: '<', gt: '>', amp: '&', quot: '"', apos: "'" };

/** An error that says where: the line of the offending character. */
function fail(text, at, what) {
  const line = text.slice(0, at).split('\n').length;
  return new Error(`line ${line}: ${what}`);
}

/** The five predefined entities and character references; any other &name; is refused. */
function decode(text, at, raw) {
  return raw.replace(/&(#x[0-9a-fA-F]+|#\d+|\w+);|&/g, (whole, ref) => {
    if (ref === undefined) throw fail(text, at, 'a bare “&” in an attribute value (write &amp;)');
    if (ref[0] === '#') {
      const code = ref[1] === 'x' ? parseInt(ref.slice(2), 16) : parseInt(ref.slice(1), 10);
      if (!(code > 0 && code <= 0x10ffff)) throw fail(text, at, `the character reference ${whole} is not a character`);
      return String.fromCodePoint(code);
    }
    if (!(ref in ENTITIES)) throw fail(text, at, `the entity ${whole} is not one XML defines`);
    return ENTITIES[ref];
  });
}

/** A reader over `text` that moves `at` forward. */
function cursor(text) {
  const c = { text, at: 0 };
  c.skipSpace = () => {
    SPACE.lastIndex = c.at;
    SPACE.exec(text);
    c.at = SPACE.lastIndex;
  };
  c.name = () => {
    NAME.lastIndex = c.at;
    const m = NAME.exec(text);
    if (!m) throw fail(text, c.at, 'a name was expected');
    c.at = NAME.lastIndex;
    return m[0];
  };
  c.expect = (s) => {
    if (!text.startsWith(s, c.at)) throw fail(text, c.at, `“${s}” was expected`);
    c.at += s.length;
  };
  return c;
}

/** The attributes of a start tag, up to its '>' or '/>'; a name given twice is refused. */
function readAttributes(c) {
  const attributes = {};
  for (;;) {
    c.skipSpace();
    if (c.text.startsWith('/>', c.at) || c.text[c.at] === '>') return attributes;
    const at = c.at;
    const name = c.name();
    c.skipSpace();
    c.expect('=');
    c.skipSpace();
    const quote = c.text[c.at];
    if (quote !== '"' && quote !== "'") throw fail(c.text, c.at, `the value of ${name} must be in quotes`);
    const end = c.text.indexOf(quote, c.at + 1);
    if (end < 0) throw fail(c.text, c.at, `the value of ${name} has no closing quote`);
    const raw = c.text.slice(c.at + 1, end);
    if (raw.includes('<')) throw fail(c.text, c.at, `the value of ${name} holds a “<”`);
    if (Object.hasOwn(attributes, name)) throw fail(c.text, at, `the attribute ${name} is given twice`);
    attributes[name] = decode(c.text, at, raw);
    c.at = end + 1;
  }
}

/** Skips what may stand between elements (space, text, comments); refuses what this reader does not read. */
function skipMisc(c, inside) {
  for (;;) {
    const next = c.text.indexOf('<', c.at);
    if (next < 0) {
      if (inside) throw fail(c.text, c.text.length, 'the file ends inside an element');
      if (c.text.slice(c.at).trim()) throw fail(c.text, c.at, 'text after the document');
      c.at = c.text.length;
      return;
    }
    if (!inside && c.text.slice(c.at, next).trim()) throw fail(c.text, c.at, 'text outside the document');
    c.at = next;
    if (c.text.startsWith('<!--', c.at)) {
      const end = c.text.indexOf('-->', c.at + 4);
      if (end < 0) throw fail(c.text, c.at, 'a comment is not closed');
      c.at = end + 3;
    } else if (c.text.startsWith('<!', c.at)) {
      throw fail(c.text, c.at, 'a document type, entity or CDATA section: not read in a material file');
    } else if (c.text.startsWith('<?', c.at)) {
      throw fail(c.text, c.at, 'a processing instruction: not read in a material file');
    } else return;
  }
}

/**
 * The document element of `text` as { name, attributes, children, line }, children the same. `limits`:
 * { maxDepth, maxElements }; beyond either the reading stops with an error. Throws Error(`line N: …`).
 */
export function readXml(text, { maxDepth = 16, maxElements = 10_000 } = {}) {
  const c = cursor(text.replace(/^\uFEFF/, ''));
  if (c.text.startsWith('<?xml')) {
    const end = c.text.indexOf('?>');
    if (end < 0) throw fail(c.text, 0, 'the XML declaration is not closed');
    c.at = end + 2;
  }
  let count = 0;
  const element = (depth) => {
    if (depth > maxDepth) throw fail(c.text, c.at, `elements nested deeper than ${maxDepth}`);
    if (++count > maxElements) throw fail(c.text, c.at, `more than ${maxElements} elements`);
    const line = c.text.slice(0, c.at).split('\n').length;
    c.expect('<');
    const name = c.name();
    const node = { name, attributes: readAttributes(c), children: [], line };
    if (c.text.startsWith('/>', c.at)) {
      c.at += 2;
      return node;
    }
    c.expect('>');
    for (;;) {
      skipMisc(c, true);
      if (c.text.startsWith('</', c.at)) break;
      node.children.push(element(depth + 1));
    }
    c.expect('</');
    const at = c.at;
    if (c.name() !== name) throw fail(c.text, at, `</${name}> was expected`);
    c.skipSpace();
    c.expect('>');
    return node;
  };
  skipMisc(c, false);
  if (c.at >= c.text.length) throw new Error('the file holds no element');
  const root = element(1);
  skipMisc(c, false);
  if (c.at < c.text.length) throw fail(c.text, c.at, 'a second document element');
  return root;
}
