#pragma once
// Recursive-descent parser for formulas and function scripts. Reports every
// syntax error it can recover from, each with its exact range.
#include "ast.h"
#include "diagnostic.h"
#include "limits.h"

#include <string_view>
#include <vector>

namespace fl::formula {

Program parse(std::string_view source, std::vector<Diagnostic>& diagnostics,
              const Limits& limits = {});

} // namespace fl::formula
