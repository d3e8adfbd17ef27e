// Fills, first pass: writes body index + 1 into an integer target with the XOR logic op. A pixel
// inside a body is covered an odd number of times by that body's fan and an even number of
// times by every other fan (it is outside those bodies), so what remains is the index of the
// body it is in, or 0 outside all of them: concave outlines need no triangulation.
flat in uint body_id;
layout(location = 0) out uint id;

void main() { id = body_id; }
