// For each shipped shader exercise: a correct answer, and the typical mistakes with the feedback each must get.
// The expected worst inputs follow from the mistake (worked out in the comments), not from a run of the grader:
// e.g. an unguarded Beckmann forms exp(−∞)/0 = NaN at n·h = 0, the first such input of the grid.
// Shared by tests/browser/shader-exercises.test.js and bench/custom-grade.js.

const SCHLICK = `vec3 customF(vec3 f0, float lh) {
  float m = 1.0 - clamp(lh, 0.0, 1.0);
  float m2 = m * m;
  return f0 + (1.0 - f0) * (m2 * m2 * m);
}
`;

const EXACT = (half) => `vec3 customF(vec3 f0, float lh) {
  float c = clamp(lh, 0.0, 1.0);
  vec3 s = sqrt(f0);
  vec3 eta = (1.0 + s) / (1.0 - s);
  vec3 g = sqrt(eta * eta - 1.0 + c * c);
  vec3 a = (g - c) / (g + c);
  vec3 b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return ${half} * a * a * (1.0 + b * b);
}
`;

const GGX = ({
  guard = true,
  pi = 'PI',
  sin2 = '(1.0 - c) * (1.0 + c)',
} = {}) => `float customD(float nh, float alpha) {
  ${guard ? 'if (!(nh > 0.0)) return 0.0;' : ''}
  float c = min(nh, 1.0);
  float a2 = alpha * alpha;
  float d = a2 * c * c + ${sin2};
  return a2 / (${pi} * d * d);
}
`;

const BECKMANN = ({ guard = true, cutoff = true } = {}) => `float customD(float nh, float alpha) {
  ${guard ? 'if (!(nh > 0.0)) return 0.0;' : ''}
  float c = min(nh, 1.0);
  float a2 = alpha * alpha;
  float c2 = c * c;
  float e = (1.0 - c) * (1.0 + c) / (c2 * a2);
  ${cutoff ? 'if (e > 80.0) return 0.0;' : ''}
  return exp(-e) / (PI * a2 * c2 * c2);
}
`;

const SMITH_G1 = (guard) => `float smithG1(float c, float alpha) {
  if (!(c > 0.0)) return 0.0;
  c = min(c, 1.0);
  float a2 = alpha * alpha;
  return 2.0 * c / (c + sqrt(c * c + a2 * (1.0 - c) * (1.0 + c)));
}

float customV(float nl, float nv, float alpha) {
  ${guard ? 'if (!(nl > 0.0 && nv > 0.0)) return 0.0;' : ''}
  return smithG1(nl, alpha) * smithG1(nv, alpha) / (nl * nv);
}
`;

const CORRELATED = ({ guard = true, numerator = '2.0' } = {}) => `float customV(float nl, float nv, float alpha) {
  ${guard ? 'if (!(nl > 0.0 && nv > 0.0)) return 0.0;' : ''}
  float l = min(nl, 1.0);
  float v = min(nv, 1.0);
  float a2 = alpha * alpha;
  float rootL = sqrt(l * l + a2 * (1.0 - l) * (1.0 + l));
  float rootV = sqrt(v * v + a2 * (1.0 - v) * (1.0 + v));
  return ${numerator} / (v * rootL + l * rootV);
}
`;

const TRADEOFF = ({ guard = true, pi = ' / PI' } = {}) => `float schlickWeight(float c) {
  float m = 1.0 - min(c, 1.0);
  return 1.0 - (0.04 + 0.96 * m * m * m * m * m);
}

vec3 customDiffuse(vec3 cdiff, vec3 l, vec3 v, float alpha) {
  ${guard ? 'if (!(l.z > 0.0 && v.z > 0.0)) return vec3(0.0);' : ''}
  return schlickWeight(l.z) * schlickWeight(v.z) * cdiff${pi};
}
`;

const escape = (text) => text.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
/** The exact summary for a worst input: "At <where> your <value> is <yours>; the reference is <reference>." */
const said = (where, value, yours, reference) =>
  new RegExp(`^${escape(`At ${where} your ${value} is ${yours}; the reference is ${reference}.`)}$`);

/**
 * id → { correct, mistakes: [{ name, code, summary (RegExp), detail? (RegExp) }] }. `starter: true` stands for
 * the exercise's own starter code.
 */
// F82-tint with t = 0.871: b = Schlick(F0, 1/7)(1 − t) / ((1/7)(6/7)⁶)
const F82_TINT = `vec3 customF(vec3 f0, float lh) {
  float mu = clamp(lh, 0.0, 1.0);
  float m = 1.0 - mu;
  float m2 = m * m;
  vec3 tint = vec3(0.871);
  float mBar = 6.0 / 7.0;
  vec3 schlickBar = f0 + (1.0 - f0) * (mBar * mBar * mBar * mBar * mBar);
  vec3 b = schlickBar * (1.0 - tint) / ((1.0 / 7.0) * pow(mBar, 6.0));
  return f0 + (1.0 - f0) * (m2 * m2 * m) - b * mu * (m2 * m2 * m2);
}
`;

const GGX_ANISO = ({
  guard = true,
  scale = 'h.xy / a',
  norm = 'a.x * a.y',
} = {}) => `float customDAniso(vec3 h, vec2 alpha) {
  ${guard ? 'if (!(h.z > 0.0)) return 0.0;' : ''}
  vec2 a = clamp(alpha, 1e-4, 4.0);
  vec2 s = ${scale};
  float d = dot(s, s) + h.z * h.z;
  return 1.0 / (PI * ${norm} * d * d);
}
`;

// the exercise's starter with projectedAlpha written: cos φ = wx / sin θ, sin φ = wy / sin θ
const PROJECTED = ({ guard = true, cos2 = 'c * c', sin2 = 's * s' } = {}) => `float projectedAlpha(vec3 w, vec2 alpha) {
  float sinTheta = length(w.xy);
  ${guard ? 'if (!(sinTheta > 0.0)) return alpha.x;' : ''}
  float c = w.x / sinTheta;
  float s = w.y / sinTheta;
  return sqrt(${cos2} * alpha.x * alpha.x + ${sin2} * alpha.y * alpha.y);
}

float customVAniso(vec3 l, vec3 v, vec2 alpha) {
  if (!(l.z > 0.0 && v.z > 0.0)) return 0.0;
  float aL = projectedAlpha(l, alpha);
  float aV = projectedAlpha(v, alpha);
  float rootL = sqrt(l.z * l.z + aL * aL * dot(l.xy, l.xy));
  float rootV = sqrt(v.z * v.z + aV * aV * dot(v.xy, v.xy));
  return 2.0 / (v.z * rootL + l.z * rootV);
}
`;

export const SHADER_SOLUTIONS = {
  'shader-schlick': {
    correct: SCHLICK,
    mistakes: [
      {
        // (1 − F0) m⁴(1 − m) against F0 + (1 − F0) m⁵: largest in tolerances at F0 = 0, m ≈ 0.45
        name: 'wrong power (4)',
        code: SCHLICK.replace('m2 * m2 * m', 'm2 * m2'),
        summary: said('F0 = 0, l·h = 0.55', 'F', '0.041', '0.018'),
      },
      {
        // pow of a negative base is undefined in GLSL (NaN here) at l·h = 1 + 1e-6; F > 1 at l·h = −0.01
        name: 'unclamped grazing input',
        code: 'vec3 customF(vec3 f0, float lh) {\n  return f0 + (1.0 - f0) * pow(1.0 - lh, 5.0);\n}\n',
        summary: new RegExp(
          [said('F0 = 0, l·h = 1.000001', 'F', 'NaN', '0'), said('F0 = 0, l·h = −0.01', 'F', '1.1', '1')]
            .map((r) => r.source)
            .join('|'),
        ),
      },
    ],
  },
  'shader-fresnel-exact': {
    correct: EXACT('0.5'),
    mistakes: [
      {
        // Schlick is worst against the exact curve where F is mid-way: F0 = 0.5 near grazing
        name: 'Schlick instead of exact',
        code: SCHLICK,
        summary: said('F0 = 0.5, l·h = 0.15', 'F', '0.72', '0.45'),
      },
      {
        name: 'the two polarisations summed, not averaged',
        code: EXACT('1.0'),
        summary: /your F is 2; the reference is 1\.$/,
        detail: /your F is 2× the reference\. Is a factor of 2 missing or extra\?/,
      },
    ],
  },
  'shader-f82-tint': {
    correct: F82_TINT,
    mistakes: [
      {
        // the dip b μ(1 − μ)⁶ left out: in tolerances largest where F82-tint is small, F0 = 0, μ = 0.4
        // (0.078 against 0.058; next μ = 0.35, 2% fewer tolerances)
        name: 'Schlick alone',
        code: SCHLICK,
        summary: said('F0 = 0, l·h = 0.4', 'F', '0.078', '0.058'),
      },
      {
        // b = (1 − t)/(μ̄(1 − μ̄)⁶) without Schlick(F0, 1/7): the dip 1/Schlick(0, 1/7) ≈ 2.2× too deep at F0 = 0
        name: 'tint not relative to Schlick',
        code: F82_TINT.replace('vec3 b = schlickBar * (1.0 - tint)', 'vec3 b = (1.0 - tint)'),
        summary: said('F0 = 0, l·h = 0.4', 'F', '0.035', '0.058'),
      },
    ],
  },
  'shader-ggx-tiny-alpha': {
    correct: GGX(),
    mistakes: [
      {
        // α² − 1 rounds to −1 in float32: the bracket is 0 at n·h = 1; D(1) = 1/(π α²)
        name: '0 in the textbook bracket at α → 0',
        starter: true,
        summary: said('n·h = 1, α = 1e-4', 'D', 'Inf', '3.2e7'),
      },
      {
        name: 'missing π',
        code: GGX({ pi: '1.0' }),
        summary: said('n·h = 1, α = 1e-4', 'D', '1e8', '3.2e7'),
        detail: /is 3\.1× the reference\. Is a factor of π missing or extra\?/,
      },
      {
        // below the horizon GGX is even in n·h: D(−0.5) = D(0.5) = 1/π at α = 1
        name: 'no zero below the horizon',
        code: GGX({ guard: false }),
        summary: said('n·h = −0.5, α = 1', 'D', '0.32', '0'),
      },
    ],
  },
  'shader-beckmann': {
    correct: BECKMANN(),
    mistakes: [
      {
        // tan² = ∞ at n·h = 0: exp(−∞)/0 = 0/0
        name: '0/0 at the horizon',
        code: BECKMANN({ guard: false, cutoff: false }),
        summary: said('n·h = 0, α = 1e-4', 'D', 'NaN', '0'),
      },
      {
        // cos⁴θ · α² = 1e-40 · 1e-8 underflows to 0 while exp(−tan²/α²) already has
        name: '0/0 just above the horizon',
        code: BECKMANN({ cutoff: false }),
        summary: said('n·h = 1e-10, α = 1e-4', 'D', 'NaN', '0'),
      },
    ],
  },
  'shader-smith-g1': {
    correct: SMITH_G1(true),
    mistakes: [
      {
        // G1(n·l ≤ 0) = 0 and n·v = 0: 0/0, first at n·l = −0.5, n·v = 0
        name: 'no zero below the horizon: 0/0',
        code: SMITH_G1(false),
        summary: said('n·l = −0.5, n·v = 0, α = 1e-4', 'V', 'NaN', '0'),
      },
      {
        // G = G1 G1 instead of V = G / ((n·l)(n·v)): furthest where n·l n·v is smallest
        name: 'G instead of V',
        code: SMITH_G1(true).replace(' / (nl * nv)', ''),
        summary: said('n·l = 1e-7, n·v = 1e-7, α = 1e-4', 'V', '4e-6', '4e8'),
      },
    ],
  },
  'shader-smith-correlated': {
    correct: CORRELATED(),
    mistakes: [
      {
        name: 'the microfacet BRDF’s 1/4 folded in',
        code: CORRELATED({ numerator: '0.5' }),
        summary: /your V is [\d.e]+; the reference is [\d.e]+\.$/,
        detail: /your V is 0\.25× the reference\. Is a factor of 1\/4 missing or extra\?/,
      },
      {
        // n·v √(n·l² + α²…) + n·l √(n·v² + α²…) ≈ n·v |n·l| + n·l n·v = 0 for n·l < 0 < n·v once float32 loses α²:
        // Inf at α = 1e-4 (at which n·v first depends on float32's rounding)
        name: 'unclamped grazing input',
        code: CORRELATED({ guard: false }),
        summary: /^At n·l = −0\.5, n·v = 0\.\d+, α = 1e-4 your V is Inf; the reference is 0\.$/,
      },
    ],
  },
  'shader-lambert-tradeoff': {
    correct: TRADEOFF(),
    mistakes: [
      {
        name: 'missing π',
        code: TRADEOFF({ pi: '' }),
        // the ratio is π everywhere; the worst is where the reference is largest, n·l and n·v near 1 (float32 ties)
        summary: /^At c_diff = 1, n·l = [\d.]+, n·v = [\d.]+, cos φ = −1, α = 0\.5 your diffuse BRDF is 0\.92; /,
        detail: /is 3\.1× the reference\. Is a factor of π missing or extra\?/,
      },
      {
        // the weight at n·l = n·v = −0.5: (1 − (0.04 + 0.96 · 1.5⁵))² / π ≈ 13
        name: 'unclamped grazing input',
        code: TRADEOFF({ guard: false }),
        summary: said('c_diff = 1, n·l = −0.5, n·v = −0.5, cos φ = −1, α = 0.5', 'diffuse BRDF', '13', '0'),
      },
      {
        name: 'plain Lambert, no weight (the starter)',
        starter: true,
        summary: said('c_diff = 1, n·l = −0.5, n·v = −0.5, cos φ = −1, α = 0.5', 'diffuse BRDF', '0.32', '0'),
      },
    ],
  },
  'shader-fix-cancellation': {
    correct: GGX(),
    mistakes: [
      {
        // 1 − c·c loses up to ~1e-4 of sin²θ, twice that of D, where sin²θ outweighs α²c² (1 − c ~ 1e-4)
        name: 'cancellation in 1 − c·c (the starter)',
        starter: true,
        summary:
          /^At n·h = 0\.999\d*, α = (1e-4|3e-4|0\.001|0\.003|0\.01) your D is [\d.]+; the reference is [\d.]+\.$/,
      },
    ],
  },
  'shader-ggx-aniso': {
    correct: GGX_ANISO(),
    mistakes: [
      {
        // hx/αy, hy/αx: at grazing h across the tangent (φh = 90°) the swap reads αx = 2 where αy = 0.02 belongs,
        // 1/(π·0.04·(1/4)²) ≈ 130 against 1/(π·0.04·(1/0.02²)²) ≈ 1.3e-6
        name: 'αx and αy swapped',
        code: GGX_ANISO({ scale: 'h.xy / a.yx' }),
        summary: said('n·h = 1e-4, φh = 90, αx = 2, αy = 0.02', 'D', '130', '1.3e-6'),
      },
      {
        // h.z = 0: the sum is (1/2)² along t at αx = 2, so D = 1/(π·0.04·(1/4)²) ≈ 130 where the reference is 0
        name: 'no zero below the horizon',
        code: GGX_ANISO({ guard: false }),
        summary: said('n·h = 0, φh = 0, αx = 2, αy = 0.02', 'D', '130', '0'),
      },
      {
        // αx² in place of αx αy: 100× where αy/αx = 100, and the excess in tolerances saturates where D is large:
        // across the tangent (φh = 90°, where D at αy = 1 is tens), at any of the n·h near the peak (float32 ties)
        name: 'the isotropic normalisation 1/(π α²) with α = αx',
        code: GGX_ANISO({ norm: 'a.x * a.x' }),
        summary: /^At n·h = 0\.\d+, φh = 90, αx = 0\.01, αy = 1 your D is 3200; the reference is 32\.$/,
      },
    ],
  },
  'shader-smith-aniso': {
    correct: PROJECTED(),
    mistakes: [
      {
        // cos² and sin² swapped: along t at αx = 2, αy = 0.05, r(w) ≈ 0.05 in place of 2 for both grazing directions,
        // V = 2/(2·1e-4·0.05) = 2e5 against 2/(2·1e-4·2) = 5000
        name: 'cos²φ and sin²φ swapped',
        code: PROJECTED({ cos2: 's * s', sin2: 'c * c' }),
        summary: said('n·l = 1e-4, φl = 0, n·v = 1e-4, φv = 0, αx = 2, αy = 0.05', 'V', '2e5', '5000'),
      },
      {
        // along n (n·v = 1) sin θ = 0 and cos φ = 0/0: the first input with v along n and l above the horizon
        name: 'no guard where the azimuth has no meaning: 0/0',
        code: PROJECTED({ guard: false }),
        summary: said('n·l = 1e-4, φl = 0, n·v = 1, φv = 0, αx = 0.05, αy = 0.05', 'V', 'NaN', '40'),
      },
      {
        // αx in every azimuth: across t (φ = 90°) at αy = 10 αx, both grazing, r(w) ≈ 0.05 in place of 0.5
        name: 'the isotropic α = αx (the starter)',
        starter: true,
        summary: said('n·l = 1e-4, φl = 90, n·v = 1e-4, φv = 90, αx = 0.05, αy = 0.5', 'V', '2e5', '20000'),
      },
    ],
  },
};
