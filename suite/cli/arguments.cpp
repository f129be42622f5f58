#include "cli/arguments.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace fl::cli {

bool parseNumber(const std::string& text, double& out) {
    if (text.empty()) return false;
    char* end = nullptr;
    out = std::strtod(text.c_str(), &end);
    return end && *end == '\0' && std::isfinite(out);
}

bool parseNumberList(const std::string& text, std::vector<double>& out) {
    out.clear();
    std::stringstream in(text);
    for (std::string part; std::getline(in, part, ',');) {
        double d = 0;
        if (!parseNumber(part, d)) return false;
        out.push_back(d);
    }
    return !out.empty();
}

std::optional<formula::Tape> compileFormulaArgument(const std::string& source,
                                                    formula::DefinitionKind kind) {
    formula::CompileOptions options;
    options.kind = kind;
    formula::CompileResult result = formula::compile(source, options);
    for (const formula::Diagnostic& d : result.diagnostics)
        std::cerr << formula::formatDiagnostic(d, source, "formula");
    return std::move(result.tape);
}

} // namespace fl::cli
