// Telemetry formatting (telemetry.h): the INTERFACE.md columns, exact numbers, quoting, and
// rows that read back to the World's state and events.
#include "engine/dynamics/telemetry.h"

#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "engine/core/random.h"
#include "support/test_bodies.h"
#include "support/test_output.h"

namespace rugosim {
namespace {

using testing::disk;
using testing::floor_block;
using testing::make_material;

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string field; std::getline(in, field, ',');)
    fields.push_back(field);
  return fields;
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(Telemetry, HeadersAreTheInterfaceColumns) {
  EXPECT_EQ(kTrajectoryCsvHeader, "frame,time,body,x,y,angle,vx,vy,omega,kinetic_energy\n");
  EXPECT_EQ(kEventsCsvHeader,
            "time,kind,body_a,body_b,segment_a,segment_b,t_a,t_b,x,y,nx,ny,lambda_a,lambda_b,"
            "mu,vn,vt,jn,jt\n");
}

// 20,000 seeded doubles over 600 orders of magnitude, both signs, and the extremes: each
// reads back with strtod to the same bits.
TEST(Telemetry, NumbersReadBackExactly) {
  Rng rng(91);
  std::vector<double> values = {0.0,
                                -0.0,
                                1.0,
                                0.1,
                                std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::min(),
                                std::numeric_limits<double>::denorm_min(),
                                -std::numeric_limits<double>::max()};
  for (int i = 0; i < 20000; ++i) {
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    values.push_back(sign * rng.uniform(1.0, 10.0) * std::pow(10.0, rng.uniform(-300.0, 300.0)));
  }
  for (const double x : values) {
    std::string text;
    append_number(text, x);
    EXPECT_TRUE(same_bits(std::strtod(text.c_str(), nullptr), x)) << text;
  }
  std::string short_form;
  append_number(short_form, 0.1);
  EXPECT_EQ(short_form, "0.1");  // shortest, not 0.10000000000000001
}

TEST(Telemetry, FieldsWithCommasOrQuotesAreQuoted) {
  std::string out;
  append_csv_field(out, "pebble");
  out.push_back('|');
  append_csv_field(out, "big, round");
  out.push_back('|');
  append_csv_field(out, "the \"stone\"");
  EXPECT_EQ(out, "pebble|\"big, round\"|\"the \"\"stone\"\"\"");
}

// A floor and two disks: one row per movable body per frame, in body order, each reading back
// to the body's state and kinetic energy exactly.
TEST(Telemetry, TrajectoryRowsReadBackToTheState) {
  World world;
  world.add_body(floor_block(3.0, 0.3, 0.0, make_material(0.5, 0.5)), "floor");
  world.add_body(disk(0.2, 32, Vec2(-0.5, 0.5), Vec2(1.0, 0.0), make_material(0.5, 0.5)), "a");
  world.add_body(disk(0.1, 32, Vec2(0.5, 0.8), Vec2(0.0, 1.0), make_material(0.5, 0.5)), "b");
  world.advance_to(0.25);
  std::string out;
  append_trajectory_rows(out, world, 7);
  const std::vector<std::string> lines = split_lines(out);
  ASSERT_EQ(lines.size(), 2u);
  for (std::size_t row = 0; row < 2; ++row) {
    const std::vector<std::string> f = split_fields(lines[row]);
    ASSERT_EQ(f.size(), 10u);
    const RigidBody& body = world.body(row + 1);
    EXPECT_EQ(f[0], "7");
    EXPECT_EQ(std::strtod(f[1].c_str(), nullptr), world.time());
    EXPECT_EQ(f[2], world.name(row + 1));
    const double expected[] = {body.state().position.x(), body.state().position.y(),
                               body.state().angle,        body.state().velocity.x(),
                               body.state().velocity.y(), body.state().angular_velocity,
                               body.kinetic_energy()};
    for (std::size_t k = 0; k < 7; ++k)
      EXPECT_TRUE(same_bits(std::strtod(f[3 + k].c_str(), nullptr), expected[k])) << f[3 + k];
  }
}

// A bouncing disk's events: 19 fields each, the kind, the names, jn >= 0 and μ exact.
TEST(Telemetry, EventRowsCarryEveryColumn) {
  World world;
  world.add_body(floor_block(3.0, 0.3, 0.0, make_material(0.5, 0.5), 1e-3), "floor");
  world.add_body(disk(0.2, 32, Vec2(0.0, 0.5), Vec2::Zero(), make_material(0.5, 0.5), 1e-3),
                 "ball");
  world.advance_to(1.0);
  ASSERT_FALSE(world.events().empty());
  std::string out;
  for (const ContactEvent& e : world.events())
    append_event_row(out, world, e);
  const std::vector<std::string> lines = split_lines(out);
  ASSERT_EQ(lines.size(), world.events().size());
  bool saw_collision = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::vector<std::string> f = split_fields(lines[i]);
    ASSERT_EQ(f.size(), 19u) << lines[i];
    EXPECT_TRUE(f[1] == "collision" || f[1] == "contact");
    saw_collision = saw_collision || f[1] == "collision";
    // Pairs are named in body order: A is the floor (added first), B the ball.
    EXPECT_EQ(f[2], "floor");
    EXPECT_EQ(f[3], "ball");
    EXPECT_GE(std::strtod(f[17].c_str(), nullptr), 0.0);
    EXPECT_EQ(std::strtod(f[14].c_str(), nullptr), world.events()[i].mu);
  }
  EXPECT_TRUE(saw_collision);
}

TEST(Telemetry, StatsJsonHasTheInterfaceKeys) {
  World world;
  world.add_body(floor_block(3.0, 0.3, 0.0, make_material(0.5, 0.5), 1e-3), "floor");
  world.add_body(disk(0.2, 32, Vec2(0.0, 0.5), Vec2::Zero(), make_material(0.5, 0.5), 1e-3));
  world.advance_to(1.0);
  const nlohmann::json j = nlohmann::json::parse(stats_json(world.stats(), 0.125));
  for (const char* key :
       {"steps", "bisections", "collisions", "contacts", "fallbacks", "crossings", "sim_time"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["steps"].get<std::uint64_t>(), world.stats().steps);
  EXPECT_EQ(j["collisions"].get<std::uint64_t>(), world.stats().collisions);
  EXPECT_EQ(j["sim_time"].get<double>(), 1.0);
  EXPECT_EQ(j["wall_time"].get<double>(), 0.125);
}

}  // namespace
}  // namespace rugosim
