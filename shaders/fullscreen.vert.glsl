// A full-screen pass: the geometry is a 2x2 plane in clip space.
void main() { gl_Position = vec4(position.xy, 0.0, 1.0); }
