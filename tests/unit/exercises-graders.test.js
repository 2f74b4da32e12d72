// Each grader against numbers worked out here independently: closed forms written in the test, published
// values, and brute-force searches, never the grader's own output.
import { describe, expect, it } from 'vitest';
import { GRADERS, materialSphere, ndfProfiles, profileFactor, schlickWorstAngle } from '../../src/exercises/graders.js';
import { matchNdfWidths } from '../../src/math/ndf-width.js';
import { DEG } from '../../src/math/angles.js';

const grade = (name, args) => GRADERS[name].grade(args);

/** Unpolarised Fresnel of a dielectric by Snell's law and the textbook rs, rp (not the app's rewritten form). */
function fresnelTextbook(thetaDeg, n) {
  const ti = thetaDeg * DEG;
  const tt = Math.asin(Math.sin(ti) / n);
  const rs = (Math.cos(ti) - n * Math.cos(tt)) / (Math.cos(ti) + n * Math.cos(tt));
  const rp = (n * Math.cos(ti) - Math.cos(tt)) / (n * Math.cos(ti) + Math.cos(tt));
  return (rs * rs + rp * rp) / 2;
}

describe('transmittance-depth', () => {
  // Hale & Querry: k = 1.64e-8 at 650 nm, so sigma = 4 pi k / lambda = 0.31705 / m; 1% is left after ln(100) / sigma
  const depth = Math.log(100) / ((4 * Math.PI * 1.64e-8) / 0.65e-6);
  const params = { channel: 'r', threshold: 0.01 };
  it('accepts the Beer–Lambert depth and rejects a shallow guess, saying by how much', () => {
    expect(depth).toBeCloseTo(14.525, 2);
    expect(grade('transmittance-depth', { answer: 14, params, tolerance: 1.5 }).ok).toBe(true);
    const r = grade('transmittance-depth', { answer: 10, params, tolerance: 1.5 });
    expect(r.ok).toBe(false);
    expect(r.summary).toBe(
      `10 m is too low by ${(depth - 10).toFixed(2)} m ` +
        `(−${((1 - 10 / depth) * 100).toFixed(1)}%); needs to be within ±1.5 m.`,
    );
    expect(r.details[0]).toContain(
      `${Number((100 * Math.exp((-10 * Math.log(100)) / depth)).toPrecision(3))}% of the red (650 nm) light is left`,
    );
  });
});

describe('fresnel-reflectance-angle', () => {
  const n = (1 + Math.sqrt(0.02)) / (1 - Math.sqrt(0.02)); // water's F0 of 0.02 from the talk's table
  it('matches the textbook Fresnel equations and points the right way', () => {
    const at77 = grade('fresnel-reflectance-angle', {
      state: { material: 'water', theta: 77 },
      params: { target: 0.25 },
      tolerance: 0.02,
    });
    expect(at77.ok).toBe(true);
    expect(at77.summary).toContain(`${(fresnelTextbook(77, n) * 100).toFixed(1)}%`);
    const at40 = grade('fresnel-reflectance-angle', {
      state: { material: 'water', theta: 40 },
      params: { target: 0.25 },
      tolerance: 0.02,
    });
    expect(at40.ok).toBe(false);
    expect(at40.summary).toContain(`${((0.25 - fresnelTextbook(40, n)) * 100).toFixed(1)} points below`);
    expect(at40.details).toEqual(['Raise the angle of incidence.']);
    expect(
      grade('fresnel-reflectance-angle', {
        state: { material: 'water', theta: 85 },
        params: { target: 0.25 },
        tolerance: 0.02,
      }).details,
    ).toEqual(['Lower the angle of incidence.']);
  });
});

describe('sphere-match', () => {
  const params = { f0: 0.5, alpha: 0.2, lightTheta: 30, exposure: 0.3, size: 48 };
  it('renders the GGX sphere the closed forms give', () => {
    // pixel nearest the centre of a 49-pixel grid is the exact centre: n = v = (0, 0, 1), l at 30°, h at 15°
    const img = materialSphere(params, { ...params, size: 49 });
    const a2 = params.alpha ** 2;
    const [nl, nv, nh, lh] = [Math.cos(30 * DEG), 1, Math.cos(15 * DEG), Math.cos(15 * DEG)];
    const D = a2 / (Math.PI * (nh * nh * (a2 - 1) + 1) ** 2);
    const F = 0.5 + 0.5 * (1 - lh) ** 5;
    // Heitz 2014's height-correlated G / (4 nl nv), so f = F D · this
    const Vheitz = 0.5 / (nl * Math.sqrt(nv * nv * (1 - a2) + a2) + nv * Math.sqrt(nl * nl * (1 - a2) + a2));
    expect(img[24 * 49 + 24]).toBeCloseTo(Math.PI * F * D * Vheitz * nl, 10);
    expect(Number.isNaN(img[0])).toBe(true); // corner: off the disk
  });
  it('passes the target itself, fails a smoother sphere and says which way', () => {
    expect(grade('sphere-match', { state: { f0: 0.5, alpha: 0.2 }, params, tolerance: 0.012 })).toEqual({
      ok: true,
      summary: 'Right: RMS error 0 (display value 0–1), under 0.012.',
      details: [],
    });
    const r = grade('sphere-match', { state: { f0: 0.5, alpha: 0.1 }, params, tolerance: 0.012 });
    expect(r.ok).toBe(false);
    expect(r.summary).toMatch(/^RMS error 0\.\d+ \(display value 0–1\), needs < 0\.012\.$/);
    expect(r.details).toContain('Roughness too low.');
    // GGX peak at the mirror direction scales as 1/alpha²: halving alpha makes it about 4× brighter
    expect(Number(r.details[0].match(/is ([\d.]+)× as bright/)[1])).toBeGreaterThan(3);
  });
});

describe('smith-g1', () => {
  it('uses GGX’s closed form and Beckmann’s (within Walter’s rational fit)', () => {
    const ggx = grade('smith-g1', {
      state: { kind: 'ggx', alpha: 0.5, viewTheta: -70 },
      params: { target: 0.5 },
      tolerance: 0.01,
    });
    const t = Math.tan(70 * DEG);
    expect(ggx.summary).toContain(`G1 = ${(2 / (1 + Math.sqrt(1 + 0.25 * t * t))).toPrecision(3)}`);
    // Walter et al. 2007: a = 1/(alpha tan), G1 ≈ (3.535a + 2.181a²)/(1 + 2.276a + 2.577a²), within 0.35%
    const a = 1 / (0.5 * Math.tan(77 * DEG));
    const walter = (3.535 * a + 2.181 * a * a) / (1 + 2.276 * a + 2.577 * a * a);
    const r = grade('smith-g1', {
      state: { kind: 'beckmann', alpha: 0.5, viewTheta: 77 },
      params: { target: walter },
      tolerance: 0.004,
    });
    expect(r.ok).toBe(true);
    const wrong = grade('smith-g1', {
      state: { kind: 'beckmann', alpha: 0.5, viewTheta: 40 },
      params: { target: 0.8 },
      tolerance: 0.02,
    });
    expect(wrong.ok).toBe(false);
    expect(wrong.details).toEqual(['Too little is masked: view the surface at a more grazing angle.']);
  });
});

describe('albedo-loss', () => {
  it('finds ln 2 lost at normal incidence for α = 1 (E(1) = 1 − ln 2)', () => {
    const params = { alpha: 1, thetaDeg: 0 };
    expect(grade('albedo-loss', { answer: 100 * Math.LN2, params, tolerance: 0.1 }).ok).toBe(true);
    const r = grade('albedo-loss', { answer: 50, params, tolerance: 3 });
    expect(r.ok).toBe(false);
    expect(r.summary).toMatch(/^50% is too low by 19\.\d%/);
  });
});

describe('multiple-scattering-gain', () => {
  it(
    'grades against the random walk, ' +
      'whose gain with F0 = 1 is the furnace loss 1 − E (independent quadrature: ln 2 at α = 1)',
    () => {
      // F = 1: every path leaves with weight 1, so all bounces give 100% and the gain is what one bounce loses
      const ok = grade('multiple-scattering-gain', {
        answer: 100 * Math.LN2,
        params: { alpha: 1, f0: 1, thetaDeg: 0 },
        tolerance: 0.5,
      });
      expect(ok.ok).toBe(true);
      const low = grade('multiple-scattering-gain', {
        answer: 5,
        params: { alpha: 0.75, f0: 0.71, thetaDeg: 0 },
        tolerance: 3,
      });
      expect(low.ok).toBe(false);
      expect(low.details[0]).toMatch(/^More comes back/);
    },
    30_000,
  );
});

describe('light-zone', () => {
  it('takes l·h = cos(θ/2) from the vectors and tells how far to move', () => {
    // l at 160° from v = (0,0,1): h = normalize(l + v), l·h
    const l = [Math.sin(160 * DEG), 0, Math.cos(160 * DEG)];
    const s = [l[0], 0, l[2] + 1];
    const len = Math.hypot(...s);
    expect((l[0] * s[0] + l[2] * s[2]) / len).toBeCloseTo(Math.cos(80 * DEG), 12);
    const ok = grade('light-zone', { state: { lightTheta: 160 }, params: { zone: 'red' }, tolerance: 1 });
    expect(ok.ok).toBe(true);
    const r = grade('light-zone', { state: { lightTheta: 60 }, params: { zone: 'red' }, tolerance: 1 });
    expect(r.ok).toBe(false);
    expect(r.summary).toContain('the object is green');
    expect(r.details).toEqual([
      'Move the light about 92° further from the view (θd changes half as fast as the light).',
    ]);
    // on the boundary, inside the tolerance: still wrong
    expect(grade('light-zone', { state: { lightTheta: 151 }, params: { zone: 'red' }, tolerance: 1 }).ok).toBe(false);
  });
});

describe('schlick-worst-angle', () => {
  it('agrees with a ternary search on the textbook equations; at n = 1.5 it lies between 84° and 85.5°', () => {
    const f0 = 0.04;
    const err = (deg) => Math.abs(f0 + (1 - f0) * (1 - Math.cos(deg * DEG)) ** 5 - fresnelTextbook(deg, 1.5));
    let [lo, hi] = [60, 89.9];
    for (let i = 0; i < 100; i++) {
      const [m1, m2] = [lo + (hi - lo) / 3, hi - (hi - lo) / 3];
      if (err(m1) < err(m2)) lo = m1;
      else hi = m2;
    }
    const worst = schlickWorstAngle(1.5);
    expect(Math.abs(worst.deg - lo)).toBeLessThan(0.02);
    expect(worst.deg).toBeGreaterThan(84);
    expect(worst.deg).toBeLessThan(85.5);
    expect(grade('schlick-worst-angle', { state: { ior: 1.5 }, answer: 85, tolerance: 1.5 }).ok).toBe(true);
    const r = grade('schlick-worst-angle', { state: { ior: 1.5 }, answer: 60, tolerance: 1.5 });
    expect(r.ok).toBe(false);
    expect(r.summary).toMatch(/^60° is too low by 25° \(−29\.4%\)/);
  });
});

describe('ndf-profile', () => {
  const params = { hwhm: 5, floor: 0.01, abcA2: 2.5, sgdP: 0.64, lightTheta: 30 };
  it('compares profiles as the closed forms of GGX and Beckmann give them', () => {
    const m = matchNdfWidths(5);
    const ggx = (c) => m.ggx.alpha ** 4 / (c * c * (m.ggx.alpha ** 2 - 1) + 1) ** 2;
    const beck = (c) => Math.exp(-(1 - c * c) / (c * c) / m.beckmann.alpha ** 2) / c ** 4;
    let factor = 1;
    for (let i = 0; i < 360; i++) {
      const c = Math.cos(i * 0.25 * DEG);
      if (beck(c) >= 0.01) factor = Math.max(factor, ggx(c) / beck(c), beck(c) / ggx(c));
    }
    const p = ndfProfiles(5, params);
    expect(profileFactor(p.ggx, p.beckmann, 0.01).factor).toBeCloseTo(factor, 6);
  });
  it('accepts the hidden NDF only, and rejects the others with the tail named', () => {
    const args = { params: { ...params, hwhm: 10 }, tolerance: 1.2, hidden: 'beckmann' };
    expect(grade('ndf-profile', { ...args, answer: 'beckmann' })).toMatchObject({ ok: true, details: [] });
    for (const k of ['blinnPhong', 'ggx', 'abc', 'sgd'])
      expect(grade('ndf-profile', { ...args, answer: k }).ok, k).toBe(false);
    const wrong = grade('ndf-profile', { ...args, answer: 'ggx' });
    expect(wrong.summary).toMatch(
      /^GGX’s profile is [\d.]+× brighter than the highlight’s at θh = [\d.]+°; a match needs ≤ 1.2×\.$/,
    );
    expect(wrong.details).toEqual(['The highlight’s tail falls off faster than your choice’s.']);
  });
  it(
    'is well posed only when no two NDFs are within the tolerance: ' + 'Beckmann and Blinn-Phong are 1.10× apart at 5°',
    () => {
      const check = (hwhm, tolerance) => GRADERS['ndf-profile'].check({ ...params, hidden: 'random', hwhm }, tolerance);
      // the closed forms give the pair's factor independently of the grader's profiles
      const m = matchNdfWidths(5);
      const n = m.blinnPhong.exponent; // the exponent that gives Blinn-Phong the same half width
      const beck = (c) => Math.exp(-(1 - c * c) / (c * c) / m.beckmann.alpha ** 2) / c ** 4;
      let factor = 1;
      for (let i = 0; i < 360; i++) {
        const c = Math.cos(i * 0.25 * DEG);
        if (beck(c) >= 0.01) factor = Math.max(factor, c ** n / beck(c), beck(c) / c ** n);
      }
      expect(factor).toBeCloseTo(1.1, 2);
      expect(check(5, 1.3).join('\n')).toMatch(/Blinn–Phong is within 1\.1\d*× of Beckmann/);
      expect(check(10, 1.2)).toEqual([]); // the shipped exercise: every pair at least 1.45× apart
      expect(check(10, 1.5).length).toBeGreaterThan(0);
    },
  );
  it('draws a random hidden NDF from the five', () => {
    expect(GRADERS['ndf-profile'].hide({ hidden: 'random' }, () => 0.99)).toBe('sgd');
    expect(GRADERS['ndf-profile'].hide({ hidden: 'ggx' }, () => 0.99)).toBe('ggx');
  });
});

describe('visibility-ratio', () => {
  it('equals 4cR/(c + R)² for separable over height-correlated Smith GGX at a mirror pair', () => {
    const [c, a] = [Math.cos(80 * DEG), 0.5];
    const R = Math.sqrt(a * a + (1 - a * a) * c * c);
    const ratio = (4 * c * R) / (c + R) ** 2;
    const params = { numerator: 'smithGGXSeparable', denominator: 'smithGGXCorrelated', thetaDeg: 80 };
    expect(grade('visibility-ratio', { state: { alpha: a }, answer: ratio + 0.029, params, tolerance: 0.03 }).ok).toBe(
      true,
    );
    const r = grade('visibility-ratio', { state: { alpha: a }, answer: 1, params, tolerance: 0.03 });
    expect(r.ok).toBe(false);
    expect(r.summary).toContain(`too high by ${(1 - ratio).toPrecision(3)}`);
  });
});

describe('lambert-radiance', () => {
  const params = { cdiff: 1, cLight: 3, thetaDeg: 60 };
  it('Lo = c_diff c_light cos θ, and names the usual slips', () => {
    expect(grade('lambert-radiance', { answer: 1.5, params, tolerance: 0.05 }).ok).toBe(true);
    expect(grade('lambert-radiance', { answer: 1.5 * Math.PI, params, tolerance: 0.05 }).details[0]).toMatch(
      /^That is π times too bright/,
    );
    expect(grade('lambert-radiance', { answer: 1.5 / Math.PI, params, tolerance: 0.05 }).details[0]).toMatch(
      /^That is π times too dark/,
    );
    expect(grade('lambert-radiance', { answer: 3, params, tolerance: 0.05 }).details[0]).toMatch(
      /^You left out the cosine/,
    );
    expect(grade('lambert-radiance', { answer: 2, params, tolerance: 0.05 })).toEqual({
      ok: false,
      summary: '2 is too high by 0.5 (+33.3%); needs to be within ±0.05.',
      details: ['Your value is 1.3× the right one.'],
    });
  });
});
