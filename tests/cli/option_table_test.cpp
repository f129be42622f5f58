// The option table every `functionlab` subcommand reads its command line
// through: each kind of option, its errors, and the help made from it.
#include "platform/option_table.h"

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>

namespace fl::cli {
namespace {

const CommandSpec& sample() {
    static const CommandSpec spec{
        .name = "sample",
        .summary = "a command with one option of every kind",
        .synopsis = {"sample FILE [OUT] [options]"},
        .description = "Does nothing; it is read by the tests.\n",
        .positionals = {{.name = "FILE", .help = "the input"},
                        {.name = "OUT", .help = "the output", .required = false}},
        .options = {{.name = "json", .help = "JSON"},
                    {.name = "output",
                     .shortName = 'o',
                     .kind = OptionKind::Path,
                     .valueName = "OUT",
                     .help = "where"},
                    {.name = "time",
                     .kind = OptionKind::Number,
                     .valueName = "T",
                     .help = "when",
                     .defaultValue = "0.5"},
                    {.name = "memory",
                     .kind = OptionKind::Number,
                     .valueName = "MIB",
                     .help = "budget",
                     .min = 0,
                     .minExclusive = true},
                    {.name = "side",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "points per side",
                     .defaultValue = "64",
                     .min = 2,
                     .max = 512},
                    {.name = "count",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "anything whole"},
                    {.name = "formula", .kind = OptionKind::Text, .valueName = "SRC", .help = "f"},
                    {.name = "at",
                     .kind = OptionKind::NumberList,
                     .valueName = "X,Y,Z",
                     .help = "a point",
                     .count = 3},
                    {.name = "resolutions",
                     .kind = OptionKind::NumberList,
                     .valueName = "N,N,...",
                     .help = "resolutions",
                     .min = 1,
                     .max = 2048},
                    {.name = "param",
                     .kind = OptionKind::KeyValue,
                     .valueName = "NAME=VALUE",
                     .help = "a parameter",
                     .repeatable = true,
                     .numericValue = true},
                    {.name = "define",
                     .kind = OptionKind::KeyValue,
                     .valueName = "KEY=TEXT",
                     .help = "a text",
                     .repeatable = true},
                    {.name = "kind",
                     .kind = OptionKind::Choice,
                     .valueName = "KIND",
                     .help = "what",
                     .defaultValue = "generic",
                     .choices = {"generic", "implicit"}},
                    {.name = "size",
                     .kind = OptionKind::Size,
                     .valueName = "WxH",
                     .help = "pixels",
                     .min = 1,
                     .max = 16384}},
        .exitStatus = "0 ok, 2 usage error",
    };
    return spec;
}

ParsedArgs parseOk(const Args& args, const CommandSpec& spec = sample()) {
    ParseResult r = parseArguments(spec, args);
    if (!r.ok()) throw std::runtime_error(r.error.message);
    return std::move(*r.args);
}

std::string parseError(const Args& args, const CommandSpec& spec = sample()) {
    ParseResult r = parseArguments(spec, args);
    return r.ok() ? std::string("(no error)") : r.error.message;
}

TEST(OptionTable, FlagsAndPositionals) {
    const ParsedArgs a = parseOk({"in.x3d", "--json", "out.x3d"});
    EXPECT_TRUE(a.flag("json"));
    EXPECT_EQ(a.positional("FILE"), "in.x3d");
    EXPECT_EQ(a.positional("OUT"), "out.x3d");
    const ParsedArgs b = parseOk({"in.x3d"});
    EXPECT_FALSE(b.flag("json"));
    EXPECT_EQ(b.positional("OUT"), "");
    EXPECT_EQ(parseError({"--json"}), "missing FILE");
    EXPECT_EQ(parseError({"a", "b", "c"}), "unexpected argument 'c' (give one OUT)");
    EXPECT_EQ(parseError({"a", "--json=yes"}), "--json takes no value");
}

TEST(OptionTable, ALastPositionalThatRepeatsTakesEveryRemainingArgument) {
    static const CommandSpec spec{
        .name = "merge",
        .positionals = {{.name = "PART", .help = "a part", .repeats = true}},
        .options = {{.name = "output", .shortName = 'o', .kind = OptionKind::Path}},
    };
    const ParseResult r = parseArguments(spec, {"a.sqlite", "-o", "c.sqlite", "b.sqlite"});
    ASSERT_TRUE(r.ok()) << r.error.message;
    EXPECT_EQ(r.args->positionals(), (std::vector<std::string>{"a.sqlite", "b.sqlite"}));
    EXPECT_EQ(r.args->positional("PART"), "a.sqlite");
    EXPECT_EQ(parseError({"-o", "c.sqlite"}, spec), "missing PART");
    EXPECT_NE(markdownText(spec).find("`PART` (one or more)"), std::string::npos);
}

TEST(OptionTable, ValuesSeparateOrAfterEquals) {
    const ParsedArgs a = parseOk({"f", "--time", "2.5", "--side=128", "-o", "x.stl"});
    EXPECT_EQ(a.number("time", 0), 2.5);
    EXPECT_EQ(a.integer("side", 0), 128);
    EXPECT_EQ(a.text("output"), "x.stl");
    EXPECT_TRUE(a.given("time"));
    const ParsedArgs b = parseOk({"f", "--output=a=b.stl", "--formula="});
    EXPECT_EQ(b.text("output"), "a=b.stl"); // split at the first '='
    EXPECT_TRUE(b.given("formula"));
    EXPECT_EQ(b.text("formula", "none"), "");
}

TEST(OptionTable, DefaultsAreReadLikeGivenValues) {
    const ParsedArgs a = parseOk({"f"});
    EXPECT_EQ(a.number("time", -1), 0.5);
    EXPECT_EQ(a.integer("side", -1), 64);
    EXPECT_EQ(a.text("kind"), "generic");
    EXPECT_FALSE(a.given("time"));
    EXPECT_FALSE(a.number("memory").has_value());
}

TEST(OptionTable, Numbers) {
    EXPECT_EQ(parseOk({"f", "--time", "-3"}).number("time", 0), -3);
    EXPECT_EQ(parseOk({"f", "--time", "1e-3"}).number("time", 0), 1e-3);
    EXPECT_EQ(parseError({"f", "--time", "abc"}), "--time needs a number, not 'abc'");
    EXPECT_EQ(parseError({"f", "--time", "12abc"}), "--time needs a number, not '12abc'");
    EXPECT_EQ(parseError({"f", "--time", ""}), "--time needs a number, not ''");
    EXPECT_EQ(parseError({"f", "--time", " 1"}), "--time needs a number, not ' 1'");
    EXPECT_EQ(parseError({"f", "--time", "0x10"}), "--time needs a number, not '0x10'");
    EXPECT_EQ(parseError({"f", "--memory", "0"}), "--memory needs a number above 0, not '0'");
    EXPECT_EQ(parseOk({"f", "--memory", "0.5"}).number("memory", 0), 0.5);
}

TEST(OptionTable, NanAndInfinityAreRefused) {
    for (const char* bad : {"nan", "NaN", "inf", "-inf", "infinity", "1e400", "-1e400"})
        EXPECT_EQ(parseError({"f", "--time", bad}),
                  std::string("--time needs a finite number, not '") + bad + "'")
            << bad;
    EXPECT_EQ(parseError({"f", "--at", "nan,0,0"}),
              "--at needs 3 finite numbers: --at X,Y,Z, not 'nan,0,0'");
    EXPECT_EQ(parseError({"f", "--at", "1e400,0,0"}),
              "--at needs 3 finite numbers: --at X,Y,Z, not '1e400,0,0'");
}

TEST(OptionTable, Integers) {
    EXPECT_EQ(parseOk({"f", "--side", "512"}).integer("side", 0), 512);
    EXPECT_EQ(parseOk({"f", "--side", "1e2"}).integer("side", 0), 100);
    EXPECT_EQ(parseError({"f", "--side", "12abc"}), "--side needs a number, not '12abc'");
    EXPECT_EQ(parseError({"f", "--side", "8.5"}), "--side needs a whole number, not '8.5'");
    EXPECT_EQ(parseError({"f", "--side", "1"}),
              "--side needs a whole number from 2 to 512, not '1'");
    EXPECT_EQ(parseError({"f", "--side", "513"}),
              "--side needs a whole number from 2 to 512, not '513'");
    EXPECT_EQ(parseOk({"f", "--count", "-9223372036854775808"}).integer("count", 0),
              std::numeric_limits<std::int64_t>::min());
    EXPECT_EQ(parseOk({"f", "--count", "9223372036854775807"}).integer("count", 0),
              std::numeric_limits<std::int64_t>::max());
}

TEST(OptionTable, IntegerOverflowIsAnError) {
    // No strtol that silently clamps or wraps.
    EXPECT_EQ(parseError({"f", "--count", "9223372036854775808"}),
              "--count needs a whole number, and '9223372036854775808' is too large");
    EXPECT_EQ(parseError({"f", "--count", "99999999999999999999999"}),
              "--count needs a whole number, and '99999999999999999999999' is too large");
    EXPECT_EQ(parseError({"f", "--count", "1e30"}),
              "--count needs a whole number, and '1e30' is too large");
    EXPECT_EQ(parseError({"f", "--side", "4294967298"}),
              "--side needs a whole number from 2 to 512, not '4294967298'");
    EXPECT_EQ(parseError({"f", "--count", "inf"}), "--count needs a number, not 'inf'");
}

TEST(OptionTable, NegativeNumbersAreValuesNotOptions) {
    const ParsedArgs a = parseOk({"f", "--at", "-1,0,-2.5", "--time", "-0.5"});
    EXPECT_EQ(*a.numbers("at"), (std::vector<double>{-1, 0, -2.5}));
    EXPECT_EQ(a.number("time", 0), -0.5);
    // Whatever follows an option that takes a value is that value.
    EXPECT_EQ(parseOk({"f", "--formula", "-x^2"}).text("formula"), "-x^2");
    EXPECT_EQ(parseOk({"f", "--formula", "--json"}).text("formula"), "--json");
}

TEST(OptionTable, NumberLists) {
    EXPECT_EQ(parseError({"f", "--at", "1,2"}),
              "--at needs 3 finite numbers: --at X,Y,Z, not '1,2'");
    EXPECT_EQ(parseError({"f", "--at", "1,2,3,4"}),
              "--at needs 3 finite numbers: --at X,Y,Z, not '1,2,3,4'");
    EXPECT_EQ(parseError({"f", "--at", "1,,3"}),
              "--at needs 3 finite numbers: --at X,Y,Z, not '1,,3'");
    EXPECT_EQ(parseError({"f", "--at", "1,2,3,"}),
              "--at needs 3 finite numbers: --at X,Y,Z, not '1,2,3,'");
    EXPECT_EQ(*parseOk({"f", "--resolutions", "8"}).numbers("resolutions"),
              (std::vector<double>{8}));
    EXPECT_EQ(parseError({"f", "--resolutions", "8,0"}),
              "--resolutions needs numbers from 1 to 2048, not '8,0'");
}

TEST(OptionTable, KeyValuesRepeat) {
    const ParsedArgs a = parseOk({"f", "--param", "R=3", "--param=S=-1.5", "--define", "a=b=c"});
    EXPECT_EQ(a.keyNumbers("param"),
              (std::vector<std::pair<std::string, double>>{{"R", 3}, {"S", -1.5}}));
    EXPECT_EQ(a.keyValues("define"),
              (std::vector<std::pair<std::string, std::string>>{{"a", "b=c"}}));
    EXPECT_EQ(parseError({"f", "--param", "R"}), "--param needs NAME=VALUE, not 'R'");
    EXPECT_EQ(parseError({"f", "--param", "=3"}), "--param needs NAME=VALUE, not '=3'");
    EXPECT_EQ(parseError({"f", "--param", "R=x"}),
              "--param needs NAME=VALUE with a finite number after '=', not 'R=x'");
    EXPECT_EQ(parseError({"f", "--param", "R=nan"}),
              "--param needs NAME=VALUE with a finite number after '=', not 'R=nan'");
}

TEST(OptionTable, RepeatedSingleOptionsKeepTheLast) {
    const ParsedArgs a = parseOk({"f", "--time", "1", "--time", "2"});
    EXPECT_EQ(a.number("time", 0), 2);
    EXPECT_EQ(a.values("time").size(), 1u);
}

TEST(OptionTable, ChoicesAndSizes) {
    EXPECT_EQ(parseOk({"f", "--kind", "implicit"}).text("kind"), "implicit");
    EXPECT_EQ(parseError({"f", "--kind", "solid"}),
              "--kind needs one of generic, implicit, not 'solid'");
    EXPECT_EQ(parseOk({"f", "--size", "800x600"}).size("size"), (std::pair{800, 600}));
    for (const char* bad : {"0x10", "800", "800x", "x600", "-1x5", "800x600junk", "20000x1"})
        EXPECT_EQ(parseError({"f", "--size", bad}),
                  std::string("--size needs WxH, e.g. 800x600 (each from 1 to 16384), not '") +
                      bad + "'")
            << bad;
}

TEST(OptionTable, MissingValue) {
    EXPECT_EQ(parseError({"f", "--at"}), "--at needs a value: --at X,Y,Z");
    EXPECT_EQ(parseError({"f", "-o"}), "-o needs a value: --output OUT");
    EXPECT_EQ(parseError({"f", "--side="}), "--side needs a number, not ''");
}

TEST(OptionTable, UnknownOptionsSuggestTheNearest) {
    EXPECT_EQ(parseError({"f", "--jsn"}), "unknown option '--jsn' (did you mean --json?)");
    EXPECT_EQ(parseError({"f", "--resolution", "3"}),
              "unknown option '--resolution' (did you mean --resolutions?)");
    EXPECT_EQ(parseError({"f", "--outptu=x"}),
              "unknown option '--outptu' (did you mean --output?)");
    EXPECT_EQ(parseError({"f", "-json"}), "unknown option '-json' (did you mean --json?)");
    EXPECT_EQ(parseError({"f", "--zzzzzz"}), "unknown option '--zzzzzz'");
    EXPECT_EQ(parseError({"f", "-x"}), "unknown option '-x'");
}

TEST(OptionTable, DoubleDashEndsOptions) {
    const ParsedArgs a = parseOk({"--json", "--", "--in.x3d", "-o"});
    EXPECT_EQ(a.positional("FILE"), "--in.x3d");
    EXPECT_EQ(a.positional("OUT"), "-o");
    EXPECT_TRUE(a.flag("json"));
}

TEST(OptionTable, DoubleDashQuotingOneArgumentAndDashedPositionals) {
    const CommandSpec spec{.name = "formula eval",
                           .synopsis = {"formula eval SRC"},
                           .positionals = {{.name = "SRC", .help = "the formula"}},
                           .options = {{.name = "json", .help = "JSON"}},
                           .positionalsMayStartWithDash = true,
                           .doubleDash = DoubleDash::QuotesNext};
    const ParsedArgs a = parseOk({"--", "--x", "--json"}, spec);
    EXPECT_EQ(a.positional("SRC"), "--x");
    EXPECT_TRUE(a.flag("json"));
    EXPECT_EQ(parseOk({"-x^2", "--json"}, spec).positional("SRC"), "-x^2");
    EXPECT_EQ(parseError({"--"}, spec), "-- needs the argument that follows it");
    EXPECT_EQ(parseError({"x", "y"}, spec),
              "unexpected argument 'y' (give one SRC; quote it as one argument)");
}

TEST(OptionTable, Help) {
    EXPECT_TRUE(parseOk({"--help"}).help()); // no FILE needed
    EXPECT_TRUE(parseOk({"f", "-h"}).help());
    int exit = -1;
    std::ostringstream out, err;
    EXPECT_FALSE(parseOrExplain(sample(), {"--help"}, exit, out, err));
    EXPECT_EQ(exit, 0);
    EXPECT_EQ(out.str(), helpText(sample()));
    EXPECT_TRUE(err.str().empty());
}

TEST(OptionTable, UsageErrorsNameTheCommandAndShowItsUsage) {
    int exit = -1;
    std::ostringstream out, err;
    EXPECT_FALSE(parseOrExplain(sample(), {"f", "--side", "abc"}, exit, out, err));
    EXPECT_EQ(exit, 2);
    EXPECT_TRUE(out.str().empty());
    EXPECT_EQ(err.str(), "functionlab sample: --side needs a number, not 'abc'\n\n"
                         "usage: functionlab sample FILE [OUT] [options]\n"
                         "Run `functionlab help sample` for the options.\n");
}

TEST(OptionTable, HelpListsEveryOptionWithItsDefault) {
    const std::string help = helpText(sample());
    EXPECT_NE(help.find("usage: functionlab sample FILE [OUT] [options]\n"), std::string::npos);
    EXPECT_NE(help.find("  -o, --output OUT"), std::string::npos);
    EXPECT_NE(help.find("points per side (default 64)"), std::string::npos);
    EXPECT_NE(help.find("  -h, --help"), std::string::npos);
    EXPECT_NE(help.find("exit status: 0 ok, 2 usage error"), std::string::npos);
    for (const OptionSpec& o : sample().options)
        EXPECT_NE(help.find("--" + std::string(o.name)), std::string::npos) << o.name;
    std::istringstream lines(help); // every line fits 80 columns
    for (std::string line; std::getline(lines, line);)
        EXPECT_LE(line.size(), 80u) << line;
}

TEST(OptionTable, MarkdownHasATableRowPerOption) {
    const std::string md = markdownText(sample());
    EXPECT_EQ(md.rfind("```\nfunctionlab sample FILE [OUT] [options]\n```\n", 0), 0u);
    EXPECT_NE(md.find("| `-o, --output OUT` | where | |"), std::string::npos);
    EXPECT_NE(md.find("| `--side N` | points per side | `64` |"), std::string::npos);
    EXPECT_NE(md.find("| `--param NAME=VALUE` (repeatable) |"), std::string::npos);
    EXPECT_NE(md.find("| `OUT` (optional) | the output | |"), std::string::npos);
}

TEST(OptionTable, ReadingAnUndeclaredOptionIsAProgrammingError) {
    const ParsedArgs a = parseOk({"f"});
    EXPECT_THROW(a.flag("jsno"), std::logic_error);
    EXPECT_THROW(a.number("json"), std::logic_error); // a flag, not a number
    EXPECT_THROW(a.positional("NOPE"), std::logic_error);
}

TEST(OptionTable, ClosestMatch) {
    EXPECT_EQ(closestMatch("mesj", {"mesh", "render", "check"}), "mesh");
    EXPECT_EQ(closestMatch("rendr", {"mesh", "render", "check"}), "render");
    EXPECT_EQ(closestMatch("mehs", {"mesh", "render", "check"}), "mesh"); // a swap is one edit
    EXPECT_EQ(closestMatch("xyzzy", {"mesh", "render", "check"}), "");
}

} // namespace
} // namespace fl::cli
