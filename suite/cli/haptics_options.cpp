#include "cli/haptics_options.h"

#include "scene/scene_reader.h"

#include <cstdio>
#include <ostream>

namespace fl::cli {

OptionSpec hapticsPathOption(std::string_view help) {
    return {
        .name = "path", .kind = OptionKind::Text, .valueName = "X,Y,Z:X,Y,Z[:...]", .help = help};
}

OptionSpec hapticsDurationOption() {
    return {.name = "duration",
            .kind = OptionKind::Number,
            .valueName = "S",
            .help = "seconds to walk the path",
            .defaultValue = "1",
            .min = 0,
            .max = 10000,
            .minExclusive = true};
}

OptionSpec hapticsTimeOption(std::string_view help) {
    return {.name = "time",
            .kind = OptionKind::Number,
            .valueName = "T",
            .help = help,
            .defaultValue = "0"};
}

OptionSpec hapticsRateOption() {
    return {.name = "rate",
            .kind = OptionKind::Number,
            .valueName = "HZ",
            .help = "the servo rate",
            .defaultValue = "1000",
            .min = 1,
            .max = 100000};
}

std::unique_ptr<scene::Scene> hapticsSceneOrExplain(const std::string& file, std::ostream& err) {
    scene::ReadResult r = scene::readSceneFile(file);
    for (const auto& d : r.diagnostics)
        err << scene::formatSceneDiagnostic(d) << "\n";
    return std::move(r.scene);
}

void printRunNotes(const std::string& command, const haptics::ProbeRun& run, std::ostream& err) {
    for (const std::string& n : run.notes)
        err << "functionlab " << command << ": " << n << "\n";
    for (const std::string& n : run.reports)
        err << "functionlab " << command << ": " << n << "\n";
}

void printRun(const haptics::ProbeRun& run, bool json, std::ostream& out) {
    if (json) {
        out << haptics::probeJson(run);
        return;
    }
    char line[320];
    std::snprintf(line, sizeof line, "%zu ticks at %g Hz (max force %g N)\n", run.ticks.size(),
                  run.rateHz, run.maxForce);
    out << line;
    std::snprintf(line, sizeof line, "%10s  %-32s %-32s %-30s %s\n", "ms", "device", "proxy",
                  "force (N)", "contact");
    out << line;
    for (const haptics::ProbeTick& t : run.ticks) {
        std::snprintf(line, sizeof line,
                      "%10.3f  %10.5f %10.5f %10.5f %10.5f %10.5f %10.5f %9.4f %9.4f %9.4f %s\n",
                      t.ms, t.device[0], t.device[1], t.device[2], t.proxy[0], t.proxy[1],
                      t.proxy[2], t.force[0], t.force[1], t.force[2],
                      std::string(haptics::contactName(t.contact)).c_str());
        out << line;
    }
}

} // namespace fl::cli
