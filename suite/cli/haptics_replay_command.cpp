// `functionlab haptics replay FILE LOG [--time T] [--rate HZ] [--json]`: a
// recorded device session played back through the servo loop on the
// simulated clock against a scene — the same forces every time.
#include "cli/commands.h"
#include "cli/haptics_options.h"
#include "platform/exit_codes.h"

#include "haptics/device/replay_device.h"
#include "haptics/probe.h"

#include <cstdio>
#include <iostream>

namespace fl::cli {

const CommandSpec& hapticsReplaySpec() {
    static const CommandSpec spec{
        .name = "haptics replay",
        .summary = "play a device log back against a scene: forces per tick",
        .synopsis = {"haptics replay FILE LOG [--time T] [--rate HZ] [--json]"},
        .description =
            "Plays the device log (written by `haptics record`, or by hand: docs/haptics.md,\n"
            "\"Device logs\") through the servo loop on the simulated clock, from scene time\n"
            "T, and prints the ticks as `haptics probe` does: the device's point, the proxy,\n"
            "the force and the contact. A log that cannot be read says where\n"
            "(file:line:column) and why.\n",
        .positionals = {{.name = "FILE", .help = "the scene to touch"},
                        {.name = "LOG", .help = "the device log"}},
        .options = {hapticsTimeOption("the scene time at the log's first sample"),
                    hapticsRateOption(),
                    {.name = "json", .help = "print the object `haptics probe --json` prints"}},
        .exitStatus = "0 replayed, 1 the scene or the log could not be read, 2 usage error",
    };
    return spec;
}

int hapticsReplayCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(hapticsReplaySpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    const auto scene = hapticsSceneOrExplain(a->positionals()[0], std::cerr);
    if (!scene) return kExitDiagnostic;
    std::string error;
    auto replay = haptics::ReplayDevice::open(a->positionals()[1], &error);
    if (!replay) {
        std::cerr << error << "\n";
        return kExitDiagnostic;
    }
    haptics::ProbeOptions o;
    o.startTime = a->number("time", 0);
    o.rateHz = a->number("rate", 1000);
    o.duration = std::max(replay->duration(), 1 / o.rateHz);
    const auto run = haptics::runOnSimulatedClock(
        *scene, *replay, [&](double t) { return replay->setTime(t); }, o, &error);
    if (!run) return usageError(hapticsReplaySpec(), error, std::cerr);
    printRunNotes("haptics replay", *run, std::cerr);
    printRun(*run, a->flag("json"), std::cout);
    return kExitOk;
}

} // namespace fl::cli
