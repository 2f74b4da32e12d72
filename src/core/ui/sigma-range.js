// How far Oren–Nayar's σ is modelled: one rule and one wording for the diffuse explorer and the material lab.
// σ is the standard deviation of the facet tilt angle; past 2σ = 90° a Gaussian puts 4.6% of the facets beyond
// 90°, which no V-groove can have. The limit is this app's argument, not Oren & Nayar's (1994).
import { DEG } from '../../math/angles.js';

/** Above this σ (degrees) the model is extrapolated. */
export const SIGMA_MODELLED_DEG = 45;

/** The hint for a σ slider. */
export const SIGMA_HINT =
  `Standard deviation of the facet slope angle, in degrees (the model itself takes radians). ` +
  `Above ${SIGMA_MODELLED_DEG}° it is an extrapolation: a Gaussian of tilts that wide puts over 4.6% of the facets ` +
  'past 90°, which no V-groove facet can have (the diffuse chapter says more).';

export const sigmaExtrapolated = (deg) => deg > SIGMA_MODELLED_DEG;

/** "σ = 50° (0.873 rad, extrapolated)". */
export const sigmaText = (deg) =>
  `σ = ${deg}° (${(deg * DEG).toFixed(3)} rad${sigmaExtrapolated(deg) ? ', extrapolated' : ''})`;
