#pragma once
// The interpreter's code for one batch step, shared by the interpreter
// (BatchEvaluator::runBlock) and the JIT (batch_jit.cpp calls it for the
// steps it does not write itself), so that both give the same bits. Kept out
// of batch_step.h: only these two files need it.
#include "batch_step.h"

#include <cstddef>

namespace fl::formula {

// Step `s` over the rows of n points (base: each register's row; scratch:
// three spare rows, for the constant operands of ternary steps).
// noexcept: the JIT's frames cannot be unwound through.
void runBatchStep(const BatchStep& s, double* const* base, std::size_t n,
                  double* const* scratch) noexcept;

} // namespace fl::formula
