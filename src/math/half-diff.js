// Rusinkiewicz's half/difference parametrisation of a pair of directions (1998): theta_h is the angle of
// the half vector from n, theta_d the angle between l and h, phi_d the rotation of l about h. Isotropic
// BRDFs depend on (theta_h, theta_d, phi_d) only, and most of their structure shows in (theta_h, theta_d).

/** l and v (unit, local frame, n = z) for the half/difference angles, with the half vector in the x-z plane. */
export function directionsFromHalfDiff(thetaH, thetaD, phiD) {
  const d = [Math.sin(thetaD) * Math.cos(phiD), Math.sin(thetaD) * Math.sin(phiD), Math.cos(thetaD)];
  const rotY = ([x, y, z]) => [
    x * Math.cos(thetaH) + z * Math.sin(thetaH),
    y,
    -x * Math.sin(thetaH) + z * Math.cos(thetaH),
  ];
  return { l: rotY(d), v: rotY([-d[0], -d[1], d[2]]) };
}

/** The inverse: (theta_h, theta_d) of a pair of unit directions. */
export function halfDiffAngles(l, v) {
  const h = [l[0] + v[0], l[1] + v[1], l[2] + v[2]];
  const len = Math.hypot(...h);
  const c = (x) => Math.acos(Math.min(Math.max(x, -1), 1));
  return { thetaH: c(h[2] / len), thetaD: c((l[0] * h[0] + l[1] * h[1] + l[2] * h[2]) / len) };
}

/**
 * All three angles of a pair of unit directions, as the MERL reader (Matusik et al. 2003, BRDFRead.cpp)
 * forms them: l is turned by -phi_h about n, then by -theta_h about the y axis, which brings h onto n and
 * leaves l as the difference vector d (angles by atan2, precise near 0); phi_d = atan2(d.y, d.x) in (-pi, pi].
 * The inverse of directionsFromHalfDiff.
 */
export function halfDiffFromDirections(l, v) {
  const h = [l[0] + v[0], l[1] + v[1], l[2] + v[2]];
  const thetaH = Math.atan2(Math.hypot(h[0], h[1]), h[2]); // not acos: near n, acos(1 - ε) ≈ √(2ε) swamps θh
  const phiH = Math.atan2(h[1], h[0]);
  const [cp, sp, ct, st] = [Math.cos(phiH), Math.sin(phiH), Math.cos(thetaH), Math.sin(thetaH)];
  const x = l[0] * cp + l[1] * sp;
  const y = -l[0] * sp + l[1] * cp;
  const d = [x * ct - l[2] * st, y, x * st + l[2] * ct];
  return { thetaH, thetaD: Math.atan2(Math.hypot(d[0], d[1]), d[2]), phiD: Math.atan2(d[1], d[0]) };
}
