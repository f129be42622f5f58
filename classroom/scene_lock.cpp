#include "scene_lock.h"

#include <algorithm>

namespace fl::classroom {

std::optional<LockHolder> SceneLock::holder(Millis now) {
    if (holder_ && now >= holder_->expires) holder_.reset();
    return holder_;
}

bool SceneLock::heldByOther(MemberId member, Millis now) {
    const auto h = holder(now);
    return h && h->member != member;
}

void SceneLock::grant(MemberId member, Millis now) {
    holder_ = LockHolder{member, now + lease_};
}

void SceneLock::breakLock(Millis now, bool cooldown) {
    if (cooldown && holder(now)) {
        broken_ = holder_->member;
        brokenUntil_ = now + cooldown_;
    }
    holder_.reset();
}

bool SceneLock::coolingDown(MemberId member, Millis now) const {
    return broken_ == member && now < brokenUntil_;
}

bool SceneLock::release(MemberId member) {
    if (!holder_ || holder_->member != member) return false;
    holder_.reset();
    return true;
}

void SceneLock::disconnected(MemberId member, Millis now) {
    if (!holder(now) || holder_->member != member) return;
    holder_->connected = false;
    holder_->expires = std::max(holder_->expires, now + grace_);
}

void SceneLock::reconnected(MemberId member, Millis now) {
    if (!holder(now) || holder_->member != member) return;
    holder_->connected = true;
    holder_->expires = std::max(holder_->expires, now + lease_);
}

} // namespace fl::classroom
