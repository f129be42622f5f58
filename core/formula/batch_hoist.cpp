#include "batch_hoist.h"

#include "tape.h"

namespace fl::formula {

HoistedSteps hoistTimeOnly(const std::vector<BatchStep>& steps, const std::vector<char>& liveOut,
                           std::int32_t registerCount) {
    HoistedSteps h;
    h.steps = steps;
    h.registerCount = registerCount;
    h.hoisted = hoistTimeOnlySteps(
        h.steps, liveOut, h.registerCount, [](BatchStep& s, auto&& f) { forEachRead(s, f); },
        [](BatchStep& s, auto&& f) {
            f(s.out);
            if (s.fused == Fused::SinCos) f(s.out2);
        });
    h.liveOut = liveOut;
    h.liveOut.resize(std::size_t(h.registerCount), 0);
    return h;
}

} // namespace fl::formula
