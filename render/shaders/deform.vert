// deform.vert — the paper's stage 3 (eq. 7) per vertex, then Lambert + ambient lighting for point or mesh drawing.
//
//   D_I = sum_lm T^I_lm f_lm          (f the force SH of one mL: D in mm per mL)
//   u_I = D_I e_I + R_I w             (e_I: the vertex's baked direction of motion; its normal n_I in the paper's
//                                      model, the principal direction of its vector displacement in the sliding
//                                      model; R_I w: the sliding model's off-axis part, its 3x4 basis times the
//                                      orientation's linear weights; docs/design.md "Vector displacement")
//   p'_I = p_I + dV u_I
//
// The ventilation map colours each vertex by the depth of air its patch of surface swept over the last breath,
// n_I . u_I times the lung's last tidal volume (mm: volume per area), on a ramp whose top is u_sweep_full_scale_mm
// (render/ventilation_ramp.h holds the same ramp for the legend); 0 there draws the lung's own colour.
//
// The host prepends `#version 300 es` and these defines (render/shader_program.cpp):
//   DEFORM          1: evaluate eq. (7); 0: draw a_position as given (rest shape, CPU-deformed or captured positions)
//   COEFF_VEC4      number of vec4 holding the L^2 coefficients (zero-padded to a multiple of 4)
//   COEFF_TEXTURE   1: coefficients in a float texture fetched by gl_VertexID; 0: vertex attributes
//   CULL            1: move back-facing points out of the clip volume (points mode); 0: keep all (mesh, capture)
//   OFF_AXIS        1: add the off-axis part (a sliding-model asset); 0: none (the paper's model)
// The transform-feedback capture (deform once, then draw both eyes) records v_position.

precision highp float;
precision highp int;

layout(location = 0) in vec3 a_position;  // rest position x_I, mm, lung frame
layout(location = 1) in vec3 a_normal;    // outward unit normal n_I

#if DEFORM
layout(location = 11) in vec3 a_direction;  // e_I, unit (render/lung_drawable.h, kDirectionAttribute)
#if OFF_AXIS
layout(location = 12) in vec4 a_off_x;      // row x of R_I: (r0, r_x, r_y, r_z), mm per unit pressure
layout(location = 13) in vec4 a_off_y;
layout(location = 14) in vec4 a_off_z;
uniform vec4 u_linear;                      // w of this vertex's lung, mm per mL per unit of R
#endif
uniform vec4 u_force[COEFF_VEC4];  // f_lm of this vertex's lung, per mL: D in mm per mL
uniform float u_volume;            // dV of this vertex's lung, mL
uniform float u_sweep_ml;          // the lung's last tidal volume, mL (the ventilation map)
#if COEFF_TEXTURE
uniform highp sampler2D u_coeff;   // texel (v * COEFF_VEC4 + k) holds T^v_{4k..4k+3}
uniform int u_coeff_width;         // texels per row of u_coeff
#else
// T^I_lm, 4 per attribute (GLSL ES 3.00 has no attribute arrays, hence one name each; at most 9 = 36 values).
layout(location = 2) in vec4 a_coeff0;
#if COEFF_VEC4 > 1
layout(location = 3) in vec4 a_coeff1;
#endif
#if COEFF_VEC4 > 2
layout(location = 4) in vec4 a_coeff2;
#endif
#if COEFF_VEC4 > 3
layout(location = 5) in vec4 a_coeff3;
#endif
#if COEFF_VEC4 > 4
layout(location = 6) in vec4 a_coeff4;
#endif
#if COEFF_VEC4 > 5
layout(location = 7) in vec4 a_coeff5;
#endif
#if COEFF_VEC4 > 6
layout(location = 8) in vec4 a_coeff6;
#endif
#if COEFF_VEC4 > 7
layout(location = 9) in vec4 a_coeff7;
#endif
#if COEFF_VEC4 > 8
layout(location = 10) in vec4 a_coeff8;
#endif
#endif
#endif

uniform mat4 u_model_view_proj;  // lung frame -> clip space of this eye
uniform vec3 u_eye_model;        // this eye's centre in the lung frame (back-face test and head light)
uniform vec3 u_color;            // lung colour
uniform float u_ambient;         // ambient share of the lighting
uniform float u_point_size;      // pixels (the paper: 5)
uniform float u_sweep_full_scale_mm;  // > 0: colour by the ventilation map, this sweep at the ramp's top

out vec3 v_position;             // deformed position, captured by transform feedback
flat out vec3 v_color;

// D_I of eq. (7): the dot product of the vertex's coefficients with the lung's force SH.
float displacement_eq7() {
#if DEFORM
  vec4 acc = vec4(0.0);
#if COEFF_TEXTURE
  for (int k = 0; k < COEFF_VEC4; ++k) {
    int texel = gl_VertexID * COEFF_VEC4 + k;
    acc += texelFetch(u_coeff, ivec2(texel % u_coeff_width, texel / u_coeff_width), 0) * u_force[k];
  }
#else
  acc += a_coeff0 * u_force[0];
#if COEFF_VEC4 > 1
  acc += a_coeff1 * u_force[1];
#endif
#if COEFF_VEC4 > 2
  acc += a_coeff2 * u_force[2];
#endif
#if COEFF_VEC4 > 3
  acc += a_coeff3 * u_force[3];
#endif
#if COEFF_VEC4 > 4
  acc += a_coeff4 * u_force[4];
#endif
#if COEFF_VEC4 > 5
  acc += a_coeff5 * u_force[5];
#endif
#if COEFF_VEC4 > 6
  acc += a_coeff6 * u_force[6];
#endif
#if COEFF_VEC4 > 7
  acc += a_coeff7 * u_force[7];
#endif
#if COEFF_VEC4 > 8
  acc += a_coeff8 * u_force[8];
#endif
#endif
  return acc.x + acc.y + acc.z + acc.w;
#else
  return 0.0;
#endif
}

// The ventilation map's ramp from no sweep (0) to full scale (1): dark blue, teal, green, yellow (viridis-like, so
// that it reads in grey too); the same stops as render/ventilation_ramp.h.
vec3 ventilation_ramp(float s) {
  s = clamp(s, 0.0, 1.0);
  vec3 c0 = vec3(0.27, 0.00, 0.33), c1 = vec3(0.23, 0.32, 0.55), c2 = vec3(0.13, 0.57, 0.55),
       c3 = vec3(0.37, 0.79, 0.38), c4 = vec3(0.99, 0.91, 0.14);
  if (s < 0.25) return mix(c0, c1, s * 4.0);
  if (s < 0.5) return mix(c1, c2, (s - 0.25) * 4.0);
  if (s < 0.75) return mix(c2, c3, (s - 0.5) * 4.0);
  return mix(c3, c4, (s - 0.75) * 4.0);
}

void main() {
#if DEFORM
  vec3 u = displacement_eq7() * a_direction;  // D e, mm per mL
#if OFF_AXIS
  u += vec3(dot(a_off_x, u_linear), dot(a_off_y, u_linear), dot(a_off_z, u_linear));  // + R w
#endif
  vec3 p = a_position + u_volume * u;  // p' = p + dV (D e + R w)
  float sweep_mm = u_sweep_ml * dot(a_normal, u);
#else
  vec3 p = a_position;
  float sweep_mm = 0.0;
#endif
  v_position = p;

  // The head light sits at the eye; the rest normal stands for the deformed one (displacements are small).
  vec3 to_eye = u_eye_model - p;
  float facing = dot(a_normal, to_eye) * inversesqrt(max(dot(to_eye, to_eye), 1e-12));  // cos of the view angle
  float lambert = max(facing, 0.0);
  vec3 base = u_sweep_full_scale_mm > 0.0 ? ventilation_ramp(sweep_mm / u_sweep_full_scale_mm) : u_color;
  v_color = base * (u_ambient + (1.0 - u_ambient) * lambert);
  gl_PointSize = u_point_size;
  gl_Position = u_model_view_proj * vec4(p, 1.0);
#if CULL
  // A back-facing point is hidden by the front surface: put it outside the clip volume so that the rasteriser
  // drops it before any setup (the per-point setup and raster are what cost on llvmpipe). Points just past the
  // limb (up to ~6 degrees) are kept: their splats still fill the silhouette's edge.
  if (facing < -0.1) gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
#endif
}
