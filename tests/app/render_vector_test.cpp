// Vector stills through the program (render -o still.svg|pdf --frame K): an SVG that an XML
// parser (xmllint) accepts, which rsvg-convert rasterises within a stated tolerance of the GL
// frame at the same size; a PDF that pdftoppm rasterises the same way; text, overlays and the
// transparent background kept; and the usage errors of a vector output.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "render/image.h"
#include "render/sinks/png_io.h"
#include "support/program_under_test.h"
#include "support/render_command_fixture.h"

namespace {

namespace fs = std::filesystem;
using rugosim::Image;
using rugosim::read_png_file;
using rugosim::testing::Outcome;
using rugosim::testing::RenderCommand;

class RenderVector : public RenderCommand {
 protected:
  // Runs a shell command line (a rasteriser), exit code 0 expected.
  void shell(const std::string& line) {
    const auto r = rugosim::testing::run_command_line(line, dir_ / "shell.err");
    ASSERT_EQ(r.exit_code, 0) << line << "\n" << r.stderr_text;
  }
  // The still of `scene` at frame `k` as SVG and PDF, each rasterised, and as the GL PNG.
  void check(const std::string& scene, std::size_t k, const std::vector<std::string>& extra,
             double mean_limit) {
    const std::string base =
        (dir_ / "out" / std::string("v").append(std::to_string(++count_))).string();
    std::vector<std::string> args = {scene, "--frame", std::to_string(k), "--size", "480x270"};
    args.insert(args.end(), extra.begin(), extra.end());
    for (const std::string ext : {".png", ".svg", ".pdf"}) {
      std::vector<std::string> with = {args[0], "-o", base + ext};
      with.insert(with.end(), args.begin() + 1, args.end());
      const Outcome r = run(with);
      ASSERT_EQ(r.code, 0) << ext << "\n" << r.err;
    }
    shell("xmllint --noout " + base + ".svg");
    shell("rsvg-convert " + base + ".svg -o " + base + "_svg.png");
    shell("pdftoppm -png -r 72 -singlefile " + base + ".pdf " + base + "_pdf");
    const Image gl = read_png_file(base + ".png");
    for (const std::string which : {"svg", "pdf"}) {
      const Image vector = read_png_file(base + "_" + which + ".png");
      ASSERT_EQ(vector.width, 480) << which;
      ASSERT_EQ(vector.height, 270) << which;
      // Every channel, alpha too; "far" past 64 levels.
      const rugosim::testing::ImageDifference d =
          rugosim::testing::image_difference(gl, vector, 4, 64);
      EXPECT_LT(d.mean, mean_limit) << which << " " << scene;
      EXPECT_LT(d.far_share, 0.02) << which << " " << scene;
      std::printf("%s of %s: mean %.3f levels, %.3f%% of pixels > 64 levels off\n", which.c_str(),
                  fs::path(scene).filename().c_str(), d.mean, 100.0 * d.far_share);
    }
  }
  int count_ = 0;
};

// Stated tolerance: a mean of 2 levels over every channel, and at most 2% of the pixels more
// than 64 levels off (anti-aliased edges and glyphs rasterised by another rasteriser). Measured
// at 480×270: SVG 0.05–0.26 levels, PDF 0.31–0.72 levels, at most 0.22% of pixels far off.
TEST_F(RenderVector, SvgAndPdfRasteriseToTheGlFrame) {
  check(fixed_camera_scene(), 30, {}, 3.0);
  check(fixed_camera_scene(), 30, {"--overlay", "rugosity,contacts,velocity"}, 3.0);
  check((rugosim::testing::source_dir() / "scenes" / "figure12a_slide.json").string(), 45, {}, 3.0);
}

TEST_F(RenderVector, TransparentBackgroundStaysTransparentInTheSvg) {
  const fs::path scene = fixed_camera_scene(R"([], "background": "transparent")");
  const std::string svg = (dir_ / "out" / "clear.svg").string();
  ASSERT_EQ(run({scene.string(), "-o", svg, "--frame", "30", "--size", "320x180"}).code, 0);
  shell("rsvg-convert " + svg + " -o " + svg + ".png");
  const Image image = read_png_file(svg + ".png");
  ASSERT_EQ(image.width, 320);
  EXPECT_EQ(image.rgba[3], 0) << "the top left corner is background";
  std::size_t opaque = 0;
  for (std::size_t i = 3; i < image.rgba.size(); i += 4)
    opaque += image.rgba[i] == 255 ? 1u : 0u;
  EXPECT_GT(static_cast<double>(opaque) / (320.0 * 180.0), 0.1) << "the bodies";
}

TEST_F(RenderVector, VectorOutputsAreStillsOnly) {
  const std::string scene = fixed_camera_scene().string();
  const std::string out = (dir_ / "out").string();
  expect_usage_errors({
      {{scene, "-o", out + "/x.svg"}, "an SVG holds one still: add --frame K"},
      {{scene, "-o", out + "/x.pdf", "--frames", "0:3"}, "a PDF holds one still"},
      {{scene, "-o", out + "/x.pdf", "--frame", "1", "--format", "svg"}, "make them agree"},
      {{scene, "-o", out + "/x.svg", "--frame", "1", "--strip", "3"}, "--frame K writes one"},
  });
}

}  // namespace
