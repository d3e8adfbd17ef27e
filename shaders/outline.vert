// Outlines: each edge of a body's detailed outline is a quad, widened along the vertex's miter
// direction in the body frame; rigid transforms keep lengths, so the width stays `half_width`
// pixels on screen whatever the body's placement.
layout(location = 0) in vec2 position;  // m, body frame, on the outline
layout(location = 1) in uint body;
layout(location = 2) in vec2 miter;     // body frame, unit normal scaled by the miter length
layout(location = 3) in float side;     // −1 inside, +1 outside
layout(location = 4) in float lambda;   // tolerance λ there, divided by the scene's largest

uniform samplerBuffer transforms;
uniform samplerBuffer palette;  // per body: fill, outline, fill key
uniform float metres_per_pixel;
uniform float half_width;    // px, of the visible line
uniform float fringe;        // px of anti-aliasing ramp beyond it (0 with MSAA)
uniform bool colour_by_lambda;

out float across;  // px from the centre line
out vec4 line_colour;

// A perceptually even ramp from dark blue (smooth) through green to yellow (rough).
vec3 ramp(float x) {
  x = clamp(x, 0.0, 1.0);
  vec3 a = vec3(0.267, 0.005, 0.329);
  vec3 b = vec3(0.128, 0.567, 0.551);
  vec3 c = vec3(0.993, 0.906, 0.144);
  return x < 0.5 ? mix(a, b, x * 2.0) : mix(b, c, x * 2.0 - 1.0);
}

void main() {
  vec4 m = texelFetch(transforms, int(2u * body));
  vec4 t = texelFetch(transforms, int(2u * body + 1u));
  float reach = half_width + fringe;
  vec2 p = position + miter * (side * reach * metres_per_pixel);
  gl_Position = vec4(mat2(m.xy, m.zw) * p + t.xy, 0.0, 1.0);
  across = side * reach;
  line_colour = colour_by_lambda ? vec4(ramp(lambda), 1.0)
                                 : texelFetch(palette, int(3u * body + 1u));
}
