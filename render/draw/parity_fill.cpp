#include "render/draw/parity_fill.h"

#include <algorithm>
#include <numeric>

namespace rugosim {

ParityFill parity_fill(std::span<const Vec2> outline, std::size_t stride) {
  ParityFill fill;
  if (outline.size() < 3) return fill;
  stride = std::max<std::size_t>(stride, 2);
  std::vector<std::uint32_t> finer(outline.size());
  std::iota(finer.begin(), finer.end(), std::uint32_t{0});
  auto triangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    fill.indices.insert(fill.indices.end(), {a, b, c});
  };
  // Each pass: a coarser ring of every stride-th point of `finer`, and the caps between them.
  while (finer.size() > stride) {
    std::vector<std::uint32_t> coarser;
    const std::size_t m = finer.size();
    for (std::size_t start = 0; start < m; start += stride) {
      coarser.push_back(finer[start]);
      const std::size_t end = std::min(start + stride, m);  // the cap runs to finer[end % m]
      for (std::size_t i = start + 1; i < end; ++i) {
        triangle(finer[start], finer[i], finer[(i + 1) % m]);
      }
    }
    finer = std::move(coarser);
  }
  if (finer.size() >= 3) {
    for (const std::uint32_t i : finer)
      fill.anchor += outline[i];
    fill.anchor /= static_cast<double>(finer.size());
    const auto anchor = static_cast<std::uint32_t>(outline.size());
    for (std::size_t i = 0; i < finer.size(); ++i) {
      triangle(anchor, finer[i], finer[(i + 1) % finer.size()]);
    }
  }
  return fill;
}

}  // namespace rugosim
