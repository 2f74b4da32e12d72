// A quad in the plane of the unit sphere's centre, facing the camera (sphere-impostor.glsl): each fragment gets
// the point under its pixel centre in the sphere's units (view space x and y; the sphere is centred at the origin).
out vec2 vSphere;
void main() {
  vSphere = position.xy;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
