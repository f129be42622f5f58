#pragma once
// One table of options for every subcommand of `functionlab`. A command
// declares itself as plain data (CommandSpec): its name, usage lines, what it
// does, its options with their kinds and limits, its positional arguments and
// its exit status. From that one description come parsing and validation
// (parseArguments), the help text (helpText: `functionlab help COMMAND`,
// `functionlab COMMAND --help`) and the option lists of docs/cli.md
// (markdownText: `functionlab help --markdown`).
#include <cstdint>
#include <iosfwd>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fl::cli {

using Args = std::vector<std::string>;

enum class OptionKind {
    Flag,       // --json: no value
    Number,     // a finite number ("nan", "inf", "1e400" refused), within [min, max]
    Integer,    // a whole number written out in full, within [min, max], no overflow
    Text,       // any text (a formula, a name)
    Path,       // a file name
    NumberList, // "1,2.5,-3": `count` finite numbers (any count >= 1 when 0), each in [min, max]
    KeyValue,   // NAME=VALUE (VALUE a finite number when `numericValue`); usually repeatable
    Choice,     // one of `choices`
    Size,       // WxH, two whole numbers in [min, max]
};

struct OptionSpec {
    std::string_view name{}; // the long name without "--": "resolution"
    char shortName = 0;      // 'o' for -o; 0 for none
    OptionKind kind = OptionKind::Flag;
    std::string_view valueName{};    // shown in help: "N", "X,Y,Z", "OUT"
    std::string_view help{};         // one paragraph; wrapped when printed
    std::string_view defaultValue{}; // parsed like a given value when the option is absent; shown
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool minExclusive = false; // the value must be above min, not equal to it
    int count = 0;             // NumberList: exactly this many numbers (0: one or more)
    bool repeatable = false;   // every occurrence is kept; otherwise the last one counts
    bool numericValue = false; // KeyValue: VALUE is a finite number
    std::vector<std::string_view> choices{}; // Choice
};

struct PositionalSpec {
    std::string_view name{}; // "FILE", "SRC"
    std::string_view help{};
    bool required = true;
    // The last positional only: it may be given more than once (`grade merge
    // A.sqlite B.sqlite ...`); positionals() holds them all.
    bool repeats = false;
};

// What `--` does: end the options (every later argument is positional), or
// make only the next argument positional (`formula eval --at 1,0,0 -- "--x" --json`).
enum class DoubleDash { EndsOptions, QuotesNext };

struct CommandSpec {
    std::string_view name{};                  // "mesh", "bench accuracy"
    std::string_view summary{};               // one line for `functionlab help`
    std::vector<std::string_view> synopsis{}; // usage lines, after "functionlab "
    std::string_view description{};           // paragraphs, as written
    std::vector<PositionalSpec> positionals{};
    std::vector<OptionSpec> options{};
    std::string_view notes{};      // paragraphs after the options
    std::string_view exitStatus{}; // "0 written, 1 ..., 2 usage error"
    // Positional arguments may begin with '-' (a formula "-x^2"): only
    // arguments beginning with "--" (and declared short options) are options.
    bool positionalsMayStartWithDash = false;
    DoubleDash doubleDash = DoubleDash::EndsOptions;
};

// One value of an option as given (or as its default).
struct OptionValue {
    std::string text;            // as written
    double number = 0;           // Number, Integer
    std::int64_t integer = 0;    // Integer
    std::vector<double> numbers; // NumberList
    std::string key;             // KeyValue: NAME (text is VALUE)
    int width = 0, height = 0;   // Size
};

// The arguments of one command line, typed. Asking for an option the
// command does not declare, or with the wrong kind, is a programming error
// and throws std::logic_error.
class ParsedArgs {
  public:
    explicit ParsedArgs(const CommandSpec& spec) : spec_(&spec) {}

    bool help() const { return help_; }
    // Given on the command line (not only a default).
    bool given(std::string_view name) const;
    bool flag(std::string_view name) const;
    std::optional<double> number(std::string_view name) const;
    double number(std::string_view name, double fallback) const;
    std::optional<std::int64_t> integer(std::string_view name) const;
    std::int64_t integer(std::string_view name, std::int64_t fallback) const;
    std::string text(std::string_view name, std::string fallback = {}) const;
    std::optional<std::vector<double>> numbers(std::string_view name) const;
    std::vector<std::pair<std::string, std::string>> keyValues(std::string_view name) const;
    std::vector<std::pair<std::string, double>> keyNumbers(std::string_view name) const;
    std::optional<std::pair<int, int>> size(std::string_view name) const;
    // Every occurrence, in order (repeatable options).
    const std::vector<OptionValue>& values(std::string_view name) const;

    const std::vector<std::string>& positionals() const { return positionals_; }
    // The positional argument named in the spec, or empty when absent.
    std::string positional(std::string_view name) const;

  private:
    friend struct Parser;
    const OptionSpec& spec(std::string_view name, OptionKind kind) const;
    const OptionValue* last(std::string_view name) const;

    const CommandSpec* spec_;
    bool help_ = false;
    std::map<std::string, std::vector<OptionValue>, std::less<>> values_;
    std::map<std::string, bool, std::less<>> given_;
    std::vector<std::string> positionals_;
};

struct ParseError {
    std::string message; // "--resolution needs a number, not 'abc'"
};

struct ParseResult {
    std::optional<ParsedArgs> args; // absent when `error` says why
    ParseError error;
    bool ok() const { return args.has_value(); }
};

// Turns the arguments after the command's name into typed values.
ParseResult parseArguments(const CommandSpec& spec, const Args& args);

// The parsed arguments, or nothing after printing what the caller must
// return: help (to `out`; exit 0) or a usage error (to `err`; exit 2) in
// `exitCode`.
std::optional<ParsedArgs> parseOrExplain(const CommandSpec& spec, const Args& args, int& exitCode,
                                         std::ostream& out, std::ostream& err);

// "functionlab CMD: MESSAGE", the usage lines and where the options are
// explained, on `err`; returns the usage exit code (2).
int usageError(const CommandSpec& spec, const std::string& message, std::ostream& err);

// Text for a terminal (80 columns) and markdown for docs/cli.md.
std::string usageText(const CommandSpec& spec);
std::string helpText(const CommandSpec& spec);
std::string markdownText(const CommandSpec& spec);

// The closest of `candidates` to `word` when it is close enough to be a
// likely typo, else empty.
std::string closestMatch(std::string_view word, const std::vector<std::string>& candidates);

// A finite number written out in full; a whole number without overflow.
bool parseFiniteNumber(std::string_view text, double& out);
bool parseWholeNumber(std::string_view text, std::int64_t& out);

} // namespace fl::cli
