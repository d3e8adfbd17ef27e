// Overlays (contacts, velocities): lines and discs built on the CPU each frame, already in
// normalised device coordinates, each vertex knowing its offset in pixels from the line's
// centre or the disc's centre.
layout(location = 0) in vec2 position;  // normalised device coordinates
layout(location = 1) in vec2 local;     // px: (along, across) for a line, offset for a disc
layout(location = 2) in vec4 tint;
layout(location = 3) in vec2 shape;     // (half width or radius in px, 0 line / 1 disc)

out vec2 local_px;
out vec4 overlay_colour;
flat out vec2 overlay_shape;

void main() {
  gl_Position = vec4(position, 0.0, 1.0);
  local_px = local;
  overlay_colour = tint;
  overlay_shape = shape;
}
