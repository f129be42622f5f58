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

bool TokenBucket::full(Millis now) const {
    const double refilled =
        tokens_ + static_cast<double>(std::max<Millis>(now - last_, 0)) * perSecond_ / 1000.0;
    return refilled >= burst_;
}

bool AddressBuckets::take(const std::string& address, Millis now) {
    if (buckets_.size() >= kMaxAddresses) {
        std::erase_if(buckets_, [&](const auto& b) { return b.second.full(now); });
        if (buckets_.size() >= kMaxAddresses) buckets_.clear(); // a flood of addresses
    }
    auto it = buckets_.try_emplace(address, burst_, perSecond_, now).first;
    return it->second.take(now);
}

void KeyThrottle::failed(Millis now) {
    if (++failures_ <= freeTries_) return;
    const int doublings = std::min(failures_ - freeTries_ - 1, 30);
    until_ = now + std::min<Millis>(maxDelay_, Millis(1000) << doublings);
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
