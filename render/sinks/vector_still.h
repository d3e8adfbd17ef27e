// One frame as a vector still, SVG or PDF, through cairo: the page is the frame's size in
// pixels (1 px = 1 pt), and it holds what the GL renderer draws, as paths — the background
// (none when transparent), every body's fill (even-odd, as the parity fill) and outline (the
// rugosity detail the raster frame shows, the same points), the rugosity overlay's colours,
// the contact and velocity overlays, and the frame's text in the same layout
// (FrameTextPainter) with the same font as glyph outlines.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "engine/dynamics/frame_snapshot.h"
#include "render/draw/scene_renderer.h"
#include "render/text/frame_text.h"

namespace rugosim {

enum class VectorFormat { kSvg, kPdf };

// The still's file, in memory (written with write_file_atomically, atomic_output_file.h). Throws
// std::runtime_error with cairo's reason when it cannot be made, and the font's error when
// text is asked for and the font cannot be opened.
std::vector<std::uint8_t> make_vector_still(VectorFormat format, const std::vector<BodyLook>& looks,
                                            const RenderSettings& settings,
                                            const FrameSnapshot& frame, const FrameText& text);

}  // namespace rugosim
