// Numbers on the command line (INTERFACE.md, "Command line"): every numeric option is read
// by one strict parser and checked against its range before CLI11 converts it, so that NaN,
// infinities, trailing junk and out-of-range values get one message in the project's words:
//   --fps: expected a number in (0, 1000] (frames per second), got "nan"
// CLI11's own checks print their bounds with every digit of a double (309 of them for
// DBL_MAX) and accept NaN for PositiveNumber; they are not used for numbers.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace rugosim::app {

struct NumberRange {
  double min = 0.0;
  bool min_open = false;  // (min, ... rather than [min, ...
  double max = 0.0;
  bool max_open = false;
  bool integer = false;  // a whole number (written without a fraction or exponent)
  std::string unit;      // shown after the range: "s", "frames per second"; may be empty
};

// "a number in (0, 1000] (frames per second)" or "a whole number in [0, 51]".
std::string describe(const NumberRange& range);

// The number `text` spells, when all of it is one finite number (a whole number when
// `integer`: digits with an optional sign); nullopt otherwise.
std::optional<double> parse_number(const std::string& text, bool integer);

// "" when `text` is a number in `range`, else "expected <describe(range)>, got \"text\"".
std::string check_number(const std::string& text, const NumberRange& range);

// The name of every numeric option's validator, by which the tests find those options.
inline constexpr const char* kNumberValidator = "number";

// A CLI11 validator of check_number() named kNumberValidator: CLI11 prefixes the option's name
// to its message.
CLI::Validator number_in(const NumberRange& range);

}  // namespace rugosim::app
