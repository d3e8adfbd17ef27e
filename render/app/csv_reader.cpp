#include "render/app/csv_reader.h"

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <memory>
#include <sys/stat.h>
#include <system_error>
#include <unordered_map>

#include <fmt/core.h>

#include "engine/dynamics/telemetry.h"

namespace rugosim::app {
namespace {

// A field as it is shown in a message: quoted, and cut short when long, so one bad field in a
// huge file does not flood the terminal.
std::string shown(std::string_view text) {
  constexpr std::size_t kLongest = 60;
  std::string out = "\"";
  for (const char c : text.substr(0, kLongest)) {
    if (c == '\n') {
      out.append("\\n");
    } else if (c == '\r') {
      out.append("\\r");
    } else {
      out.push_back(c);
    }
  }
  out.append(text.size() > kLongest ? "\"..." : "\"");
  return out;
}

std::vector<std::string> split_header(std::string_view header) {
  std::vector<std::string> columns;
  while (!header.empty() && (header.back() == '\n' || header.back() == '\r')) {
    header.remove_suffix(1);
  }
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = header.find(',', start);
    columns.emplace_back(header.substr(start, comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return columns;
}

std::string join(const std::vector<std::string>& fields) {
  std::string out;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) out.push_back(',');
    out.append(fields[i]);
  }
  return out;
}

bool starts_with_columns(const std::vector<std::string>& fields,
                         const std::vector<std::string>& columns) {
  if (fields.size() < columns.size()) return false;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (fields[i] != columns[i]) return false;
  }
  return true;
}

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};

std::string read_whole_file(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    throw CsvError(fmt::format("{}: cannot read: {}", path, std::strerror(errno)));
  }
  if (S_ISDIR(info.st_mode)) throw CsvError(fmt::format("{}: cannot read: is a directory", path));
  const std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) throw CsvError(fmt::format("{}: cannot read: {}", path, std::strerror(errno)));
  std::string text;
  if (S_ISREG(info.st_mode)) text.reserve(static_cast<std::size_t>(info.st_size));
  char buffer[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, file.get())) > 0)
    text.append(buffer, got);
  if (std::ferror(file.get()) != 0) {
    throw CsvError(fmt::format("{}: cannot read: {}", path, std::strerror(errno)));
  }
  return text;
}

// One checked record of a telemetry file: typed access to its fields by column, each failure
// naming the file, line, column and the expectation.
class Row {
 public:
  Row(const CsvParser& parser, const std::vector<std::string>& fields,
      const std::vector<std::string>& columns)
      : parser_(parser), fields_(fields), columns_(columns) {
    if (fields.size() != columns.size()) {
      parser.fail(fmt::format("expected {} fields as in the header ({}), found {}", columns.size(),
                              join(columns), fields.size()));
    }
  }

  const std::string& text(std::size_t i) const { return fields_[i]; }

  double number(std::size_t i) const {
    const std::string& s = fields_[i];
    double value = 0.0;
    const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (s.empty() || error != std::errc() || end != s.data() + s.size()) {
      fail_field(i, "a number");
    }
    return value;
  }

  std::uint64_t whole_number(std::size_t i) const {
    const std::string& s = fields_[i];
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (s.empty() || error != std::errc() || end != s.data() + s.size()) {
      fail_field(i, "a whole number >= 0");
    }
    return value;
  }

  [[noreturn]] void fail_field(std::size_t i, std::string_view expected) const {
    parser_.fail(fmt::format("column {} (field {}): expected {}, found {}", columns_[i], i + 1,
                             expected, shown(fields_[i])));
  }

 private:
  const CsvParser& parser_;
  const std::vector<std::string>& fields_;
  const std::vector<std::string>& columns_;
};

// Body names in order of first appearance, each mapped to its index.
class NameTable {
 public:
  explicit NameTable(std::vector<std::string>& names) : names_(names) {}
  std::size_t index(const std::string& name) {
    const auto [it, added] = index_.try_emplace(name, names_.size());
    if (added) names_.push_back(name);
    return it->second;
  }

 private:
  std::vector<std::string>& names_;
  std::unordered_map<std::string, std::size_t> index_;
};

// Reads and checks the header of a telemetry file. Returns every column of the file's header:
// the expected ones, then any the contract added at the end of a row.
std::vector<std::string> read_header(CsvParser& parser, std::string_view expected_header,
                                     std::string_view kind, std::string_view other_header,
                                     std::string_view other_kind) {
  const std::vector<std::string> expected = split_header(expected_header);
  std::vector<std::string> fields;
  if (!parser.next(fields)) {
    throw CsvError(fmt::format("{}:1: expected the {} header \"{}\", found an empty file",
                               parser.file(), kind, join(expected)));
  }
  if (!starts_with_columns(fields, expected)) {
    // A swapped pair of options is the likeliest cause of a wrong header: say so. Otherwise
    // point at the first column that differs, which a long header would hide.
    std::string what;
    if (starts_with_columns(fields, split_header(other_header))) {
      what = fmt::format("found {} (that is the header of {}: were the files swapped?)",
                         shown(join(fields)), other_kind);
    } else {
      std::size_t i = 0;
      while (i < fields.size() && fields[i] == expected[i])
        ++i;
      what = i < fields.size()
                 ? fmt::format("column {} is {} instead of \"{}\"", i + 1, shown(fields[i]),
                               expected[i])
                 : fmt::format("found only {} columns ({})", fields.size(), join(fields));
    }
    parser.fail(fmt::format("expected the {} header \"{}\": {}", kind, join(expected), what));
  }
  return fields;
}

}  // namespace

void CsvParser::fail(std::string_view message) const {
  throw CsvError(fmt::format("{}:{}: {}", file_, record_line_, message));
}

bool CsvParser::next(std::vector<std::string>& fields) {
  fields.clear();
  const std::size_t size = text_.size();
  auto line_end_at = [&](std::size_t i) -> std::size_t {  // length of a line end at i, or 0
    if (i < size && text_[i] == '\n') return 1;
    if (i + 1 < size && text_[i] == '\r' && text_[i + 1] == '\n') return 2;
    return 0;
  };
  for (std::size_t n = line_end_at(pos_); n > 0; n = line_end_at(pos_)) {
    pos_ += n;
    ++line_;
  }
  if (pos_ >= size) return false;
  record_line_ = line_;
  std::string field;
  while (true) {
    field.clear();
    if (text_[pos_] == '"') {
      ++pos_;
      while (true) {
        if (pos_ >= size) fail("a quoted field in this record is never closed");
        const char c = text_[pos_++];
        if (c == '"') {
          if (pos_ < size && text_[pos_] == '"') {
            field.push_back('"');
            ++pos_;
            continue;
          }
          break;
        }
        if (c == '\n') ++line_;
        field.push_back(c);
      }
      if (pos_ < size && text_[pos_] != ',' && line_end_at(pos_) == 0) {
        fail(fmt::format("expected a comma or the end of the line after the closing quote of {}",
                         shown(field)));
      }
    } else {
      while (pos_ < size && text_[pos_] != ',' && line_end_at(pos_) == 0) {
        if (text_[pos_] == '"') {
          fail(
              fmt::format("a quote inside the unquoted field starting {} (quote the whole field "
                          "and double the quotes inside)",
                          shown(text_.substr(pos_ - field.size(), field.size() + 1))));
        }
        field.push_back(text_[pos_++]);
      }
    }
    fields.push_back(field);
    if (pos_ >= size) return true;
    if (text_[pos_] == ',') {
      ++pos_;
      if (pos_ >= size || line_end_at(pos_) > 0) {
        fields.emplace_back();  // a trailing comma ends with an empty field
        pos_ += line_end_at(pos_);
        ++line_;
        return true;
      }
      continue;
    }
    pos_ += line_end_at(pos_);
    ++line_;
    return true;
  }
}

Trajectory parse_trajectory_csv(std::string_view text, const std::string& file) {
  CsvParser parser(text, file);
  const std::vector<std::string> columns =
      read_header(parser, kTrajectoryCsvHeader, "trajectory.csv", kEventsCsvHeader, "events.csv");
  Trajectory out;
  NameTable names(out.bodies);
  std::vector<std::string> fields;
  while (parser.next(fields)) {
    const Row row(parser, fields, columns);
    TrajectoryRow r;
    r.frame = row.whole_number(0);
    r.time = row.number(1);
    r.body = names.index(row.text(2));
    r.x = row.number(3);
    r.y = row.number(4);
    r.angle = row.number(5);
    r.vx = row.number(6);
    r.vy = row.number(7);
    r.omega = row.number(8);
    r.kinetic_energy = row.number(9);
    out.rows.push_back(r);
  }
  return out;
}

Events parse_events_csv(std::string_view text, const std::string& file) {
  CsvParser parser(text, file);
  const std::vector<std::string> columns =
      read_header(parser, kEventsCsvHeader, "events.csv", kTrajectoryCsvHeader, "trajectory.csv");
  Events out;
  NameTable names(out.bodies);
  std::vector<std::string> fields;
  while (parser.next(fields)) {
    const Row row(parser, fields, columns);
    EventRow r;
    r.time = row.number(0);
    if (row.text(1) == to_string(EventKind::kCollision)) {
      r.kind = EventKind::kCollision;
    } else if (row.text(1) == to_string(EventKind::kContact)) {
      r.kind = EventKind::kContact;
    } else {
      row.fail_field(1, "\"collision\" or \"contact\"");
    }
    r.body_a = names.index(row.text(2));
    r.body_b = names.index(row.text(3));
    r.segment_a = row.whole_number(4);
    r.segment_b = row.whole_number(5);
    r.t_a = row.number(6);
    r.t_b = row.number(7);
    r.x = row.number(8);
    r.y = row.number(9);
    r.nx = row.number(10);
    r.ny = row.number(11);
    r.lambda_a = row.number(12);
    r.lambda_b = row.number(13);
    r.mu = row.number(14);
    r.vn = row.number(15);
    r.vt = row.number(16);
    r.jn = row.number(17);
    r.jt = row.number(18);
    out.rows.push_back(r);
  }
  return out;
}

Trajectory read_trajectory_csv(const std::string& path) {
  return parse_trajectory_csv(read_whole_file(path), path);
}

Events read_events_csv(const std::string& path) {
  return parse_events_csv(read_whole_file(path), path);
}

}  // namespace rugosim::app
