// The geometry of the MERL table (Matusik, Pfister, Brand, McMillan 2003): its dimensions and where a direction pair
// falls in it, index arithmetic with no file. Node (i, j, k) sits where the reference reader's index first becomes
// (i, j, k) (BRDFRead.cpp truncates): theta_h = (i/90)² · 90°, theta_d = j°, phi_d = k°. The GPU's twin is in
// shaders/measured.glsl; src/measured/merl.js reads and writes the files.

export const MERL_DIMS = Object.freeze([90, 90, 180]);
export const MERL_SAMPLES = MERL_DIMS[0] * MERL_DIMS[1] * MERL_DIMS[2];
const [NH, ND, NP] = MERL_DIMS;
const HALF_PI = Math.PI / 2;

/** The table index of node (i, j, k): theta_h, theta_d, phi_d. */
export const merlIndex = (i, j, k) => (i * ND + j) * NP + k;

/** The angles (radians) of node (i, j, k). */
export function merlNodeAngles(i, j, k) {
  return { thetaH: (i / NH) ** 2 * HALF_PI, thetaD: (j / ND) * HALF_PI, phiD: (k / NP) * Math.PI };
}

/** Continuous node coordinates of (theta_h, theta_d, phi_d): the reference's indices before truncation. */
export function merlCoordinates(thetaH, thetaD, phiD) {
  const p = phiD < 0 ? phiD + Math.PI : phiD; // reciprocity, as BRDFRead.cpp
  return [Math.sqrt(Math.max(thetaH, 0) / HALF_PI) * NH, (thetaD / HALF_PI) * ND, (p / Math.PI) * NP];
}
