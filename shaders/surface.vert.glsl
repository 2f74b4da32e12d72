// View-space position and normal of a mesh, for shading in view space.
out vec3 vNormal;
out vec3 vViewPosition;
void main() {
  vec4 viewPos = modelViewMatrix * vec4(position, 1.0);
  vViewPosition = viewPos.xyz;
  vNormal = normalMatrix * normal;
  gl_Position = projectionMatrix * viewPos;
}
