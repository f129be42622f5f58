// `functionlab haptics probe FILE --path X,Y,Z:X,Y,Z[:…] [--duration S]
// [--time T] [--rate HZ] [--json]` (issue 16 §4; docs/haptics.md): the
// simulated device's tool point walks the path while the servo loop runs on
// the simulated clock. Tests outside this repository read its JSON.
#include "cli/commands.h"
#include "cli/exit_codes.h"

#include "device/polyline_path.h"
#include "probe.h"

#include "scene/scene_reader.h"

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
        .options = {{.name = "path",
                     .kind = OptionKind::Text,
                     .valueName = "X,Y,Z:X,Y,Z[:...]",
                     .help = "the tool's polyline in scene coordinates (one point or more)"},
                    {.name = "duration",
                     .kind = OptionKind::Number,
                     .valueName = "S",
                     .help = "seconds to walk the path",
                     .defaultValue = "1",
                     .min = 0,
                     .max = 10000,
                     .minExclusive = true},
                    {.name = "time",
                     .kind = OptionKind::Number,
                     .valueName = "T",
                     .help = "the scene time at the first tick",
                     .defaultValue = "0"},
                    {.name = "rate",
                     .kind = OptionKind::Number,
                     .valueName = "HZ",
                     .help = "the servo rate",
                     .defaultValue = "1000",
                     .min = 1,
                     .max = 100000},
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
    const std::string file = a->positionals().front();
    scene::ReadResult r = scene::readSceneFile(file);
    for (const auto& d : r.diagnostics)
        std::cerr << scene::formatSceneDiagnostic(d) << "\n";
    if (!r.ok()) return kExitDiagnostic;
    haptics::ProbeOptions o;
    o.path = *path;
    o.duration = a->number("duration", 1);
    o.startTime = a->number("time", 0);
    o.rateHz = a->number("rate", 1000);
    const auto run = haptics::runProbe(*r.scene, o, &error);
    if (!run) return usageError(hapticsProbeSpec(), error, std::cerr);
    for (const std::string& n : run->notes)
        std::cerr << "functionlab haptics probe: " << n << "\n";
    for (const std::string& n : run->reports)
        std::cerr << "functionlab haptics probe: " << n << "\n";
    if (a->flag("json")) {
        std::cout << haptics::probeJson(*run);
        return kExitOk;
    }
    std::printf("%zu ticks at %g Hz (max force %g N)\n", run->ticks.size(), run->rateHz,
                run->maxForce);
    std::printf("%10s  %-32s %-32s %-30s %s\n", "ms", "device", "proxy", "force (N)", "contact");
    for (const haptics::ProbeTick& t : run->ticks)
        std::printf("%10.3f  %10.5f %10.5f %10.5f %10.5f %10.5f %10.5f %9.4f %9.4f %9.4f %s\n",
                    t.ms, t.device[0], t.device[1], t.device[2], t.proxy[0], t.proxy[1], t.proxy[2],
                    t.force[0], t.force[1], t.force[2],
                    std::string(haptics::contactName(t.contact)).c_str());
    return kExitOk;
}

} // namespace fl::cli
