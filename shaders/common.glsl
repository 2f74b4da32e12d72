// Shared helpers for every chunk. GLSL ES 3.00, float32.
#define PI 3.14159265358979
float saturate(float x) { return clamp(x, 0.0, 1.0); }
vec3 saturate(vec3 x) { return clamp(x, 0.0, 1.0); }
// sin² from cos without cancellation near c = 1.
float sin2FromCos(float c) { return (1.0 - c) * (1.0 + c); }
