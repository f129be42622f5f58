#include "measure/bench_eval_spec.h"

namespace fl::measure {

using namespace fl::cli;

const CommandSpec& benchEvalSpec() {
    static const CommandSpec spec{
        .name = "bench eval",
        .summary = "evaluator speed: FunctionLab vs hand-written C++ vs muParser",
        .synopsis = {"bench eval [--json] [--side N] [--seconds S]"},
        .description =
            "Evaluates the benchmark formulas over an N^3 grid with FunctionLab's batch\n"
            "evaluator, the same formulas hand-written in C++, and muParser, all on one\n"
            "thread; prints nanoseconds per point and the ratios. Then one point a call,\n"
            "as picking, haptics and the grader ask: FunctionLab's scalar evaluator\n"
            "against the hand-written C++ called through a pointer for each point\n"
            "(nanoseconds per call), and one point's value and gradient a call with\n"
            "the gradient evaluator as machine code against its interpreter. The\n"
            "engines take turns for at least S seconds and each reports its best turn.\n"
            "The work is done by the executable functionlab-bench next to functionlab.\n",
        .options = {{.name = "json",
                     .help = "print a list of {\"formula\", \"ns_per_point\": {\"functionlab\", "
                             "\"native\", \"muparser\"}, \"ns_per_call\": {\"scalar\", "
                             "\"native\", \"gradient\", \"gradient_interpreted\"}, \"jit\", "
                             "\"jit_compile_us\"} instead of the table"},
                    {.name = "side",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "points along each side of the grid",
                     .defaultValue = "64",
                     .min = 2,
                     .max = 512},
                    {.name = "seconds",
                     .kind = OptionKind::Number,
                     .valueName = "S",
                     .help = "how long the engines take turns, at least",
                     .defaultValue = "0.2",
                     .min = 0,
                     .max = 60}},
        .exitStatus = "0 measured, 1 functionlab-bench is missing or failed, 2 usage error",
    };
    return spec;
}

} // namespace fl::measure
