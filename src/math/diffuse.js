// Diffuse terms, in 1/sr like every BRDF here.

/** Lambert: c_diff / pi, where c_diff is the share of light scattered back (the diffuse colour). */
export function diffuseLambert(cdiff) {
  return Math.min(Math.max(cdiff, 0), 1) / Math.PI;
}
