// lens.vert — a full-screen triangle for the lens-distortion pass; one per eye viewport.
precision highp float;

out vec2 v_uv;  // 0..1 over the eye's viewport

void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));  // (0,0) (2,0) (0,2)
  v_uv = corner;
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
