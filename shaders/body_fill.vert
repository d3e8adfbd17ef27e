// Fills: the parity triangles of each body's outline (render/draw/parity_fill.h), placed by the
// body's transform (body frame → normalised device coordinates, from a texture buffer).
layout(location = 0) in vec2 position;  // m, body frame
layout(location = 1) in uint body;      // index of the body

uniform samplerBuffer transforms;  // per body: (m00, m10, m01, m11), (tx, ty, 0, 0)
uniform samplerBuffer palette;     // per body: fill, outline, fill key

flat out vec4 key;

void main() {
  vec4 m = texelFetch(transforms, int(2u * body));
  vec4 t = texelFetch(transforms, int(2u * body + 1u));
  gl_Position = vec4(mat2(m.xy, m.zw) * position + t.xy, 0.0, 1.0);
  key = texelFetch(palette, int(3u * body + 2u));
}
