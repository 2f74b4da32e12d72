// The id a page's URL names after '#', read without trusting it.

/** location.hash without the '#', decoded; a malformed escape (#%E0) is kept as written instead of throwing. */
export function hashId(hash = location.hash) {
  const raw = hash.slice(1);
  try {
    return decodeURIComponent(raw);
  } catch {
    return raw;
  }
}
