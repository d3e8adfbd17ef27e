// Fills, second pass, over each body's box: turns the body index left by the first pass into the
// body's colour; pixels of no body keep the cleared background. With MSAA the pass runs once
// per sample (gl_SampleID), so the colour target's own resolve averages an edge pixel's samples.
#ifdef MSAA
uniform usampler2DMS ids;
#else
uniform usampler2D ids;
#endif
uniform samplerBuffer palette;  // per body: fill colour, outline colour

layout(location = 0) out vec4 colour;

void main() {
#ifdef MSAA
  uint id = texelFetch(ids, ivec2(gl_FragCoord.xy), gl_SampleID).r;
#else
  uint id = texelFetch(ids, ivec2(gl_FragCoord.xy), 0).r;
#endif
  if (id == 0u) discard;
  colour = texelFetch(palette, int(2u * (id - 1u)));
}
