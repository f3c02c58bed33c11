// lens.frag — radial (barrel) pre-distortion for HMD optics, per colour channel for chromatic aberration:
//   r_src = r (1 + k1 r^2 + k2 r^4), with r measured from the lens centre in units of the eye's half height.
precision highp float;

uniform sampler2D u_eye_image;  // the undistorted frame
uniform vec4 u_eye_rect;        // this eye's rectangle in u_eye_image's texture coordinates: x0, y0, w, h
uniform vec2 u_center;          // lens centre in eye uv
uniform float u_aspect;         // eye width / height
uniform vec3 u_k1;              // per channel R, G, B
uniform vec3 u_k2;

in vec2 v_uv;
out vec4 o_color;

float sample_channel(vec2 d, float k1, float k2, int channel) {
  float r2 = dot(d, d);
  vec2 s = d * (1.0 + k1 * r2 + k2 * r2 * r2);
  vec2 uv = u_center + vec2(s.x / u_aspect, s.y) * 0.5;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 0.0;
  return texture(u_eye_image, u_eye_rect.xy + uv * u_eye_rect.zw)[channel];
}

void main() {
  vec2 d = vec2((v_uv.x - u_center.x) * u_aspect, v_uv.y - u_center.y) * 2.0;
  o_color = vec4(sample_channel(d, u_k1.r, u_k2.r, 0), sample_channel(d, u_k1.g, u_k2.g, 1),
                 sample_channel(d, u_k1.b, u_k2.b, 2), 1.0);
}
