#pragma once
// Does a set operation do anything? It counts only when it can change the
// shown solid: replacing it by either of its operands must change the sign
// of the field somewhere in the box. Otherwise it is dead — one operand
// alone gives the same solid — and the verdict says which and why.
#include "set_operations.h"
#include "solid_difference.h"

#include <optional>

namespace fl::grading {

// What an idle operand (the one that could be dropped) is over the box.
enum class OperandSign : std::uint8_t {
    Mixed,    // both signs: it is cut away elsewhere in the formula
    Positive, // > 0 everywhere: everything is inside it
    Negative, // <= 0 everywhere: nothing is inside it
};

struct OperationVerdict {
    TapeSetOperation operation;
    bool counts = false; // live: each replacement changes the solid
    // Live: a point where dropping the operation (keeping operand a)
    // changes inside to outside or back.
    std::optional<field::Vec3> witness;
    // Dead: the operand that could be dropped (0: a, 1: b) and its sign.
    int idleOperand = -1;
    OperandSign idleSign = OperandSign::Mixed;
    bool undecided = false; // the budget ran out: not counted, and said so
    std::size_t unresolvedCells = 0;
};

// `field`: a shape's field at one moment, exactly as shown (ShapeMesh::field).
OperationVerdict judgeOperation(const field::ImplicitField& field,
                                const TapeSetOperation& operation, Budget& budget,
                                const CompareOptions& options = {});

// The instruction that computed operand `which` (0: a, 1: b) of instruction
// `index`, or none (an input, a parameter, a constant).
std::optional<std::size_t> operandWriter(const formula::Tape& tape, std::size_t index, int which);

} // namespace fl::grading
