#pragma once
// What the `haptics` commands share: the options of a run on the simulated
// clock (one wording in every command's help), reading the scene with its
// diagnostics printed, and printing a run's ticks and what it had to say.
#include "platform/option_table.h"

#include "haptics/probe.h"

#include "scene/scene.h"

#include <iosfwd>
#include <memory>
#include <string>

namespace fl::cli {

OptionSpec hapticsPathOption(std::string_view help);
OptionSpec hapticsDurationOption();
OptionSpec hapticsTimeOption(std::string_view help = "the scene time at the first tick");
OptionSpec hapticsRateOption();

// The scene, its diagnostics on `err`; null when it cannot be read.
std::unique_ptr<scene::Scene> hapticsSceneOrExplain(const std::string& file, std::ostream& err);

// The run's notes and reports on `err`, each line led by "functionlab COMMAND: ".
void printRunNotes(const std::string& command, const haptics::ProbeRun& run, std::ostream& err);
// The run: the JSON object of `haptics probe --json`, or a table.
void printRun(const haptics::ProbeRun& run, bool json, std::ostream& out);

} // namespace fl::cli
