// Where the polar plot's words go, so that none covers another or a handle: the direction names (n, l, v, h,
// mirror) first, each at the first free place around its arrow's tip; then the degrees of the spokes and the values
// of the rings, each left out when every place of its own is taken (the direction named there says as much).
// Pure: the plot measures the words with its canvas; a test does with any width.

import { DEG } from '../../math/angles.js';

export const NAME_FONT = 'bold 13px system-ui, sans-serif';
export const SMALL_FONT = '11px system-ui, sans-serif';
const NAME_HEIGHT = 13;
const SMALL_HEIGHT = 11;
const HANDLE = 7; // px: the radius of the l and v handles (the other tips have a 3 px dot)

/** The dial's size and centre on a canvas of w × h CSS pixels. */
export function dialGeometry(w, h) {
  const R = Math.min(w / 2, h) * 0.86;
  return { w, h, R, cx: w / 2, cy: h * 0.92 };
}

/** Angle theta (°) from n, positive towards +x (the view side), at radius r (1: the dial's rim). */
export const toXY = (g, theta, r) => [g.cx + r * g.R * Math.sin(theta * DEG), g.cy - r * g.R * Math.cos(theta * DEG)];

/** A box of half size (hw, hh) centred `gap` px from (x, y) in the direction (dx, dy), beside it, not on it. */
function beside([x, y], [dx, dy], gap, hw, hh) {
  const n = Math.hypot(dx, dy);
  const [ux, uy] = [dx / n, dy / n];
  const reach = gap + Math.abs(ux) * hw + Math.abs(uy) * hh;
  return [x + ux * reach, y + uy * reach];
}

/** Places around a tip at angle theta: beside it outwards and to both sides first, then further away. */
function aroundTip(tip, theta, hw, hh, near) {
  const u = [Math.sin(theta * DEG), -Math.cos(theta * DEG)]; // outwards from the centre
  const t = [-u[1], u[0]]; // along the rim
  const dirs = [
    [u[0] + t[0], u[1] + t[1]],
    [u[0] - t[0], u[1] - t[1]],
    u,
    t,
    [-t[0], -t[1]],
    [t[0] - u[0], t[1] - u[1]],
    [-t[0] - u[0], -t[1] - u[1]],
  ];
  return [near, near + 14, near + 30].flatMap((gap) => dirs.map((d) => beside(tip, d, gap, hw, hh)));
}

/**
 * Every word of the plot with the places it may take, in the order they are placed.
 * @param {{ R: number, cx: number, cy: number }} g  the dial (dialGeometry)
 * @param {{ lightTheta: number, viewTheta: number, halfTheta: number | null, max: number }} spec
 * @param {(text: string, font: string) => number} measure  the width of `text` in `font`, px
 */
export function polarLabelSpecs(g, spec, measure) {
  const word = (text, font, color, optional, places) => {
    const w = measure(text, font);
    const h = font === NAME_FONT ? NAME_HEIGHT : SMALL_HEIGHT;
    return { text, font, color, optional, w, h, places: places(w / 2, h / 2) };
  };
  const surface = word('surface', SMALL_FONT, '#666', false, (hw) => [[g.cx - g.R * 1.05 + hw, g.cy + 9]]);
  const arrows = directionsOf(spec).map(([theta, color, name]) => {
    const tip = toXY(g, theta, 1);
    const near = (name === 'l' || name === 'v' ? HANDLE : 3) + 2;
    return word(name, NAME_FONT, color, false, (hw, hh) => aroundTip(tip, theta, hw, hh, near));
  });
  const spokes = [-90, -60, -30, 0, 30, 60, 90].map((a) =>
    word(`${Math.abs(a)}°`, SMALL_FONT, '#666', true, (hw, hh) => {
      const u = [Math.sin(a * DEG), -Math.cos(a * DEG)];
      return [3, 12].map((gap) => beside(toXY(g, a, 1), u, gap, hw, hh));
    }),
  );
  const rings = [0.25, 0.5, 0.75, 1].map((r) =>
    word(`${(r * spec.max).toPrecision(2)}`, SMALL_FONT, '#666', true, (hw, hh) => [
      [g.cx + 3 + hw, g.cy - r * g.R + hh + 1],
      [g.cx - 3 - hw, g.cy - r * g.R + hh + 1],
    ]),
  );
  return [surface, ...arrows, ...spokes, ...rings];
}

/** The drawn directions: [angle (°), colour, name], n first; h only when it is in the plane (not null). */
export function directionsOf(spec) {
  return [
    [0, '#333', 'n'],
    [spec.lightTheta, '#777', 'mirror'],
    ...(spec.halfTheta === null ? [] : [[spec.halfTheta, '#cc79a7', 'h']]),
    [-spec.lightTheta, '#e6a700', 'l'],
    [spec.viewTheta, '#0072b2', 'v'],
  ];
}

const meets = (a, b) => a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;

/**
 * Gives each word the first of its places that stays on the canvas and meets no word placed before it nor a
 * direction's dot; an optional word with no such place is left out, a direction's name takes its first place.
 * @param {ReturnType<typeof polarLabelSpecs>} words
 * @param {{ w: number, h: number, R: number, cx: number, cy: number }} g
 * @param {{ lightTheta: number, viewTheta: number, halfTheta: number | null }} spec
 * @returns {{ text: string, font: string, color: string, x: number, y: number, w: number, h: number }[]}
 *   x, y: the top left corner of the word's box
 */
export function layOutLabels(words, g, spec) {
  const taken = directionsOf(spec).map(([theta, , name]) => {
    const [x, y] = toXY(g, theta, 1);
    const r = name === 'l' || name === 'v' ? HANDLE : 3;
    return { x: x - r, y: y - r, w: 2 * r, h: 2 * r };
  });
  const placed = [];
  for (const { places, optional, ...label } of words) {
    const boxes = places.map(([x, y]) => ({ ...label, x: x - label.w / 2, y: y - label.h / 2 }));
    const fits = (b) => b.x >= 0 && b.y >= 0 && b.x + b.w <= g.w && b.y + b.h <= g.h;
    const free = boxes.find((b) => fits(b) && !taken.some((t) => meets(t, b)));
    const box = free ?? (optional ? null : boxes.find(fits) ?? boxes[0]);
    if (!box) continue;
    taken.push(box);
    placed.push(box);
  }
  return placed;
}
