#pragma once
// Turns formula text into tokens with exact line:column ranges. Comments are
// `// …` and `/* … */`. Bad characters become Invalid tokens plus a diagnostic.
#include "diagnostic.h"
#include "token.h"

#include <string_view>
#include <vector>

namespace fl::formula {

std::vector<Token> tokenize(std::string_view source, std::vector<Diagnostic>& diagnostics);

} // namespace fl::formula
