// `rugosim plot` for papers: 18 pairs of bodies, of which the ten with the most events get their
// own colours and legend entries (with their counts) and the other eight one grey entry; SVG
// and PDF figures and a chosen size, through the program.
#include "render/app/plot_figures.h"

#include <cstdio>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <gtest/gtest.h>

#include "engine/dynamics/telemetry.h"
#include "render/image.h"
#include "render/sinks/png_io.h"
#include "support/file_text.h"
#include "support/program_under_test.h"

namespace {

namespace fs = std::filesystem;
using rugosim::app::EventRow;
using rugosim::app::Events;

// Pair p (bodies "rock p" and "rock p+1"... as "a_p" – "b_p") has 18 − p events: pair 0 the
// most. Collisions only, at times spread over 2 s.
Events eighteen_pairs() {
  Events events;
  for (int p = 0; p < 18; ++p) {
    events.bodies.push_back(fmt::format("a{}", p));
    events.bodies.push_back(fmt::format("b{}", p));
  }
  // Interleaved in time, so that first appearance is not the ranking.
  for (int k = 0; k < 18; ++k) {
    for (int p = 17; p >= 0; --p) {
      if (k >= 18 - p) continue;
      EventRow e;
      e.time = 0.1 * k + 0.001 * p;
      e.body_a = static_cast<std::size_t>(2 * p);
      e.body_b = static_cast<std::size_t>(2 * p + 1);
      e.mu = 0.1 + 0.01 * p;
      events.rows.push_back(e);
    }
  }
  return events;
}

std::string events_csv(const Events& events) {
  std::string text(rugosim::kEventsCsvHeader);
  for (const EventRow& e : events.rows) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "%.17g,collision,%s,%s,0,0,0,0,0,0,0,1,0.001,0.001,%.17g,-1,0,1,0\n", e.time,
                  events.bodies[e.body_a].c_str(), events.bodies[e.body_b].c_str(), e.mu);
    text += line;
  }
  return text;
}

TEST(PlotFigures, TheTenPairsWithTheMostEventsGetColoursAndTheRestOneGreyEntry) {
  const std::string script = rugosim::app::friction_script(eighteen_pairs(), "events.csv", true,
                                                           2.0, rugosim::app::FigureFormat{});
  std::vector<std::string> titles;
  std::set<std::string> colours;
  // Each legend entry: "keyentry ... linecolor rgb '#rrggbb' title '<title>' ...".
  const auto quoted_after = [&](std::size_t from, const std::string& key) {
    const std::size_t at = script.find(key, from);
    if (at == std::string::npos) return std::string();
    const std::size_t begin = at + key.size();
    return script.substr(begin, script.find('\'', begin) - begin);
  };
  for (std::size_t at = script.find("keyentry"); at != std::string::npos;
       at = script.find("keyentry", at + 1)) {
    const std::size_t line_end = script.find('\n', at);
    if (script.find("title '", at) > line_end) continue;
    colours.insert(quoted_after(at, "linecolor rgb '"));
    titles.push_back(quoted_after(at, "title '"));
  }
  ASSERT_EQ(titles.size(), 11u) << script;
  for (int p = 0; p < 10; ++p) {
    EXPECT_EQ(titles[static_cast<std::size_t>(p)], fmt::format("a{0} – b{0} ({1})", p, 18 - p));
  }
  EXPECT_EQ(titles[10], "8 other pairs");
  EXPECT_EQ(colours.size(), 11u) << "ten colours and the grey";
  EXPECT_EQ(colours.count("#9a9a9a"), 1u);
}

TEST(PlotFigures, AFewPairsAreAllNamedWithNoOtherEntry) {
  Events events = eighteen_pairs();
  std::erase_if(events.rows, [](const EventRow& e) { return e.body_a >= 6; });  // pairs 0..2
  const std::string script =
      rugosim::app::friction_script(events, "events.csv", true, 2.0, rugosim::app::FigureFormat{});
  EXPECT_EQ(script.find("other pair"), std::string::npos);
  EXPECT_NE(script.find("a2 – b2 (16)"), std::string::npos);
}

class PlotProgram : public ::testing::Test {
 protected:
  rugosim::testing::ScratchDir scratch_{"plot_figures"};
  const fs::path& dir_ = scratch_.path();

  int plot(const std::string& options) {
    const fs::path csv = dir_ / "events.csv";
    rugosim::testing::write_text(csv, events_csv(eighteen_pairs()));
    const std::string command = rugosim::testing::program() + " plot --events " + csv.string() +
                                " -o " + (dir_ / "figures").string() + " " + options + " 2> " +
                                (dir_ / "stderr.txt").string();
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
};

TEST_F(PlotProgram, SvgHoldsTheLegendAsTextAtTheChosenSize) {
  if (std::system("gnuplot --version > /dev/null 2>&1") != 0) GTEST_SKIP() << "no gnuplot";
  ASSERT_EQ(plot("--format svg --size 800x500"), 0)
      << rugosim::testing::read_text(dir_ / "stderr.txt");
  const std::string svg = rugosim::testing::read_text(dir_ / "figures" / "friction.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("width=\"800\""), std::string::npos);
  EXPECT_NE(svg.find("height=\"500\""), std::string::npos);
  EXPECT_NE(svg.find("a0 – b0 (18)"), std::string::npos);
  EXPECT_NE(svg.find("a9 – b9 (9)"), std::string::npos);
  EXPECT_EQ(svg.find("a10 – b10"), std::string::npos) << "past the ten: grey, unnamed";
  EXPECT_NE(svg.find("8 other pairs"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "figures" / "friction.png"));
}

TEST_F(PlotProgram, PdfAndAPngOfTheChosenSize) {
  if (std::system("gnuplot --version > /dev/null 2>&1") != 0) GTEST_SKIP() << "no gnuplot";
  ASSERT_EQ(plot("--format pdf"), 0) << rugosim::testing::read_text(dir_ / "stderr.txt");
  EXPECT_EQ(rugosim::testing::read_text(dir_ / "figures" / "friction.pdf").substr(0, 5), "%PDF-");
  ASSERT_EQ(plot("--size 640x400"), 0) << rugosim::testing::read_text(dir_ / "stderr.txt");
  const rugosim::Image png = rugosim::read_png_file((dir_ / "figures" / "friction.png").string());
  EXPECT_EQ(png.width, 640);
  EXPECT_EQ(png.height, 400);
  EXPECT_EQ(plot("--size 10x10"), 2);
  EXPECT_NE(rugosim::testing::read_text(dir_ / "stderr.txt").find("--size"), std::string::npos);
  EXPECT_EQ(plot("--format jpg"), 2);
}

}  // namespace
