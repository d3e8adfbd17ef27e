// Sweep specs (sweep_spec.h, sweep_expression.h, sweep_measures.h): the built-in incline sweep
// loads into its 64 tasks in order; every kind of mistake is reported at its JSON path with what
// was expected (and the nearest name for a misspelt one); seeded random specs keep the task
// numbering's invariants; reductions and expressions give their closed forms.
#include "render/app/sweep_spec.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <random>
#include <set>
#include <string>

#include <fmt/core.h>
#include <gtest/gtest.h>

#include "render/app/sweep_expression.h"
#include "render/app/sweep_measures.h"
#include "support/program_under_test.h"

namespace rugosim::app {
namespace {

using nlohmann::json;
using testing::ScratchDir;
using testing::source_dir;

std::string incline_spec() {
  return (source_dir() / "scenes" / "sweeps" / "incline_friction.json").string();
}

// Writes `spec` (JSON text, the incline scene by absolute path unless it names one) and loads it.
SweepSpecLoad load_text(const ScratchDir& dir, const std::string& text) {
  const std::string path = (dir.path() / "spec.json").string();
  std::ofstream(path) << text;
  return load_sweep_spec(path);
}

std::string scene_path() {
  return (source_dir() / "scenes" / "validation_incline_below.json").string();
}

// A valid spec with `axes` and `measures` (JSON arrays as text) spliced in.
std::string spec_with(const std::string& axes, const std::string& measures = "[]",
                      const std::string& command = R"({"simulate": {}})") {
  return fmt::format(
      R"({{"version": 1, "scene": "{}", "axes": {}, "command": {}, "measures": {}}})", scene_path(),
      axes, command, measures);
}

// The first error's path and message, as "PATH: MESSAGE"; "ok" when none.
std::string first_error(const SweepSpecLoad& load) {
  if (load.errors.empty()) return "ok";
  return load.errors.front().path + ": " + load.errors.front().message;
}

TEST(SweepSpec, TheInclineSweepHas64TasksLastAxisFastest) {
  const SweepSpecLoad load = load_sweep_spec(incline_spec());
  ASSERT_TRUE(load.errors.empty()) << first_error(load);
  const SweepSpec& spec = load.spec;
  EXPECT_EQ(spec.name, "incline_friction");
  ASSERT_EQ(spec.axes.size(), 2u);
  EXPECT_EQ(spec.task_count(), 64u);
  EXPECT_EQ(spec.axes[0].values.front(), json(100));
  EXPECT_EQ(spec.axes[0].values.back(), json(450));
  EXPECT_EQ(spec.axes[1].values[1], json(15));
  EXPECT_EQ(spec.coordinates(9), (std::vector<std::size_t>{1, 1}));
  EXPECT_EQ(spec.coordinates(63), (std::vector<std::size_t>{7, 7}));
  EXPECT_EQ(spec.describe(9), "gain=150 angle=15");

  const json scene = task_scene(spec, 9);
  EXPECT_EQ(scene["world"]["friction_gain"], json(150));
  EXPECT_EQ(scene["world"]["duration"], json(2.0));
  const double theta = 15.0 * std::numbers::pi / 180.0;
  EXPECT_NEAR(scene["world"]["gravity"][0].get<double>(), 9.81 * std::sin(theta), 1e-13);
  EXPECT_NEAR(scene["world"]["gravity"][1].get<double>(), -9.81 * std::cos(theta), 1e-13);
  // The scene file itself is untouched by the spec.
  EXPECT_EQ(spec.scene["world"]["friction_gain"], json(250.0));

  // A range's ends as written (0.1 + 3 × 0.2 is 0.7000000000000001 in doubles); whole numbers
  // as integers, whether from a range or a list.
  const ScratchDir dir("sweep_spec_values");
  const SweepSpecLoad ends =
      load_text(dir, spec_with(R"([{"name": "g", "range": {"from": 0.1, "to": 0.7, "step": 0.2},
                          "pointer": "/world/friction_gain"},
                         {"name": "s", "values": [1.0, 2.5], "pointer": "/world/duration"}])"));
  ASSERT_TRUE(ends.errors.empty()) << first_error(ends);
  EXPECT_EQ(ends.spec.axes[0].values.size(), 4u);
  EXPECT_EQ(ends.spec.axes[0].values.back(), json(0.7));
  EXPECT_TRUE(ends.spec.axes[1].values[0].is_number_integer());
  EXPECT_EQ(ends.spec.axes[1].values[1], json(2.5));

  // The same bytes, the same hash; the hash is what a task's result is matched by.
  EXPECT_EQ(load_sweep_spec(incline_spec()).spec.hash, spec.hash);
}

TEST(SweepSpec, ReportsEveryMistakeAtItsPath) {
  const ScratchDir dir("sweep_spec_errors");
  const std::string axis =
      R"([{"name": "gain", "values": [100, 200], "pointer": "/world/friction_gain"}])";
  struct Case {
    std::string text;
    std::string expected;  // a part of the first error, "PATH: MESSAGE"
  };
  const std::vector<Case> cases = {
      {"{", "invalid JSON"},
      {fmt::format(
           R"({{"version": 1, "scene": "{}", "axis": [], "command": {{"simulate": {{}}}}}})",
           scene_path()),
       R"(/axis: unknown key "axis"; did you mean "axes"?)"},
      {fmt::format(
           R"({{"version": 2, "scene": "{}", "axes": {}, "command": {{"simulate": {{}}}}}})",
           scene_path(), axis),
       "/version: expected an integer in [1, 1]"},
      {R"({"version": 1, "scene": "missing.json", "axes": [], "command": {"simulate": {}}})",
       "/scene: cannot read the scene file"},
      {spec_with(R"([{"name": "g", "values": [1], "pointer": "/wrld/friction_gain"}])"),
       R"(/axes/0/pointer: the scene has nothing at "/wrld")"},
      {spec_with(R"([{"name": "g", "values": [1], "pointer": "world/friction_gain"}])"),
       "/axes/0/pointer: expected a JSON pointer"},
      {spec_with(R"([{"name": "g", "values": [1], "pointer": "/world/gravity/2"}])"),
       "expected an index below 2"},
      {spec_with(R"([{"name": "g", "values": [1]}])"), "/axes/0: expected \"pointer\""},
      {spec_with(R"([{"name": "g", "values": [1], "range": {"from": 0, "to": 1, "count": 2},
                      "pointer": "/world/friction_gain"}])"),
       "/axes/0: expected exactly one of \"values\", \"range\" and \"seeds\""},
      {spec_with(R"([{"name": "g", "range": {"from": 0, "to": 1, "count": 2, "step": 1},
                      "pointer": "/world/friction_gain"}])"),
       "/axes/0/range: expected one of \"count\""},
      {spec_with(R"([{"name": "sin", "values": [1], "pointer": "/world/friction_gain"}])"),
       "/axes/0/name: expected a name"},
      {spec_with(R"([{"name": "g", "values": [1], "pointer": "/world/friction_gain"},
                     {"name": "g", "values": [1], "pointer": "/world/duration"}])"),
       R"(/axes/1/name: the name "g" is taken)"},
      {spec_with(R"([{"name": "g", "values": [1], "pointer": "/world/friction_gain"},
                     {"name": "h", "values": [1], "pointer": "/world/friction_gain"}])"),
       R"(/axes/1/pointer: "/world/friction_gain" is set elsewhere in the spec too)"},
      {spec_with(R"j([{"name": "angle", "values": [10],
                      "set": {"/world/gravity/0": "9.81 * sin(angel)"}}])j"),
       R"j(/axes/0/set/~1world~1gravity~10: "9.81 * sin(angel)": unknown name "angel" (did you mean "angle"?); the names known here: angle)j"},
      {spec_with(R"([{"name": "s", "values": ["a", "b"], "set": {"/world/duration": "s"}}])"),
       "/axes/0/values: expected numbers"},
      {spec_with(axis, R"([{"name": "x", "trajectory": {"body": "blok", "column": "x"}}])"),
       R"(/measures/0/trajectory/body: the scene has no body named "blok"; did you mean "block"?)"},
      {spec_with(axis, R"([{"name": "x", "trajectory": {"body": "incline", "column": "x"}}])"),
       R"("incline" is fixed)"},
      {spec_with(axis, R"([{"name": "x", "trajectory": {"body": "block", "column": "z"}}])"),
       "/measures/0/trajectory/column: expected one of x, y, angle"},
      {spec_with(
           axis,
           R"([{"name": "x", "trajectory": {"body": "block", "column": "x", "reduce": "avg"}}])"),
       "/measures/0/trajectory/reduce: expected one of first, last, mean"},
      {spec_with(axis, R"([{"name": "n", "stats": "step"}])"),
       R"(/measures/0/stats: stats.json has no number "step"; did you mean "steps"?)"},
      {spec_with(axis, R"([{"name": "n", "expression": "gain + slide"}])"),
       R"(/measures/0/expression: "gain + slide": unknown name "slide"; the names known here: gain)"},
      {spec_with(axis, R"([{"name": "n", "stats": "steps"}])", R"({"render": {}})"),
       "/measures/0: a render task writes no telemetry"},
      {spec_with(axis, "[]", R"({"simulate": {"accuracy": "fast"}})"),
       "/command/simulate/accuracy: expected draft, normal or precise"},
      {spec_with(axis, "[]", R"({"simulate": {}, "render": {}})"),
       "/command: expected exactly one of"},
      {spec_with(R"([{"name": "g", "values": [100, -1], "pointer": "/world/friction_gain"}])"),
       "/world/friction_gain: task 1 (g=-1) makes a scene that is not valid"},
      // Pointers that nlohmann's own lookups would throw on, and changes that overlap.
      {spec_with(
           R"([{"name": "g", "values": [1], "pointer": "/world/gravity/99999999999999999999999"}])"),
       R"(/axes/0/pointer: "/world/gravity" is an array of 2 values: expected an index below 2)"},
      {spec_with(
           R"([{"name": "g", "values": [1], "pointer": "/bodies/99999999999999999999999/name"}])"),
       R"("/bodies" is an array of 2 values)"},
      {spec_with(R"([{"name": "g", "values": [1], "pointer": "/world/gravity/00"}])"),
       R"(got "00")"},
      {spec_with(R"([{"name": "g", "values": [1], "pointer": "/world/duration/x"}])"),
       R"("/world/duration" is a number, not an object or an array)"},
      {spec_with(R"([{"name": "w", "values": [1, 2], "pointer": "/world"},
                     {"name": "g", "values": [1], "pointer": "/world/friction_gain"}])"),
       R"(/axes/1/pointer: "/world/friction_gain" overlaps "/world", which the spec sets too)"},
      {fmt::format(R"({{"version": 1, "scene": "{}", "set": {{"/world/gravity": [0, -9.81]}},
                       "axes": [{{"name": "s", "values": [1], "pointer": "/world/gravity/0"}}],
                       "command": {{"simulate": {{}}}}}})",
                   scene_path()),
       R"(/axes/0/pointer: "/world/gravity/0" overlaps "/world/gravity", which the spec sets too)"},
      {spec_with(axis, "[]", R"({"simulat": {}})"),
       "/command/simulat: unknown key \"simulat\"; did you mean \"simulate\"?"},
      {spec_with(R"([{"name": "g", "range": {"from": 0, "to": 1, "step": 0.3},
                      "pointer": "/world/friction_gain"}])"),
       "/axes/0/range/step: expected a step that divides to − from (1) into whole steps"},
      {spec_with(R"([{"name": "g", "range": {"from": 0, "to": 1, "count": 1},
                      "pointer": "/world/friction_gain"}])"),
       "/axes/0/range/count: expected a count of at least 2"},
      {spec_with(R"([{"name": "s", "seeds": {"first": 18446744073709551615, "count": 3},
                      "pointer": "/world/seed"}])"),
       "/axes/0/seeds/count: expected the seeds to stay below 2^64"},
      {spec_with(
           R"([{"name": "g", "values": [1], "set": {"/world/friction_gain": "100 * g, 5"}}])"),
       R"("100 * g, 5" gives 2 values (separated by commas); expected one)"},
  };
  for (const Case& c : cases) {
    const std::string error = first_error(load_text(dir, c.text));
    EXPECT_NE(error.find(c.expected), std::string::npos)
        << "spec: " << c.text << "\nerror: " << error << "\nexpected: " << c.expected;
  }
}

// Seeded random specs of 1 to 3 axes (values, ranges by count or step, seeds): the tasks are the
// product of the axes, numbered with the last axis fastest, each task's scene holds its values,
// and the load is deterministic. RUGOSIM_SWEEP_CASES sets the number of cases (default 150).
TEST(SweepSpec, RandomSpecsKeepTheTaskNumbering) {
  const ScratchDir dir("sweep_spec_random");
  const char* env = std::getenv("RUGOSIM_SWEEP_CASES");
  const int cases = env != nullptr ? std::atoi(env) : 150;
  const std::vector<std::string> pointers = {"/world/friction_gain", "/world/duration"};
  std::mt19937_64 rng(20261205);
  for (int c = 0; c < cases; ++c) {
    const std::size_t axes = 1 + rng() % 3;
    std::string text = "[";
    std::vector<std::size_t> sizes;
    for (std::size_t a = 0; a < axes; ++a) {
      const std::size_t n = 1 + rng() % 5;
      sizes.push_back(n);
      std::string values;
      switch (rng() % 3) {
        case 0: {
          values = "\"values\": [";
          for (std::size_t i = 0; i < n; ++i)
            values += fmt::format("{}{}", i > 0 ? ", " : "", 0.5 + double(rng() % 1000) / 7.0);
          values += "]";
          break;
        }
        case 1:
          // A count of 1 is a range from a value to itself.
          values = fmt::format(R"("range": {{"from": 0.25, "to": {}, "count": {}}})",
                               n == 1 ? 0.25 : 0.25 + double(1 + rng() % 50), n);
          break;
        default:
          values = fmt::format(R"("seeds": {{"first": {}, "count": {}}})", rng() % 1000, n);
      }
      // Seeds go into the world's seed (a key the scene leaves out), the others into world numbers.
      const std::string pointer = values[1] == 's' ? "/world/seed" : pointers[a % 2];
      text += fmt::format(R"({}{{"name": "a{}", {}, "pointer": "{}"}})", a > 0 ? ", " : "", a,
                          values, pointer);
    }
    text += "]";
    // Two axes may not share a pointer: such cases are valid specs only with distinct targets.
    std::set<std::string> targets;
    const SweepSpecLoad load = load_text(dir, spec_with(text));
    bool shared = false;
    for (const SweepAxis& axis : load.spec.axes)
      shared |= !targets.insert(axis.pointer).second;
    if (shared) {
      EXPECT_FALSE(load.errors.empty());
      continue;
    }
    ASSERT_TRUE(load.errors.empty()) << text << "\n" << first_error(load);
    const SweepSpec& spec = load.spec;
    std::size_t product = 1;
    for (std::size_t n : sizes)
      product *= n;
    ASSERT_EQ(spec.task_count(), product) << text;
    std::set<std::vector<std::size_t>> seen;
    for (std::size_t task = 0; task < spec.task_count(); ++task) {
      const std::vector<std::size_t> index = spec.coordinates(task);
      std::size_t back = 0;  // the index rebuilt, last axis fastest
      for (std::size_t a = 0; a < axes; ++a) {
        ASSERT_LT(index[a], sizes[a]);
        back = back * sizes[a] + index[a];
      }
      EXPECT_EQ(back, task);
      seen.insert(index);
      const json scene = task_scene(spec, task);
      for (std::size_t a = 0; a < axes; ++a)
        EXPECT_EQ(scene[json::json_pointer(spec.axes[a].pointer)], spec.axes[a].values[index[a]]);
    }
    EXPECT_EQ(seen.size(), product);
    EXPECT_EQ(load_text(dir, spec_with(text)).spec.hash, spec.hash);
  }
}

TEST(SweepExpression, ArithmeticComparisonsAndNames) {
  EXPECT_DOUBLE_EQ(evaluate_expression("9.81 * sin(a * pi / 180)", {{"a", 30.0}}),
                   9.81 * std::sin(30.0 * std::numbers::pi / 180.0));
  EXPECT_EQ(evaluate_expression("abs(s) < 0.001", {{"s", -0.0005}}), 1.0);
  EXPECT_EQ(evaluate_expression("abs(s) < 0.001", {{"s", 0.5}}), 0.0);
  EXPECT_EQ(evaluate_expression("a > 1 ? 2 : 3", {{"a", 2.0}}), 2.0);
  EXPECT_EQ(evaluate_expression("max(a, b, 4)", {{"a", 2.0}, {"b", 5.0}}), 5.0);
  EXPECT_THROW(evaluate_expression("1 / a", {{"a", 0.0}}), ExpressionError);
  EXPECT_THROW(evaluate_expression("a +", {{"a", 0.0}}), ExpressionError);
  EXPECT_EQ(expression_uses("a * 2 + pi", {{"a", 1.0}, {"b", 2.0}}), std::vector<std::string>{"a"});
  EXPECT_TRUE(valid_variable_name("friction_gain"));
  for (const char* bad : {"", "2a", "a-b", "pi", "sin", "_e"})
    EXPECT_FALSE(valid_variable_name(bad)) << bad;
}

TEST(SweepMeasures, ReductionsOfASeries) {
  const std::vector<double> v = {3.0, -1.0, 4.0, 1.5};
  EXPECT_EQ(reduce_values(v, "first"), 3.0);
  EXPECT_EQ(reduce_values(v, "last"), 1.5);
  EXPECT_EQ(reduce_values(v, "mean"), 7.5 / 4.0);
  EXPECT_EQ(reduce_values(v, "min"), -1.0);
  EXPECT_EQ(reduce_values(v, "max"), 4.0);
  EXPECT_EQ(reduce_values(v, "delta"), -1.5);
  EXPECT_EQ(reduce_values(v, "range"), 5.0);
  EXPECT_EQ(reduce_values(v, "sum"), 7.5);
  EXPECT_EQ(reduce_values(v, "count"), 4.0);
  EXPECT_EQ(reduce_values({}, "count"), 0.0);
  EXPECT_EQ(reduce_values({}, "sum"), 0.0);
  EXPECT_FALSE(reduce_values({}, "max").has_value());
}

}  // namespace
}  // namespace rugosim::app
