// sRGB transfer functions, IEC 61966-2-1 piecewise form (scalar).
// Domain: any number; inputs are clamped to [0, 1] because the transfer curve is only defined there.

const clamp01 = (x) => Math.min(Math.max(x, 0), 1);

export function srgbToLinear(c) {
  const x = clamp01(c);
  return x <= 0.04045 ? x / 12.92 : ((x + 0.055) / 1.055) ** 2.4;
}

export function linearToSrgb(c) {
  const x = clamp01(c);
  return x <= 0.0031308 ? x * 12.92 : 1.055 * x ** (1 / 2.4) - 0.055;
}

/** The luminance Y of a linear Rec. 709 / sRGB colour [r, g, b] (ITU-R BT.709's weights). */
export const luminanceRec709 = ([r, g, b]) => 0.2126 * r + 0.7152 * g + 0.0722 * b;
