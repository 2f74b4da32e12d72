// The material lab's punctual light, exact: one direction, pi f c_light (n·l) (lab-material.glsl).
uniform vec3 uPunctualDir;
uniform vec3 uPunctualCLight;

vec3 evaluatePunctual(mat3 toLocal, vec3 v) { return punctualRadiance(toLocal * uPunctualDir, v, uPunctualCLight); }
