#pragma once
// A formula given as a command-line argument, compiled the same way in every
// subcommand (its diagnostics printed with the caret under the column).
// Option values are read by the option table (option_table.h).
#include "formula/compiler.h"

#include <optional>
#include <string>

namespace fl::cli {

// The compiled formula, or nothing after printing its errors to stderr.
std::optional<formula::Tape> compileFormulaArgument(const std::string& source,
                                                    formula::DefinitionKind kind);

} // namespace fl::cli
