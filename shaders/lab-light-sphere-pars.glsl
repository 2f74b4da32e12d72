// The material lab's sphere light, distant: its direction, the sine of its angular radius and its radiance
// (read by its approximation, lab-light-sphere.glsl, and by the reference, lab-reference.glsl).
uniform vec3 uSphereDir;
uniform float uSphereSin;
uniform vec3 uSphereRadiance;
