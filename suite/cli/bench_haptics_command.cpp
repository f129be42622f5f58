// `functionlab bench haptics [--json]`: one force tick on the paper's
// tangible scenes, function against polygon contact, and the real-time
// loop's jitter (bench/haptics_bench.h). Figures are printed, never judged.
#include "cli/commands.h"
#include "platform/exit_codes.h"

#include "courseware/catalogue.h"
#include "haptics/haptics_bench.h"

#include <iostream>

namespace fl::cli {

const CommandSpec& benchHapticsSpec() {
    static const CommandSpec spec{
        .name = "bench haptics",
        .summary = "what a force tick costs; function against polygon contact; loop jitter",
        .synopsis = {"bench haptics [--json] [--passes N] [--loop-seconds S] [--rate HZ]"},
        .description =
            "For the tangible examples (watermelon, fan, shark): the cost of one force tick\n"
            "along a path through their tangible shapes, as percentiles. Then function\n"
            "contact against polygon contact side by side, sliding just under the\n"
            "watermelon's skin: tick cost, triangles and contact error (the proxy's\n"
            "distance from the true surface, a fraction of the box diagonal) per mesh\n"
            "resolution. Last, the real-time servo loop for a few seconds: its period's\n"
            "jitter, with the machine's load as it is.\n",
        .options = {{.name = "json",
                     .help = "print one object: {\"scenes\": [...], \"contact\": [...], "
                             "\"loop\": {...}}"},
                    {.name = "passes",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "times each path is walked",
                     .defaultValue = "5",
                     .min = 1,
                     .max = 1000},
                    {.name = "loop-seconds",
                     .kind = OptionKind::Number,
                     .valueName = "S",
                     .help = "how long the real-time loop runs",
                     .defaultValue = "2",
                     .min = 0.1,
                     .max = 600},
                    {.name = "rate",
                     .kind = OptionKind::Number,
                     .valueName = "HZ",
                     .help = "the real-time loop's rate",
                     .defaultValue = "1000",
                     .min = 1,
                     .max = 10000}},
        .exitStatus = "0 measured, 2 usage error",
    };
    return spec;
}

int benchHapticsCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(benchHapticsSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    haptics::HapticsBenchOptions o;
    o.examples = courseware::coursewareFolder() / "examples";
    o.passes = int(a->number("passes", 5));
    o.loopSeconds = a->number("loop-seconds", 2);
    o.rateHz = a->number("rate", 1000);
    const haptics::HapticsBenchResult r = haptics::runHapticsBench(o);
    std::cout << (a->flag("json") ? haptics::hapticsBenchJson(r) : haptics::hapticsBenchText(r));
    return kExitOk;
}

} // namespace fl::cli
