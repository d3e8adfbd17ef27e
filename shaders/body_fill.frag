// Fills: writes the body's key (background XOR fill colour, 8 bits a channel) with the XOR
// logic op onto the cleared background. A pixel inside a body is covered an odd number of times
// by that body's triangles and an even number of times by every other body's (it is outside
// them), so what remains is background XOR key = the body's colour, or the background outside
// every body: concave outlines need no triangulation, and all bodies fill in one draw.
flat in vec4 key;
layout(location = 0) out vec4 colour;

void main() { colour = key; }
