#include "cli/arguments.h"

#include <iostream>

namespace fl::cli {

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
