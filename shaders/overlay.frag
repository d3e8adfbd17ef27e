in vec2 local_px;
in vec4 overlay_colour;
flat in vec2 overlay_shape;

uniform float fringe;  // px of anti-aliasing ramp (0 with MSAA)

layout(location = 0) out vec4 colour;

void main() {
  float distance_px = overlay_shape.y > 0.5 ? length(local_px) : abs(local_px.y);
  float coverage = fringe > 0.0
                       ? clamp(overlay_shape.x + 0.5 * fringe - distance_px, 0.0, fringe) / fringe
                       : step(distance_px, overlay_shape.x);
  colour = vec4(overlay_colour.rgb, overlay_colour.a * coverage);
}
