// A browser can report a language tag that Intl rejects: WebKitGTK started with LANG=C says navigator.language is
// "C", and `new Intl.NumberFormat('C')` throws a RangeError. uPlot formats its axes with
// Intl.NumberFormat(navigator.language) as its module loads, so that one tag would stop every plot of the app.
// Imported before uPlot (plot.js), this gives the page a tag Intl accepts: the first usable one the browser lists,
// else 'en'. A usable tag is left as it is.

/**
 * The first of `tags` that Intl.NumberFormat accepts, else 'en'.
 * @param {readonly (string | undefined)[]} tags
 */
export function usableLanguage(tags) {
  for (const tag of tags) {
    try {
      if (tag) return new Intl.NumberFormat(tag).resolvedOptions().locale && tag;
    } catch {
      // not a tag Intl knows: try the next
    }
  }
  return 'en';
}

if (typeof navigator !== 'undefined') {
  const language = usableLanguage([navigator.language, ...(navigator.languages ?? [])]);
  if (language !== navigator.language) Object.defineProperty(navigator, 'language', { value: language });
}
