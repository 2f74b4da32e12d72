// Writes an environment into the app's equirectangular float target: from an equirectangular texture (any
// size: a dropped file, the sky, the furnace) or, with CUBE_SOURCE, from a cube map (three.js's room).
// With WEIGHTED it writes (L cos(el), cos(el)): mip-maps of that, divided rgb / a, average radiance by solid
// angle, where plain mips of an equirectangular map would smear the small polar texels over large ones.
#include "env.glsl"
#ifdef CUBE_SOURCE
uniform samplerCube uSource;
#else
uniform sampler2D uSource;
#endif
uniform vec2 uSize;
out vec4 fragColor;
void main() {
  vec2 uv = gl_FragCoord.xy / uSize;
#ifdef CUBE_SOURCE
  vec3 d = equirectDirection(uv);
  vec3 c = texture(uSource, vec3(-d.x, d.y, d.z)).rgb; // three.js renders cube maps mirrored in x
#else
  vec3 c = texture(uSource, uv).rgb;
#endif
#ifdef WEIGHTED
  float w = cos((uv.y - 0.5) * PI);
  fragColor = vec4(max(c, vec3(0.0)) * w, w);
#else
  fragColor = vec4(max(c, vec3(0.0)), 1.0);
#endif
}
