// metal-fresnel, the three ways to draw a metal's Fresnel curve from two numbers per channel that it compares
// with the exact conductor Fresnel equations: each model's parameters, fitted to a channel's measured (n, k), and
// its value. Pure (Node, no DOM).
import {
  conductorIorFromF0EdgeTint,
  edgeTintFromConductorIor,
  f82TintFromConductor,
  fresnelConductor,
  fresnelF82Tint,
  fresnelSchlick,
} from '../../math/fresnel.js';

/** The models, in legend order: label, source, and how it is drawn. */
export const METAL_MODELS = {
  schlick: { label: 'Schlick', cite: 'Schlick 1994', dash: [6, 4] },
  gulbrandsen: { label: 'Gulbrandsen edge tint', cite: 'Gulbrandsen 2014', dash: [2, 5] },
  f82Tint: { label: 'F82-tint', cite: 'Hoffman 2023', dash: [12, 3, 2, 3] },
};

/**
 * Each model's parameters for a channel with optical constants (eta, k): F0 (all three), F82-tint's tint at
 * cos θ = 1/7, Gulbrandsen's edge tint g and the (n, k) it maps back to.
 */
export function channelFit(eta, k) {
  const { f0, tint } = f82TintFromConductor(eta, k);
  const edgeTint = edgeTintFromConductorIor(eta, k);
  return { eta, k, f0, tint, edgeTint, gulbrandsenIor: conductorIorFromF0EdgeTint(f0, edgeTint) };
}

const VALUES = {
  schlick: (fit, mu) => fresnelSchlick(fit.f0, mu),
  gulbrandsen: (fit, mu) => fresnelConductor(mu, ...fit.gulbrandsenIor),
  f82Tint: (fit, mu) => fresnelF82Tint(fit.f0, fit.tint, mu),
};

/** The value of `model` (a key of METAL_MODELS) for a channel's fit at cos θ = mu. */
export const modelValue = (model, fit, mu) => VALUES[model](fit, mu);
