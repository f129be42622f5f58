// `functionlab haptics probe FILE --path X,Y,Z:X,Y,Z[:…] [--duration S]
// [--time T] [--rate HZ] [--json]` (issue 16 §4; docs/haptics.md): the
// simulated device's tool point walks the path while the servo loop runs on
// the simulated clock. Tests outside this repository read its JSON.
#include "cli/commands.h"
#include "cli/haptics_options.h"
#include "platform/exit_codes.h"

#include "haptics/device/polyline_path.h"
#include "haptics/probe.h"

#include <cstdio>
#include <iostream>

namespace fl::cli {

const CommandSpec& hapticsProbeSpec() {
    static const CommandSpec spec{
        .name = "haptics probe",
        .summary = "feel a scene with the simulated device along a path: forces per tick",
        .synopsis = {"haptics probe FILE --path X,Y,Z:X,Y,Z[:...] [--duration S] [--time T]\n"
                     "[--rate HZ] [--json]"},
        .description =
            "The simulated device's tool point moves along the polyline (scene\n"
            "coordinates) at constant speed for S seconds, starting at scene time T, while\n"
            "the servo loop runs on the simulated clock: deterministic, no waiting for real\n"
            "time, no connect ramp. Each tick gives the device's point, the proxy (on the\n"
            "surface in contact, else the device's point), the force the device applies to\n"
            "the hand (newtons, along the scene's axes, within the simulated device's\n"
            "limits) and the contact: none, surface or inside.\n",
        .positionals = {{.name = "FILE", .help = "the scene to touch"}},
        .options = {hapticsPathOption("the tool's polyline in scene coordinates (one point or "
                                      "more)"),
                    hapticsDurationOption(),
                    hapticsTimeOption(),
                    hapticsRateOption(),
                    {.name = "json",
                     .help = "print exactly one object: {\"rate_hz\", \"max_force\", \"ticks\": "
                             "[{\"ms\", \"device\", \"proxy\", \"force\", \"contact\"}]}"}},
        .notes = "Tangible shapes the servo loop cannot feel yet (standard geometry lent\n"
                 "physics by a sibling FShape) and formulas that were not a number somewhere\n"
                 "are said on standard error, once each.\n",
        .exitStatus = "0 probed, 1 the scene could not be read, 2 usage error",
    };
    return spec;
}

int hapticsProbeCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(hapticsProbeSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    if (!a->given("path")) return usageError(hapticsProbeSpec(), "--path is required", std::cerr);
    std::string error;
    const auto path = haptics::parsePathSpec(a->text("path"), &error);
    if (!path) return usageError(hapticsProbeSpec(), "--path: " + error, std::cerr);
    const auto scene = hapticsSceneOrExplain(a->positionals().front(), std::cerr);
    if (!scene) return kExitDiagnostic;
    haptics::ProbeOptions o;
    o.path = *path;
    o.duration = a->number("duration", 1);
    o.startTime = a->number("time", 0);
    o.rateHz = a->number("rate", 1000);
    const auto run = haptics::runProbe(*scene, o, &error);
    if (!run) return usageError(hapticsProbeSpec(), error, std::cerr);
    printRunNotes("haptics probe", *run, std::cerr);
    printRun(*run, a->flag("json"), std::cout);
    return kExitOk;
}

} // namespace fl::cli
