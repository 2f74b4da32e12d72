// One step of a sum reduction: each output texel holds the sum of a 4x4 block of the source.
uniform sampler2D uSrc;
uniform ivec2 uSrcSize;
out vec4 fragColor;
void main() {
  ivec2 base = ivec2(gl_FragCoord.xy) * 4;
  vec4 s = vec4(0.0);
  for (int j = 0; j < 4; j++) {
    for (int i = 0; i < 4; i++) {
      ivec2 p = base + ivec2(i, j);
      if (p.x < uSrcSize.x && p.y < uSrcSize.y) s += texelFetch(uSrc, p, 0);
    }
  }
  fragColor = s;
}
