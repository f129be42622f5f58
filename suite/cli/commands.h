#pragma once
// Subcommands of the `functionlab` executable. Each declares its options in
// the shared table (option_table.h) and takes the arguments after its own
// name, returning an exit code (see exit_codes.h).
#include "measure/bench_eval_spec.h"
#include "measure/bench_pde_spec.h"
#include "platform/option_table.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace fl::cli {

const CommandSpec& formulaCheckSpec();
const CommandSpec& formulaEvalSpec();
const CommandSpec& checkSpec();
const CommandSpec& convertSpec();
const CommandSpec& meshSpec();
const CommandSpec& exportWebSpec();
const CommandSpec& benchMeshSpec();
const CommandSpec& benchRemeshSpec();
const CommandSpec& renderSpec();
using measure::benchEvalSpec; // measure/bench_eval_spec.h: functionlab-bench reads it too
const CommandSpec& benchAccuracySpec();
const CommandSpec& benchGradingSpec();
const CommandSpec& benchHapticsSpec();
const CommandSpec& gradeCheckSpec();
const CommandSpec& gradeBatchSpec();
const CommandSpec& gradeExportSpec();
const CommandSpec& gradeSimilarSpec();
const CommandSpec& gradeReportSpec();
const CommandSpec& gradeVerifySpec();
const CommandSpec& gradeMergeSpec();
const CommandSpec& gradeKeySpec();
const CommandSpec& hapticsProbeSpec();
const CommandSpec& hapticsDevicesSpec();
const CommandSpec& hapticsRecordSpec();
const CommandSpec& hapticsReplaySpec();
const CommandSpec& serveSpec();
const CommandSpec& benchClassroomSpec();
const CommandSpec& pdeFitSpec();
using measure::benchPdeSpec; // measure/bench_pde_spec.h: functionlab-bench reads it too

int formulaCheckCommand(const Args& args);
int formulaEvalCommand(const Args& args);
int checkCommand(const Args& args);
int convertCommand(const Args& args);
int meshCommand(const Args& args);
int exportWebCommand(const Args& args);
int benchMeshCommand(const Args& args);
int benchRemeshCommand(const Args& args);
int renderCommand(const Args& args);
int benchEvalCommand(const Args& args);      // runs the sibling functionlab-bench
int benchAccuracyCommand(const Args& args);  // `bench accuracy`
int benchGradingCommand(const Args& args);   // `bench grading`
int benchHapticsCommand(const Args& args);   // `bench haptics`
int gradeCheckCommand(const Args& args);     // `grade check`
int gradeBatchCommand(const Args& args);     // `grade batch`
int gradeExportCommand(const Args& args);    // `grade export`
int gradeSimilarCommand(const Args& args);   // `grade similar`
int gradeReportCommand(const Args& args);    // `grade report`
int gradeVerifyCommand(const Args& args);    // `grade verify`
int gradeMergeCommand(const Args& args);     // `grade merge`
int gradeKeyCommand(const Args& args);       // `grade key new`
int hapticsProbeCommand(const Args& args);   // `haptics probe`
int hapticsDevicesCommand(const Args& args); // `haptics devices`
int hapticsRecordCommand(const Args& args);  // `haptics record`
int hapticsReplayCommand(const Args& args);  // `haptics replay`
int serveCommand(const Args& args);          // `serve`
int benchClassroomCommand(const Args& args); // `bench classroom`
int pdeFitCommand(const Args& args);         // `pde fit`
int benchPdeCommand(const Args& args);       // `bench pde` (runs functionlab-bench)

struct Command {
    const CommandSpec& (*spec)();
    int (*run)(const Args& args);
};

// Every command, in the order `functionlab help` lists them.
const std::vector<Command>& commands();

// `functionlab ARGS...` for everything but the window: the subcommands,
// `help [--markdown] [COMMAND]`, `--help`, `--version`. Returns -1 when
// args[0] is no command (the caller may open it as a scene file).
int runCommandLine(const Args& args, std::ostream& out, std::ostream& err);

// True for the words runCommandLine knows (commands, help, --version).
bool isCommandWord(std::string_view word);

// The top-level help, from the table.
std::string overviewText();

} // namespace fl::cli
