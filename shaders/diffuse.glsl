// Diffuse terms, mirrors src/math/diffuse.js.
#include "common.glsl"
float diffuseLambert(float cdiff) { return saturate(cdiff) / PI; }
