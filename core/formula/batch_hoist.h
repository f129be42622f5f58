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
#include "tape.h"

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

// The rule for any kind of step (the gradient code's instructions use it
// too): `reads(step, f)` and `writes(step, f)` call f on each register the
// step reads or writes, by reference (they are renamed). `isOutput`: per
// register of the tape. Reorders `steps`, hoisted first; `registerCount`
// grows by the new registers; returns how many steps lead.
template <class Step, class Reads, class Writes>
std::size_t hoistTimeOnlySteps(std::vector<Step>& steps, const std::vector<char>& isOutput,
                               std::int32_t& registerCount, Reads reads, Writes writes) {
    const std::size_t regs = std::size_t(registerCount);
    // Per register of the tape: whether what it holds now is t or a hoisted
    // value, and the register that value has in the new steps.
    std::vector<char> timeOnly(regs, 0);
    std::vector<std::int32_t> name(regs);
    for (std::size_t r = 0; r < regs; ++r)
        name[r] = std::int32_t(r);
    timeOnly[std::size_t(Input::T)] = 1;
    std::vector<Step> lead, rest;
    for (Step s : steps) {
        bool hoist = true, readsAny = false;
        writes(s, [&](std::int32_t& out) { hoist = hoist && !isOutput[std::size_t(out)]; });
        reads(s, [&](std::int32_t& r) {
            readsAny = true;
            hoist = hoist && timeOnly[std::size_t(r)]; // not another input, or unhoisted work
        });
        hoist = hoist && readsAny;
        reads(s, [&](std::int32_t& r) { r = name[std::size_t(r)]; });
        writes(s, [&](std::int32_t& out) {
            const std::size_t o = std::size_t(out);
            timeOnly[o] = hoist ? 1 : 0;
            name[o] = hoist ? registerCount++ : out;
            out = name[o];
        });
        (hoist ? lead : rest).push_back(s);
    }
    const std::size_t hoisted = lead.size();
    steps = std::move(lead);
    steps.insert(steps.end(), rest.begin(), rest.end());
    return hoisted;
}

} // namespace fl::formula
