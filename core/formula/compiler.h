#pragma once
// Formula text -> checked tape. The front door of the formula engine: parses,
// checks names, arity and outputs against the kind of definition, inlines
// user functions, unrolls loops, and builds the tape.
#include "diagnostic.h"
#include "limits.h"
#include "tape.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fl::formula {

// Which inputs a definition reads and which outputs it must produce.
enum class DefinitionKind {
    Generic,    // any of x y z t u v w; one value
    Implicit,   // FRep geometry or an explicit scalar field: x y z t -> value
    Parametric, // u v w t -> x, y, z
    Colour,     // x y z u v w t -> r, g, b (or one value for a colour map)
    Force,      // x y z u v w t -> fx, fy, fz
};

const char* definitionKindName(DefinitionKind kind);

// How the operators & | \ combine shapes (DESIGN §2, "set-operation mode").
struct SetOperationMode {
    enum class Kind { MinMax, RFunction };
    Kind kind = Kind::MinMax;
    double m = 0.0;     // continuity of the R-functions (C^m)
    double alpha = 0.0; // R_alpha family parameter, in (-1, 1]
};

struct ExternalParameter {
    std::string name;
    double defaultValue = 0.0;
    bool hasRange = false;
    double lo = 0.0;
    double hi = 0.0;
};

struct CompileOptions {
    DefinitionKind kind = DefinitionKind::Generic;
    SetOperationMode setOperations;
    std::vector<ExternalParameter> parameters; // supplied by the scene, in addition to `param`
    Limits limits;
};

struct CompileResult {
    std::optional<Tape> tape; // present exactly when there are no errors
    std::vector<Diagnostic> diagnostics;
    long expansionSteps = 0; // the work compiling took (Limits::maxExpansionSteps)
    bool ok() const { return tape.has_value(); }
};

CompileResult compile(std::string_view source, const CompileOptions& options = {});

} // namespace fl::formula
