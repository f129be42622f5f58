#pragma once
// Every bound the classroom puts on what clients send (docs/classroom-protocol.md,
// "Limits"). Messages from others are hostile: each bound, when exceeded, is a
// refusal or an error naming it, never a crash or unbounded memory.
#include "clock.h"

#include <cstddef>

namespace fl::classroom {

struct ClassroomLimits {
    std::size_t maxMessageBytes = 1u << 20;  // one WebSocket message (frame text)
    std::size_t maxSceneBytes = 256u << 10;  // the scene text of an edit or push
    std::size_t maxNodes = 5000;             // nodes of a scene, PROTO expansions included
    std::size_t maxFormulaBytes = 16u << 10; // one definition field's formula text
    std::size_t maxNameChars = 40;           // a member's name
    std::size_t maxChatChars = 2000;         // one chat text (commands included)
    std::size_t maxLabelChars = 120;         // a snapshot label
    std::size_t maxClassCodeChars = 64;
    std::size_t maxMembers = 500;

    // Edits and chat (commands included) share one token bucket per member.
    double rateBurst = 10;    // tokens when full
    double ratePerSecond = 5; // tokens refilled per second
    // Failed joins per peer address within the window close the connection.
    int maxFailedJoins = 15;
    Millis failedJoinWindow = 60'000;

    Millis leaseMillis = 10'000;           // a lock without edits or heartbeats expires
    Millis disconnectGraceMillis = 20'000; // a disconnected holder keeps it this long
    Millis silentMemberMillis = 30'000;    // no message at all: the server closes
    std::size_t maxMissedListed = 100;     // versions a resuming member is told about
    long autoSnapshotEvery = 100;          // versions between automatic snapshots
};

} // namespace fl::classroom
