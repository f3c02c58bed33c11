// lesion.vert — a lesion inside the lungs (a tumour): a unit sphere scaled to its radius and placed at its centre,
// which the CPU moves each frame by the interior field (sim/motion/lesion_rows.h: the lesion's own coefficient
// rows, the same dot product with the force SH as a surface vertex's); lit from the eye like the lungs.
precision highp float;

layout(location = 0) in vec3 a_unit;  // a point of the unit sphere, which is also its outward normal

uniform mat4 u_model_view_proj;  // lung frame -> clip space of this eye
uniform vec3 u_eye_model;        // this eye's centre in the lung frame (the head light)
uniform vec3 u_centre;           // the lesion's centre this frame, mm, lung frame
uniform float u_radius;          // mm
uniform vec3 u_color;
uniform float u_ambient;

out vec3 v_color;

void main() {
  vec3 p = u_centre + u_radius * a_unit;
  float lambert = max(dot(a_unit, normalize(u_eye_model - p)), 0.0);
  v_color = u_color * (u_ambient + (1.0 - u_ambient) * lambert);
  gl_Position = u_model_view_proj * vec4(p, 1.0);
}
