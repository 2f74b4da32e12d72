// Shows the running mean of the media tracer's samples, sRGB encoded.
#include "color.glsl"
uniform sampler2D uSum;
uniform vec2 uSize; // of the canvas; the sum may be smaller (traced at a capped resolution)
out vec4 fragColor;
void main() {
  vec4 s = texture(uSum, gl_FragCoord.xy / uSize);
  fragColor = vec4(linearToSrgb(s.rgb / max(s.a, 1.0)), 1.0);
}
