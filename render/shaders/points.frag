// points.frag — flat per-lung colour, lit in deform.vert; used for points, mesh and the grey rest overlay.
precision mediump float;

flat in vec3 v_color;
out vec4 o_color;

void main() { o_color = vec4(v_color, 1.0); }
