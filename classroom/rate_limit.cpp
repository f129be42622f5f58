#include "rate_limit.h"

#include <algorithm>

namespace fl::classroom {

bool TokenBucket::take(Millis now) {
    if (now > last_) {
        tokens_ =
            std::min(burst_, tokens_ + static_cast<double>(now - last_) * perSecond_ / 1000.0);
        last_ = now;
    }
    if (tokens_ < 1.0) return false;
    tokens_ -= 1.0;
    return true;
}

void FailedJoinThrottle::forgetOld(std::deque<Millis>& times, Millis now) const {
    while (!times.empty() && now - times.front() >= window_)
        times.pop_front();
}

bool FailedJoinThrottle::blocked(const std::string& address, Millis now) {
    const auto it = failures_.find(address);
    if (it == failures_.end()) return false;
    forgetOld(it->second, now);
    if (it->second.empty()) {
        failures_.erase(it);
        return false;
    }
    return static_cast<int>(it->second.size()) >= max_;
}

void FailedJoinThrottle::failed(const std::string& address, Millis now) {
    // Bound memory over addresses too: forget those with nothing left in the window.
    if (failures_.size() >= kMaxAddresses)
        for (auto it = failures_.begin(); it != failures_.end();) {
            forgetOld(it->second, now);
            it = it->second.empty() ? failures_.erase(it) : std::next(it);
        }
    auto& times = failures_[address];
    forgetOld(times, now);
    times.push_back(now);
    // Bound memory per address: only the window's last max_ failures matter.
    while (static_cast<int>(times.size()) > max_)
        times.pop_front();
}

} // namespace fl::classroom
