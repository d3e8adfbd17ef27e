#include "render/app/sweep_expression.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <muParser.h>
#include <numbers>

#include <fmt/core.h>

#include "engine/scene/scene_loader.h"

namespace rugosim::app {
namespace {

// muparser's built-in functions and constants, which a variable may not shadow.
const std::vector<std::string>& built_in_names() {
  static const std::vector<std::string> names = {
      "sin",   "cos",   "tan",  "asin",  "acos", "atan", "sinh", "cosh", "tanh", "asinh",
      "acosh", "atanh", "log2", "log10", "log",  "ln",   "exp",  "sqrt", "sign", "rint",
      "abs",   "min",   "max",  "sum",   "avg",  "pi",   "_pi",  "_e"};
  return names;
}

// " (did you mean "x"?); the names known here: a, b" for an unknown `name`.
std::string known_names(const std::string& name,
                        const std::vector<std::pair<std::string, double>>& variables) {
  std::vector<std::string> known = built_in_names();
  for (const auto& v : variables)
    known.push_back(v.first);
  std::string message;
  const std::string suggestion = closest_match(name, known);
  if (!suggestion.empty()) message += fmt::format(" (did you mean \"{}\"?)", suggestion);
  std::string names;
  for (const auto& v : variables)
    names += (names.empty() ? "" : ", ") + v.first;
  message += fmt::format("; the names known here: {}", names.empty() ? "none" : names);
  return message;
}

// `text`'s value; with `used`, also the names of the variables it uses.
double evaluate(const std::string& text,
                const std::vector<std::pair<std::string, double>>& variables,
                std::vector<std::string>* used) {
  mu::Parser parser;
  // muparser reads variables through pointers: they must stay put while it evaluates.
  std::vector<double> values;
  values.reserve(variables.size());
  try {
    parser.DefineConst("pi", std::numbers::pi);
    for (const auto& [name, value] : variables) {
      values.push_back(value);
      parser.DefineVar(name, &values.back());
    }
    parser.SetExpr(text);
    if (used != nullptr) {
      // GetUsedVar() accepts any name (it parses with a factory that defines the unknown ones):
      // check them here.
      for (const auto& entry : parser.GetUsedVar()) {
        const auto known = std::find_if(variables.begin(), variables.end(),
                                        [&](const auto& v) { return v.first == entry.first; });
        if (known == variables.end()) {
          throw ExpressionError(fmt::format("\"{}\": unknown name \"{}\"{}", text, entry.first,
                                            known_names(entry.first, variables)));
        }
        used->push_back(entry.first);
      }
      parser.Eval();  // any value will do (1/0 is inf, not an error): how many it gives matters
      if (parser.GetNumResults() != 1) {
        throw ExpressionError(
            fmt::format("\"{}\" gives {} values (separated by commas); expected one", text,
                        parser.GetNumResults()));
      }
      return 0.0;  // the names it uses, not its value
    }
    const double result = parser.Eval();
    if (parser.GetNumResults() != 1) {  // "a, b": muparser's list of results
      throw ExpressionError(
          fmt::format("\"{}\" gives {} values (separated by commas); expected one", text,
                      parser.GetNumResults()));
    }
    if (!std::isfinite(result)) {
      throw ExpressionError(fmt::format("\"{}\" has no finite value ({})", text, result));
    }
    return result;
  } catch (const mu::Parser::exception_type& e) {
    std::string message = fmt::format("\"{}\": {}", text, e.GetMsg());
    if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN || e.GetCode() == mu::ecUNEXPECTED_VAR)
      message += known_names(e.GetToken(), variables);
    throw ExpressionError(message);
  }
}

}  // namespace

bool valid_variable_name(const std::string& name) {
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
  const bool word = std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
  const auto& reserved = built_in_names();
  return word && std::find(reserved.begin(), reserved.end(), name) == reserved.end();
}

std::vector<std::string> expression_uses(
    const std::string& text, const std::vector<std::pair<std::string, double>>& variables) {
  std::vector<std::string> used;
  evaluate(text, variables, &used);
  return used;
}

double evaluate_expression(const std::string& text,
                           const std::vector<std::pair<std::string, double>>& variables) {
  return evaluate(text, variables, nullptr);
}

}  // namespace rugosim::app
