#pragma once
// The set-theoretic operations in a compiled field: every instruction that
// intersects, unites or subtracts solids — written as & | \, min/max,
// R-functions, blends, or made by an FTransform — told apart by what it
// does, not by how it was spelled: min is an intersection, max a union, and
// either with a negated operand a difference.
#include "formula/tape.h"

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace fl::grading {

enum class SetOperationKind : std::uint8_t { Intersection, Union, Difference };
std::string_view setOperationKindName(SetOperationKind kind); // "intersection" ...

struct TapeSetOperation {
    std::size_t instruction = 0; // index into tape.code
    SetOperationKind kind = SetOperationKind::Intersection;
};

std::vector<TapeSetOperation> setOperationsIn(const formula::Tape& tape);

// The tape with instruction `index` replaced by a copy of its operand
// `operand` (0: a, 1: b): "what if this operation were not there".
formula::Tape withOperationReplaced(const formula::Tape& tape, std::size_t index, int operand);

// The tape up to (not including) instruction `index`, with one output: the
// difference of its operands, `which` minus the other (0: a - b, 1: b - a).
// Where it is <= 0 a min/max equals the operand not subtracted.
formula::Tape operandGap(const formula::Tape& tape, std::size_t index, int which);

} // namespace fl::grading
