#include "force_limiter.h"

#include <algorithm>
#include <cmath>

namespace fl::haptics {

ForceLimiter::ForceLimiter(LimiterSettings settings) : settings_(settings) {}

void ForceLimiter::restartRamp(double now) {
    rampStart_ = now;
    ramping_ = settings_.rampSeconds > 0;
}

field::Vec3 ForceLimiter::limit(const field::Vec3& wanted, double now, double deviceAge,
                                bool late) {
    lateInARow_ = late ? lateInARow_ + 1 : 0;
    lastCut_ = Cut::None;
    field::Vec3 f = wanted;
    if (!field::isFinite(f)) {
        f = {};
        lastCut_ = Cut::NotFinite;
    }
    if (!(deviceAge <= settings_.staleSeconds)) { // NaN ages are stale too
        last_ = {};
        lastCut_ = Cut::Stale;
        return last_;
    }
    if (lateInARow_ >= settings_.missedDeadlinesToStop) {
        last_ = {};
        lastCut_ = Cut::Late;
        return last_;
    }
    const double size = field::length(f);
    if (size > settings_.maxForce) {
        f = field::scaled(f, settings_.maxForce / size);
        lastCut_ = Cut::Clamped;
    }
    if (ramping_) {
        const double k = (now - rampStart_) / settings_.rampSeconds;
        if (k >= 1) {
            ramping_ = false;
        } else {
            f = field::scaled(f, std::clamp(k, 0.0, 1.0));
            lastCut_ = Cut::Ramp;
        }
    }
    if (settings_.maxChangePerTick > 0) {
        const field::Vec3 change = field::minus(f, last_);
        const double c = field::length(change);
        if (c > settings_.maxChangePerTick) {
            f = field::plus(last_, field::scaled(change, settings_.maxChangePerTick / c));
            lastCut_ = Cut::Change;
        }
    }
    last_ = f;
    return f;
}

} // namespace fl::haptics
