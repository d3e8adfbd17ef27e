// Colours a body is drawn with when the scene gives none: a muted, distinguishable palette for
// moving bodies, a stone grey for fixed ones; outlines are the fill darkened.
#pragma once

#include <cstddef>

#include "render/color.h"

namespace rugosim {

Rgba default_body_colour(std::size_t moving_index, bool fixed);
// The fill darkened (same hue), opaque.
Rgba outline_colour(const Rgba& fill);

}  // namespace rugosim
