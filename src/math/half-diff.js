// Rusinkiewicz's half/difference parametrisation of a pair of directions (1998): theta_h is the angle of
// the half vector from n, theta_d the angle between l and h, phi_d the rotation of l about h. Isotropic
// BRDFs depend on (theta_h, theta_d, phi_d) only, and most of their structure shows in (theta_h, theta_d).

/** l and v (unit, local frame, n = z) for the half/difference angles, with the half vector in the x-z plane. */
export function directionsFromHalfDiff(thetaH, thetaD, phiD) {
  const d = [Math.sin(thetaD) * Math.cos(phiD), Math.sin(thetaD) * Math.sin(phiD), Math.cos(thetaD)];
  const rotY = ([x, y, z]) => [x * Math.cos(thetaH) + z * Math.sin(thetaH), y, -x * Math.sin(thetaH) + z * Math.cos(thetaH)];
  return { l: rotY(d), v: rotY([-d[0], -d[1], d[2]]) };
}

/** The inverse: (theta_h, theta_d) of a pair of unit directions. */
export function halfDiffAngles(l, v) {
  const h = [l[0] + v[0], l[1] + v[1], l[2] + v[2]];
  const len = Math.hypot(...h);
  const c = (x) => Math.acos(Math.min(Math.max(x, -1), 1));
  return { thetaH: c(h[2] / len), thetaD: c((l[0] * h[0] + l[1] * h[1] + l[2] * h[2]) / len) };
}
