#include "batch_hoist.h"

#include "tape.h"

namespace fl::formula {

HoistedSteps hoistTimeOnly(const std::vector<BatchStep>& steps, const std::vector<char>& liveOut,
                           std::int32_t registerCount) {
    HoistedSteps h;
    h.registerCount = registerCount;
    const std::size_t regs = std::size_t(registerCount);
    // Per register of the tape: whether what it holds now is t or a hoisted
    // value, and the register that value has in the new steps.
    std::vector<char> timeOnly(regs, 0);
    std::vector<std::int32_t> name(regs);
    for (std::size_t r = 0; r < regs; ++r)
        name[r] = std::int32_t(r);
    timeOnly[std::size_t(Input::T)] = 1;
    std::vector<BatchStep> lead, rest;
    for (BatchStep s : steps) {
        bool hoist = !liveOut[std::size_t(s.out)] &&
                     (s.fused != Fused::SinCos || !liveOut[std::size_t(s.out2)]);
        bool readsAny = false;
        forEachRead(s, [&](std::int32_t r) {
            readsAny = true;
            if (!timeOnly[std::size_t(r)]) hoist = false; // another input, or work not hoisted
        });
        hoist = hoist && readsAny;
        forEachRead(s, [&](std::int32_t& r) { r = name[std::size_t(r)]; });
        auto define = [&](std::int32_t& out) {
            const std::size_t o = std::size_t(out);
            timeOnly[o] = hoist ? 1 : 0;
            name[o] = hoist ? h.registerCount++ : out;
            out = name[o];
        };
        define(s.out);
        if (s.fused == Fused::SinCos) define(s.out2);
        (hoist ? lead : rest).push_back(s);
    }
    h.hoisted = lead.size();
    h.steps = std::move(lead);
    h.steps.insert(h.steps.end(), rest.begin(), rest.end());
    h.liveOut = liveOut;
    h.liveOut.resize(std::size_t(h.registerCount), 0);
    return h;
}

} // namespace fl::formula
