#pragma once
// The class's one lock, a lease over the whole scene (docs/design-notes.md,
// "Classroom locks"): an edit takes it for its sender and renews it; it ends
// on release, after `lease` without an edit (heartbeats keep a member's seat,
// not the lock), or `grace` after the holder disconnects (a reconnect within
// the grace keeps it). A holder whose lock the instructor breaks cannot take
// it again for `cooldown`. Time comes from the caller, so tests run on a
// ManualClock.
#include "class_clock.h"

#include <cstdint>
#include <optional>
#include <string>

namespace fl::classroom {

using MemberId = std::uint64_t;

struct LockHolder {
    MemberId member = 0;
    Millis expires = 0;
    bool connected = true;
};

class SceneLock {
  public:
    SceneLock(Millis lease, Millis grace, Millis cooldown = 30'000)
        : lease_(lease), grace_(grace), cooldown_(cooldown) {}

    // The holder at `now`, after letting an expired lease go.
    std::optional<LockHolder> holder(Millis now);
    // Held by someone other than `member` at `now`.
    bool heldByOther(MemberId member, Millis now);
    // Gives the lock to `member` (taking it from anyone) with a fresh lease.
    void grant(MemberId member, Millis now);
    // Gives the lock up if `member` holds it.
    bool release(MemberId member);
    // Nobody holds it. `cooldown`: the instructor broke it, and its holder
    // waits before taking it again (else a student takes it straight back).
    void breakLock(Millis now, bool cooldown);
    // Whether `member` is waiting after a broken lock.
    bool coolingDown(MemberId member, Millis now) const;
    // The holder left: keep the lock for the grace period only.
    void disconnected(MemberId member, Millis now);
    // The holder is back (same member, new connection): a normal lease again.
    void reconnected(MemberId member, Millis now);

  private:
    Millis lease_;
    Millis grace_;
    Millis cooldown_;
    std::optional<LockHolder> holder_;
    std::optional<MemberId> broken_; // whose lock was broken, until brokenUntil_
    Millis brokenUntil_ = 0;
};

} // namespace fl::classroom
