// Per pixel of the sphere: the squared error of the approximation against the reference (mean over RGB), the
// squared reference and 1, to be summed on the GPU: RMS = sqrt(x / z), relative RMS = sqrt(x / y).
uniform sampler2D uImage;
uniform sampler2D uOther;
out vec4 fragColor;
void main() {
  vec4 a = texelFetch(uImage, ivec2(gl_FragCoord.xy), 0);
  vec3 r = texelFetch(uOther, ivec2(gl_FragCoord.xy), 0).rgb;
  vec3 d = a.rgb - r;
  fragColor = a.a > 0.5 ? vec4(dot(d, d) / 3.0, dot(r, r) / 3.0, 1.0, 0.0) : vec4(0.0);
}
