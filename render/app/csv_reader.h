// Reading the telemetry files of INTERFACE.md ("Telemetry files") back: trajectory.csv and
// events.csv, as `rugosim simulate` writes them, for `rugosim plot`. Every row is checked
// against the header, so a damaged or foreign file is rejected with the file, the line and what
// was expected instead of being drawn as nonsense. Columns the contract may add at the end of a
// row later are accepted and ignored.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "engine/dynamics/event_record.h"

namespace rugosim::app {

// A file that cannot be read or does not follow its format; what() names the file and, for a
// format error, the line ("FILE:LINE: expected ..., found ...").
class CsvError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Splits CSV text into records (RFC 4180): fields separated by commas, a field in double quotes
// may hold commas, newlines and doubled quotes. Lines may end in "\n" or "\r\n"; empty lines are
// skipped. Errors name `file` and the line where the record starts.
class CsvParser {
 public:
  CsvParser(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

  // The next record's fields into `fields`; false at the end of the text.
  bool next(std::vector<std::string>& fields);
  // The line (from 1) on which the record last returned by next() starts.
  std::size_t line() const { return record_line_; }
  const std::string& file() const { return file_; }

  // Throws CsvError "FILE:LINE: message" for the current record.
  [[noreturn]] void fail(std::string_view message) const;

 private:
  std::string_view text_;
  std::string file_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;  // line of text_[pos_]
  std::size_t record_line_ = 0;
};

// The rows of a trajectory.csv; `body` indexes `bodies`, the names in order of first appearance.
struct TrajectoryRow {
  std::uint64_t frame = 0;
  double time = 0.0;  // s
  std::size_t body = 0;
  double x = 0.0, y = 0.0, angle = 0.0;    // m, m, rad
  double vx = 0.0, vy = 0.0, omega = 0.0;  // m/s, m/s, rad/s
  double kinetic_energy = 0.0;             // J per unit thickness
};

struct Trajectory {
  std::vector<std::string> bodies;
  std::vector<TrajectoryRow> rows;
};

// The rows of an events.csv; `body_a` and `body_b` index `bodies` (order of first appearance).
struct EventRow {
  double time = 0.0;  // s
  EventKind kind = EventKind::kCollision;
  std::size_t body_a = 0, body_b = 0;
  std::uint64_t segment_a = 0, segment_b = 0;
  double t_a = 0.0, t_b = 0.0;
  double x = 0.0, y = 0.0, nx = 0.0, ny = 0.0;
  double lambda_a = 0.0, lambda_b = 0.0, mu = 0.0;
  double vn = 0.0, vt = 0.0, jn = 0.0, jt = 0.0;
};

struct Events {
  std::vector<std::string> bodies;
  std::vector<EventRow> rows;
};

// Read and check a whole file; throw CsvError when it is missing, unreadable, not the format
// (header, field count, a field that is not a number, an unknown event kind).
Trajectory read_trajectory_csv(const std::string& path);
Events read_events_csv(const std::string& path);

// The same from text already in memory; `file` names it in the errors.
Trajectory parse_trajectory_csv(std::string_view text, const std::string& file);
Events parse_events_csv(std::string_view text, const std::string& file);

}  // namespace rugosim::app
