// Comparing a rendered frame with a golden PNG, for the visual-regression checks behind
// `rugosim snapshot`: a tolerance rule (renderers differ in the last bit of anti-aliasing, so an
// exact match is opt-in), the numbers a CI log needs, and a picture of where the frames differ.
#pragma once

#include <cstddef>
#include <string>

#include "render/image.h"

namespace rugosim {

struct CompareRule {
  bool exact = false;        // any difference fails
  int threshold = 16;        // a pixel differs when some channel (R, G, B, A) differs
                             // by more than this (0..255)
  double max_share = 0.001;  // the comparison fails when more than this share of pixels differ
                             // (0..1)
};

struct CompareResult {
  bool identical = false;      // byte-equal RGB
  bool passed = false;         // identical, or (!exact and within the rule)
  bool size_mismatch = false;  // then nothing else but the sizes below is meaningful
  // The inputs' sizes (px), always set; describe() names both on a size mismatch.
  int golden_width = 0, golden_height = 0;
  int actual_width = 0, actual_height = 0;
  std::size_t differing_pixels = 0;  // pixels with any channel difference > 0 (what `exact` counts)
  std::size_t failing_pixels = 0;    // pixels whose largest channel difference > threshold
  int worst = 0;                     // largest channel difference, 0..255
  int worst_x = -1, worst_y = -1;    // where (first in row-major order); -1 when identical
  double failing_share = 0.0;        // failing_pixels / pixel count (0 for an empty image)
  // Bounding box of the failing pixels (of the differing pixels when the rule is exact), empty
  // (all −1) when there are none: x0, y0, x1, y1 inclusive, px.
  int box_x0 = -1, box_y0 = -1, box_x1 = -1, box_y1 = -1;
};

// Compares the RGB channels of `actual` with those of `golden` under `rule`. Images of
// different sizes give size_mismatch (and fail). Throws std::invalid_argument for a rule out of
// range (threshold outside 0..255, max_share outside [0, 1] or not finite) and for an image
// whose pixel buffer does not hold width × height × 4 bytes. Rows that are byte-equal are
// skipped with memcmp, the others counted in a vectorised loop; no allocation.
CompareResult compare_images(const Image& golden, const Image& actual, const CompareRule& rule);

// A picture of the difference for a human: the actual frame washed out to a light grey (its luma
// blended 75 % towards white, so 191..255) so that the scene stays recognisable, failing pixels
// (above the threshold; under an exact rule every differing pixel) pure red #ff0000, pixels that
// differ only within the threshold orange #ffa500, and a 1 px red rectangle whose lines lie 3 px
// outside the box of the failing pixels (sides outside the image not drawn) so that a single
// changed pixel is findable. Opaque, the size of the inputs; on a size mismatch the actual's size,
// all red. Throws as compare_images.
Image difference_image(const Image& golden, const Image& actual, const CompareRule& rule);

// One line for a log: "identical"; "size mismatch: golden 320×180, actual 321×180"; otherwise
// "12 pixels differ (0.0208%, rule: threshold 16, max 0.1%), worst 87 at (120, 44), in the box
// (118, 40)–(131, 52)", counting failing pixels (differing ones under an exact rule, "rule:
// exact"), with ", 3 more within the threshold" when some pixels differ by no more than it.
std::string describe(const CompareResult& result, const CompareRule& rule);

}  // namespace rugosim
