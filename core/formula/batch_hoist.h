#pragma once
// Work that depends on t alone, done once per t rather than once a call
// (the scalar evaluator's machine code; issue 31). Picking, the grader and
// a haptic tick ask for many points at one moment: `abs(sin(pi*t))` in the
// bouncing sphere costs a SLEEF sine per call where one per moment will do.
//
// hoistTimeOnly moves the steps whose values depend on t and no other input
// to the front (the code runs them only when t's bits differ from the last
// call's) and gives each value they make a register of its own past the
// tape's, so nothing the rest of the steps write can overwrite it between
// calls. A step that writes a tape output stays where it is (the caller
// reads outputs by their registers), and so does what reads its value.
#include "batch_step.h"

#include <cstdint>
#include <vector>

namespace fl::formula {

struct HoistedSteps {
    std::vector<BatchStep> steps; // the hoisted ones first, then the rest in order
    std::vector<char> liveOut;    // per register, the new ones included (never outputs)
    std::int32_t registerCount = 0;
    std::size_t hoisted = 0; // how many steps lead (0: nothing depends on t alone)
};

HoistedSteps hoistTimeOnly(const std::vector<BatchStep>& steps, const std::vector<char>& liveOut,
                           std::int32_t registerCount);

} // namespace fl::formula
