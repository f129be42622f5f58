#pragma once
// Reading command-line values the same way in every subcommand: finite
// numbers, comma-separated lists of them, and a formula given as an argument
// (its diagnostics printed with the caret under the column).
#include "formula/compiler.h"

#include <optional>
#include <string>
#include <vector>

namespace fl::cli {

// A finite number: "nan", "inf" and overflowing literals such as 1e400 are
// refused rather than silently turned into non-finite coordinates.
bool parseNumber(const std::string& text, double& out);
// "1,2.5,-3": every item a finite number; false for an empty list.
bool parseNumberList(const std::string& text, std::vector<double>& out);
// The compiled formula, or nothing after printing its errors to stderr.
std::optional<formula::Tape> compileFormulaArgument(const std::string& source,
                                                    formula::DefinitionKind kind);

} // namespace fl::cli
