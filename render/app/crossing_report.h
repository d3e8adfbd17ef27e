// Accepted crossings, said out loud (INTERFACE.md, "Command line"): the World never ends a
// step with two bodies across each other unless a bounded loop ran out and its documented
// fallback accepted the state (StepStats::crossings). A run then says so on stderr at the
// first one (time, bodies, depth), its summary counts them, stats.json records the first, and
// with --strict (for CI) the command exits 1 after writing its outputs.
#pragma once

#include <cstdio>
#include <string>

#include "engine/dynamics/world.h"

namespace rugosim::app {

// "warning: t = 0.0123 s: bodies "a" and "b" cross, 3.2e-05 m deep: ..." for the World's first
// accepted crossing; empty when there is none.
std::string crossing_warning(const World& world);

// Prints crossing_warning() to `out` the first time it is not empty.
class CrossingWatch {
 public:
  void check(const World& world, std::FILE* out);

 private:
  bool reported_ = false;
};

// With --strict and at least one accepted crossing: prints why to `out` and returns the exit
// code 1 (kExitFailure); otherwise returns `code`. An interrupted run (130) keeps its code.
int strict_exit_code(const World& world, bool strict, int code, std::FILE* out);

}  // namespace rugosim::app
