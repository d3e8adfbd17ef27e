// Telemetry in the formats of INTERFACE.md ("Telemetry files"): rows of trajectory.csv and
// events.csv, and stats.json. Numbers are written in the shortest form that reads back to the
// same double (std::to_chars), so a CSV is exact, identical for identical runs, and compact.
// Writing files (atomically, with error handling) is the caller's job; these only format.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "engine/dynamics/accuracy.h"
#include "engine/dynamics/event_record.h"
#include "engine/dynamics/step_stats.h"
#include "engine/dynamics/world.h"

namespace rugosim {

inline constexpr std::string_view kTrajectoryCsvHeader =
    "frame,time,body,x,y,angle,vx,vy,omega,kinetic_energy\n";
inline constexpr std::string_view kEventsCsvHeader =
    "time,kind,body_a,body_b,segment_a,segment_b,t_a,t_b,x,y,nx,ny,lambda_a,lambda_b,mu,vn,vt,"
    "jn,jt\n";

// Appends the shortest round-trip decimal form of x ("nan"/"inf" never occur in a valid run,
// but are written as such rather than hidden).
void append_number(std::string& out, double x);

// Appends a CSV field: as is, or quoted (RFC 4180) when it holds a comma, quote or newline.
void append_csv_field(std::string& out, std::string_view field);

// Appends one trajectory.csv row per non-fixed body of the World, in body order, for output
// frame `frame` at the World's current time.
void append_trajectory_rows(std::string& out, const World& world, std::size_t frame);

// Appends the events.csv row of one event, naming bodies by their World names.
void append_event_row(std::string& out, const World& world, const ContactEvent& event);

// stats.json: every StepStats counter, sim_time and wall_time (s), one key per line, then, when
// given, "accuracy": the knobs the run used ({"max_step": 0.001, ...}, accuracy.h's keys), and
// when `world` is given and a crossing was accepted, "first_crossing": {"time", "body_a",
// "body_b", "depth"} (World::first_crossing, bodies by name).
std::string stats_json(const StepStats& stats, double wall_time, const Accuracy* accuracy = nullptr,
                       const World* world = nullptr);

}  // namespace rugosim
