// fresnel-zones, the probe's readout: at the surface point under the pointer, the angles and each term's value.
import { angleText, probeAngles } from '../../core/ui/probe.js';
import { lightDirFromAngles } from '../../math/angles.js';
import { probeTerms } from './model.js';
import { zoneName } from './words.js';

/** [[label, text], …] at the point with view-space normal `n`, seen from `v`. */
export function probeRows(state, n, v) {
  const a = probeAngles(n, lightDirFromAngles(state.lightTheta, state.lightPhi), v);
  const t = probeTerms(state, a);
  const rgb = (xs) => (t.metal ? xs.map((x) => x.toFixed(4)).join(', ') : xs[0].toFixed(4));
  return [
    ['n·v', angleText(a.nv)],
    ['n·l', angleText(a.nl)],
    ['n·h', angleText(a.nh)],
    ['l·h', angleText(a.lh)],
    ['F(n·v) exact', rgb(t.exact)],
    ['F(n·v) Schlick', rgb(t.schlick)],
    ['zone of n·v / l·h', `${zoneName(t.zoneNv)} / ${zoneName(t.zoneLh)}`],
    ['D GGX(n·h)', t.ndf.toPrecision(4)],
    ['V Smith corr.', t.visibility.toPrecision(4)],
    ['π·D·V/4·(n·l)', t.radiance.toPrecision(4)],
  ];
}
