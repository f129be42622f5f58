#pragma once
// Every bound the classroom puts on what clients send (docs/classroom-protocol.md,
// "Limits"). Messages from others are hostile: each bound, when exceeded, is a
// refusal or an error naming it, never a crash or unbounded memory.
#include "class_clock.h"

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

    // The work a scene may cost the server that checks it and every window
    // that shows it (issue 26 §3; `functionlab check --plan` prints a
    // scene's figures). The largest example needs 295 formula instructions,
    // 3e6 cells and 1e8 evaluations; a class scene may have twenty times that.
    std::size_t maxUnfoldedNodes = 50'000;     // nodes with every USE and PROTO instance unfolded
    std::size_t maxTapeInstructions = 200'000; // all formulas, each instance counted
    long maxCompileSteps = 2'000'000;          // compiling them (inlining, unrolling)
    double maxMeshCells = 64e6;                // at the files' resolutions
    double maxMeshEvaluations = 2e9;           // cells x formula instructions
    Millis maxCheckMillis = 3'000;             // a check still running then is refused

    // Edits and chat (commands included) share one token bucket per member.
    double rateBurst = 10;    // tokens when full
    double ratePerSecond = 5; // tokens refilled per second
    // Joins per peer address (a whole class may sit behind one NAT or proxy)
    // and per seat (resumes); an instructor's join is not counted.
    double joinBurstPerAddress = 60;
    double joinsPerSecondPerAddress = 2;
    double joinBurstPerSeat = 10;
    double joinsPerSecondPerSeat = 0.5;
    // Wrong class codes per peer address within the window: further wrong
    // ones close the connection (the right code still gets in).
    int maxFailedJoins = 15;
    Millis failedJoinWindow = 60'000;
    // The instructor key, over all addresses: free tries, then a delay that
    // doubles per wrong key up to this.
    int keyFreeTries = 3;
    Millis maxKeyDelayMillis = 60'000;
    // Connections that have not joined: per address at once, and how long.
    std::size_t maxUnjoinedPerAddress = 16;
    Millis joinDeadlineMillis = 10'000;

    Millis leaseMillis = 10'000; // a lock without an edit expires (heartbeats do not keep it)
    Millis brokenLockCooldownMillis = 30'000; // after break-lock, its holder waits this long
    Millis disconnectGraceMillis = 20'000;    // a disconnected holder keeps it this long
    Millis silentMemberMillis = 30'000;       // no message at all: the server closes
    std::size_t maxMissedListed = 100;        // versions a resuming member is told about
    long autoSnapshotEvery = 100;             // versions between automatic snapshots
};

} // namespace fl::classroom
