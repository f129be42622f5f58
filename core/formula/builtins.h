#pragma once
// The built-in functions of the formula language: one table (name, arity,
// signature, summary) used by the checker, the completer and the reference
// docs, and the lowering of each onto tape operations.
#include "tape_builder.h"

#include <span>
#include <string>
#include <string_view>

namespace fl::formula {

struct BuiltinInfo {
    std::string_view name;
    int minArgs;
    int maxArgs; // -1: any number >= minArgs
    std::string_view signature;
    std::string_view summary;
    bool readsCoordinates; // primitives read x, y, z of the point being evaluated
};

std::span<const BuiltinInfo> builtinTable();
const BuiltinInfo* findBuiltin(std::string_view name);

struct BuiltinContext {
    TapeBuilder& tb;
    Val x, y, z; // the point's coordinates (valid when the definition has them)
};

struct BuiltinError {
    int argument = -1; // which argument is at fault, -1 for the call as a whole
    std::string message;
    std::string suggestion;
};

// Lowers a call whose argument count has been checked. Returns false and
// fills `error` when an argument that must be a constant is not.
bool lowerBuiltin(const BuiltinInfo& info, BuiltinContext& ctx, std::span<const Val> args,
                  Val& result, BuiltinError& error);

} // namespace fl::formula
