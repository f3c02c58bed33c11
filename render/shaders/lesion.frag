// lesion.frag — the lesion's colour, lit in lesion.vert and interpolated over the ball.
precision mediump float;

in vec3 v_color;
out vec4 o_color;

void main() { o_color = vec4(v_color, 1.0); }
