// Coverage of a line `half_width` pixels wide: 1 inside, falling to 0 over the fringe (the
// shader anti-aliasing; with MSAA the fringe is 0 and the samples do it).
in float across;
in vec4 line_colour;

uniform float half_width;
uniform float fringe;

layout(location = 0) out vec4 colour;

void main() {
  float coverage = fringe > 0.0 ? clamp(half_width + 0.5 * fringe - abs(across), 0.0, fringe) / fringe
                                : 1.0;
  colour = vec4(line_colour.rgb, line_colour.a * coverage);
}
