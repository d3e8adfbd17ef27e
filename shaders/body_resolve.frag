// Fills, second pass: turns the body index left by the first pass into the body's colour, or
// the background. With MSAA the pass runs once per sample (gl_SampleID), so the colour target's
// own resolve averages the samples of an edge pixel.
#ifdef MSAA
uniform usampler2DMS ids;
#else
uniform usampler2D ids;
#endif
uniform samplerBuffer palette;  // per body: fill colour, outline colour
uniform vec4 background;

layout(location = 0) out vec4 colour;

void main() {
#ifdef MSAA
  uint id = texelFetch(ids, ivec2(gl_FragCoord.xy), gl_SampleID).r;
#else
  uint id = texelFetch(ids, ivec2(gl_FragCoord.xy), 0).r;
#endif
  colour = id == 0u ? background : texelFetch(palette, int(2u * (id - 1u)));
}
