#pragma once
// The class's one lock, a lease over the whole scene (docs/design-notes.md,
// "Classroom locks"): an edit takes it for its sender; the holder's edits and
// heartbeats renew it; it ends on release, after `lease` without renewal, or
// `grace` after the holder disconnects (a reconnect within the grace keeps
// it). Time comes from the caller, so tests run on a ManualClock.
#include "clock.h"

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
    SceneLock(Millis lease, Millis grace) : lease_(lease), grace_(grace) {}

    // The holder at `now`, after letting an expired lease go.
    std::optional<LockHolder> holder(Millis now);
    // Held by someone other than `member` at `now`.
    bool heldByOther(MemberId member, Millis now);
    // Gives the lock to `member` (taking it from anyone) with a fresh lease.
    void grant(MemberId member, Millis now);
    // A sign of life from `member`: renews the lease if it holds the lock.
    bool renew(MemberId member, Millis now);
    // Gives the lock up if `member` holds it.
    bool release(MemberId member);
    void breakLock() { holder_.reset(); }
    // The holder left: keep the lock for the grace period only.
    void disconnected(MemberId member, Millis now);
    // The holder is back (same member, new connection): a normal lease again.
    void reconnected(MemberId member, Millis now);

  private:
    Millis lease_;
    Millis grace_;
    std::optional<LockHolder> holder_;
};

} // namespace fl::classroom
