// Colours used across the app. The defaults follow the talk; every colour code has a colour-blind-safe
// alternative from the Okabe & Ito palette (2008), which stays distinct under the common colour deficiencies.
export const ZONE_PALETTES = {
  talk: { label: 'Talk (green, yellow, red)', colors: ['#3fae49', '#f5d327', '#e2352b'] },
  cb: { label: 'Colour-blind safe (blue, yellow, vermillion)', colors: ['#0072b2', '#f0e442', '#d55e00'] },
};
/** The schema field every widget with zone colours offers. */
export const ZONE_PALETTE_FIELD = {
  type: 'enum',
  options: Object.fromEntries(Object.entries(ZONE_PALETTES).map(([k, p]) => [k, p.label.split(' (')[0]])),
  default: 'talk',
  label: 'Zone colours',
};
export const ZONE_LABELS = ['barely changes (< 45°)', 'changes somewhat (45–75°)', 'goes rapidly to 1 (> 75°)'];

/** Okabe-Ito hues (yellow left out: too light on white) for one series per material. */
export const SERIES_COLORS = ['#0072b2', '#d55e00', '#009e73', '#cc79a7', '#e69f00', '#56b4e9', '#000000'];
/**
 * Line patterns that go with the colours, so that series stay apart without colour (colour blindness, grey
 * print). Five patterns against seven colours: the first 35 series all differ in colour or pattern.
 */
export const SERIES_DASHES = [undefined, [9, 4], [2, 3], [10, 3, 2, 3], [4, 4]];
/** Colour and line pattern of series i: { stroke, dash } for plot specs. */
export const seriesStyle = (i) => ({
  stroke: SERIES_COLORS[i % SERIES_COLORS.length],
  dash: SERIES_DASHES[i % SERIES_DASHES.length],
});
/** The colour names in a palette's label, e.g. 'green, yellow, red'. */
export const paletteColourNames = (key) => ZONE_PALETTES[key].label.match(/\((.*)\)/)[1];

export function withAlpha(hex, alpha) {
  const a = Math.round(alpha * 255)
    .toString(16)
    .padStart(2, '0');
  return `${hex}${a}`;
}

/** [r, g, b] in [0, 1] -> '#rrggbb'. */
export function rgbToHex(rgb) {
  return `#${rgb
    .map((c) =>
      Math.round(Math.min(Math.max(c, 0), 1) * 255)
        .toString(16)
        .padStart(2, '0'),
    )
    .join('')}`;
}

/** '#rrggbb' -> [r, g, b] in [0, 1] (display, i.e. sRGB-encoded, values). */
export function hexToRgb(hex) {
  const n = parseInt(hex.slice(1), 16);
  return [16, 8, 0].map((s) => ((n >> s) & 255) / 255);
}

// Viridis (perceptually uniform, colour-blind safe) at five stops, interpolated linearly.
const VIRIDIS = [
  [68, 1, 84],
  [59, 82, 139],
  [33, 145, 140],
  [94, 201, 98],
  [253, 231, 37],
];

/** Viridis colour of t in [0, 1] as [r, g, b] in 0..255. */
export function viridis(t) {
  const x = Math.min(Math.max(t, 0), 1) * (VIRIDIS.length - 1);
  const i = Math.min(Math.floor(x), VIRIDIS.length - 2);
  const f = x - i;
  return VIRIDIS[i].map((c, k) => c + f * (VIRIDIS[i + 1][k] - c));
}
