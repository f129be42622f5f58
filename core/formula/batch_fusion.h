#pragma once
// Peephole fusion for the batch loops: sequences that FRep formulas are full
// of become single passes over a block. Every fused step computes exactly
// what the steps it replaces computed (same operations, same order), so the
// batch evaluator stays bit for bit equal to the scalar one.
//
//   t = a - c; s = t*t                 ->  (a - c)^2                 (SquareOfDiff)
//   A - (b - c)^2 - (d - e)^2 ...      ->  one pass, up to 3 terms   (SquareTerms)
//   n = -b; min(a, n)                  ->  min(a, -b)                (NegatedOperand)
//   min(min(min(a, b), c), d)          ->  one pass, 3 or 4 operands (MinMaxChain)
//   s = sin(a); c = cos(a) (paired)    ->  one sincos call            (SinCos)
//
// A step is fused away only when its result has exactly one reader and the
// registers it read are not rewritten before the fused step runs. (SinCos
// keeps both results: the tape builder puts a pair's two steps side by side.)
#include "batch_step.h"
#include "tape.h"

#include <vector>

namespace fl::formula {

void fuseBatchSteps(std::vector<BatchStep>& steps, const Tape& tape);

} // namespace fl::formula
