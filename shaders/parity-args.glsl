// The parity harness's inputs (parity.frag.glsl): any number of floats per input. Input i's texel k (its floats
// 4k … 4k + 3) is ARG_ROWS rows below its texel k - 1; arg(i) is any one float of the input.
uniform sampler2D uArgs;
vec4 argTexel(int k) { return texelFetch(uArgs, ivec2(gl_FragCoord.xy) + ivec2(0, k * ARG_ROWS), 0); }
float arg(int i) { return argTexel(i / 4)[i % 4]; }
