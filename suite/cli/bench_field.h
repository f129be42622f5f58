#pragma once
// The shape a meshing benchmark measures (bench accuracy, bench mesh, bench
// remesh): the first implicit or explicit FGeometry of the scene FILE, or
// --formula over --box — its arguments, and reading them.
#include "field/field_sampler.h"
#include "formula/compiler.h"
#include "platform/option_table.h"

#include <optional>
#include <string>
#include <vector>

namespace fl::cli {

struct BenchShape {
    field::ImplicitField field;              // a scene's as the scene compiles it
    std::string source;                      // the definition's text, as the scene compiles it
    formula::SetOperationMode setOperations; // how the scene combines with & | \ (min/max or R)
    std::string name;                        // "FILE:LINE", or the formula
};

// The optional FILE positional.
PositionalSpec benchShapePositional();
// --formula and --box, then `others`.
std::vector<OptionSpec> benchShapeOptions(std::vector<OptionSpec> others);

// None with `exitCode` set: 2 for a usage error (said against `spec`), 1 for
// a scene or formula with errors (said on stderr, naming the command).
std::optional<BenchShape> benchShapeFromArgs(const CommandSpec& spec, const ParsedArgs& args,
                                             int& exitCode);

} // namespace fl::cli
