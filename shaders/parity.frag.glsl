// Evaluates one function per texel for the parity harness: arguments in, results out (float32 targets).
// CALL is defined by the harness as the expression under test, wrapped to a vec4.
// Up to eight arguments: a = the first four, b = the next four.
uniform sampler2D uArgs;
uniform sampler2D uArgs2;
out vec4 fragColor;
void main() {
  vec4 a = texelFetch(uArgs, ivec2(gl_FragCoord.xy), 0);
  vec4 b = texelFetch(uArgs2, ivec2(gl_FragCoord.xy), 0);
  fragColor = CALL;
}
