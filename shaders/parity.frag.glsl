// Evaluates one function per texel for the parity harness: arguments in, results out (float32 targets).
// CALL is defined by the harness as the expression under test, wrapped to a vec4, over a = the first four
// floats of the input, b = the next four and arg(i) any one (parity-args.glsl).
#include "parity-args.glsl"
out vec4 fragColor;
void main() {
  vec4 a = argTexel(0);
  vec4 b = argTexel(1);
  fragColor = CALL;
}
