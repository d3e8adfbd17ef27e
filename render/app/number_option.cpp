#include "render/app/number_option.h"

#include <cmath>
#include <cstdlib>

#include "engine/core/number_text.h"

namespace rugosim::app {

std::string describe(const NumberRange& range) {
  std::string text = range.integer ? "a whole number " : "a finite number ";
  if (std::isinf(range.max)) {
    // Unbounded above: the run-length checks bound durations (run_length.h).
    text += (range.min_open ? "> " : ">= ") + number_text(range.min);
  } else {
    text += range.min_open ? "in (" : "in [";
    text += number_text(range.min) + ", " + number_text(range.max);
    text += range.max_open ? ")" : "]";
  }
  if (!range.unit.empty()) text += " (" + range.unit + ")";
  return text;
}

std::optional<double> parse_number(const std::string& text, bool integer) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text.front())) != 0) {
    return std::nullopt;
  }
  if (integer) {
    // Digits only, so that "1e3", "0x10" and "1.0" are refused rather than read in part.
    const std::size_t first = (text[0] == '-' || text[0] == '+') ? 1 : 0;
    if (first == text.size()) return std::nullopt;
    for (std::size_t i = first; i < text.size(); ++i) {
      if (text[i] < '0' || text[i] > '9') return std::nullopt;
    }
  }
  // strtod also reads "nan", "inf" and hexadecimal: only decimal notation is a number here.
  if (text.find_first_not_of("0123456789+-.eE") != std::string::npos) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  if (!std::isfinite(value)) return std::nullopt;
  // Underflow to 0 or a denormal (1e-400) still reads as the number it rounds to.
  return value;
}

std::string check_number(const std::string& text, const NumberRange& range) {
  const std::optional<double> value = parse_number(text, range.integer);
  const bool ok = value && (range.min_open ? *value > range.min : *value >= range.min) &&
                  (range.max_open ? *value < range.max : *value <= range.max);
  if (ok) return {};
  return "expected " + describe(range) + ", got \"" + text + "\"";
}

CLI::Validator number_in(const NumberRange& range) {
  return CLI::Validator([range](std::string& text) { return check_number(text, range); },
                        describe(range), kNumberValidator);
}

}  // namespace rugosim::app
