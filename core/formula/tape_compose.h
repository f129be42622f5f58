#pragma once
// Building one tape out of others: a compiled tape's instructions emitted
// again into a TapeBuilder with its inputs replaced by any values (an affine
// change of coordinates, a fixed time) and its parameters fixed. The builder
// folds constants and shares common subexpressions across the pieces, and
// allocates registers afresh, so the result is an ordinary tape every
// evaluator runs. FTransform's set operations over its children use it.
#include "tape.h"
#include "tape_builder.h"

#include <array>
#include <vector>

namespace fl::formula {

// The tape's outputs as values of `builder`, its inputs being `inputs`
// (indexed by Input) and its parameters `parameterValues` (their defaults
// when empty). Each inlined instruction keeps its source range, tagged
// `sourceTag` (SourceRange::source); the builder's own origin is left as it was.
std::vector<Val> inlineTape(TapeBuilder& builder, const Tape& tape,
                            const std::array<Val, kInputCount>& inputs,
                            const std::vector<double>& parameterValues = {}, int sourceTag = 0);
// The same with parameters bound to values of the builder (an FTransform's
// operationDefinition reads its children's values as parameters f1, f2, ...).
std::vector<Val> inlineTape(TapeBuilder& builder, const Tape& tape,
                            const std::array<Val, kInputCount>& inputs,
                            const std::vector<Val>& parameterValues, int sourceTag = 0);

} // namespace fl::formula
