// The material lab's tangent field on its sphere (view space: z towards the viewer, y up), the frame (t, b, n) an
// anisotropic lobe is laid in (src/lab/lab-anisotropy.js). The brushing's lines run along b: with TANGENT_ALONG
// along uTangentAxis projected on the tangent plane (great circles through ±axis, a brushed plate), else in
// circles around the pole uTangentAxis (a machined disc). t = b × n crosses them; then both turn by
// uTangentRotation about n. Where the field has no direction (n along the axis: one point) any frame stands in.
#include "env.glsl"

uniform vec3 uTangentAxis;
uniform float uTangentRotation;

mat3 tangentFrame(vec3 n) {
#ifdef TANGENT_ALONG
  vec3 b = uTangentAxis - dot(uTangentAxis, n) * n;
#else
  vec3 b = cross(uTangentAxis, n);
#endif
  if (dot(b, b) < 1e-12) return frameAround(n);
  b = normalize(b);
  vec3 t = cross(b, n);
  float c = cos(uTangentRotation);
  float s = sin(uTangentRotation);
  return mat3(c * t + s * b, c * b - s * t, n);
}
