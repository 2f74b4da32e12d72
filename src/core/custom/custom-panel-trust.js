// @ts-check
// Which user-written code may run without asking. Code typed here runs at once; code that arrived with a link or
// from a parent frame is shown first and runs after one click ("Run this code"), remembered in this browser by a
// hash of the text. The hash (cyrb53, 53 bits) is no cryptographic seal: the click is a consent step against a
// link that runs code unseen, and GLSL that passed the static checks can do no more than any web page's WebGL.

const STORE_KEY = 'shading-lab:accepted-code';
const KEEP = 200; // the most recent hashes kept

/** @param {string} text */
export function codeHash(text) {
  let h1 = 0xdeadbeef;
  let h2 = 0x41c6ce57;
  for (let i = 0; i < text.length; i++) {
    const c = text.charCodeAt(i);
    h1 = Math.imul(h1 ^ c, 2654435761);
    h2 = Math.imul(h2 ^ c, 1597334677);
  }
  h1 = Math.imul(h1 ^ (h1 >>> 16), 2246822507) ^ Math.imul(h2 ^ (h2 >>> 13), 3266489909);
  h2 = Math.imul(h2 ^ (h2 >>> 16), 2246822507) ^ Math.imul(h1 ^ (h1 >>> 13), 3266489909);
  return (4294967296 * (2097151 & h2) + (h1 >>> 0)).toString(36);
}

/** @returns {string[]} */
function stored() {
  try {
    const list = JSON.parse(localStorage.getItem(STORE_KEY) ?? '[]');
    return Array.isArray(list) ? list.filter((x) => typeof x === 'string') : [];
  } catch {
    return []; // storage blocked or garbled: nothing is remembered, each link asks again
  }
}

/** Hashes accepted in this page, also when storage is blocked. */
const accepted = new Set();

/**
 * True when `code` may run: the slot's own starter, or code typed or accepted in this browser.
 * @param {string} code
 * @param {string} starter
 */
export function isTrusted(code, starter) {
  if (code === starter) return true;
  const hash = codeHash(code);
  return accepted.has(hash) || stored().includes(hash);
}

/**
 * Remembers `code` as accepted (typed by the user, or shown and clicked).
 * @param {string} code
 */
export function trustCode(code) {
  const hash = codeHash(code);
  accepted.add(hash);
  const list = stored().filter((x) => x !== hash);
  list.push(hash);
  try {
    localStorage.setItem(STORE_KEY, JSON.stringify(list.slice(-KEEP)));
  } catch {
    // storage blocked: accepted for this page only
  }
}
