// Arithmetic expressions of a sweep spec ("9.81 * sin(angle * pi / 180)", "abs(slide) < 0.001"),
// evaluated with muparser (Debian's libmuparser-dev): + − * / ^, comparisons and && || (1 or 0),
// c ? a : b, sin cos tan asin acos atan sinh cosh tanh sqrt exp ln log10 log2 abs sign rint,
// min max sum avg; the constants pi (also _pi) and _e; the variables a sweep names.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rugosim::app {

// An expression that does not parse, uses an unknown name or has no finite value; what() says
// why and where (the 1-based character), with the nearest known name for a misspelt one.
class ExpressionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// `text` evaluated with these variables (name, value).
double evaluate_expression(const std::string& text,
                           const std::vector<std::pair<std::string, double>>& variables);

// The names of `variables` that `text` uses (an expression of a null measure is null).
std::vector<std::string> expression_uses(
    const std::string& text, const std::vector<std::pair<std::string, double>>& variables);

// A name an expression may use as a variable: a letter or "_", then letters, digits and "_",
// and not a built-in constant or function.
bool valid_variable_name(const std::string& name);

}  // namespace rugosim::app
