#include "platform/option_table.h"

#include "text/edit_distance.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace fl::cli {

namespace {

std::string str(std::string_view s) {
    return std::string(s);
}

std::string numberText(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.15g", v);
    return buf;
}

bool isDigits(std::string_view s) {
    if (!s.empty() && (s.front() == '-' || s.front() == '+')) s.remove_prefix(1);
    return !s.empty() &&
           std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::string optionName(const OptionSpec& o) {
    return "--" + str(o.name);
}

// "from 2 to 512", "at least 0", "above 0", "at most 60", or empty.
std::string rangeText(const OptionSpec& o) {
    const bool lo = std::isfinite(o.min), hi = std::isfinite(o.max);
    if (lo && hi && !o.minExclusive)
        return "from " + numberText(o.min) + " to " + numberText(o.max);
    if (lo && hi) return "above " + numberText(o.min) + " and at most " + numberText(o.max);
    if (lo) return (o.minExclusive ? "above " : "at least ") + numberText(o.min);
    if (hi) return "at most " + numberText(o.max);
    return {};
}

bool inRange(const OptionSpec& o, double v) {
    if (o.minExclusive ? !(v > o.min) : !(v >= o.min)) return false;
    return v <= o.max;
}

// The usage hint for an option's value: "--at X,Y,Z".
std::string withValue(const OptionSpec& o) {
    return o.kind == OptionKind::Flag ? optionName(o) : optionName(o) + " " + str(o.valueName);
}

// Reads one value of `o` from `text`; an error message when it is not one.
std::optional<std::string> readValue(const OptionSpec& o, const std::string& text, OptionValue& v) {
    v.text = text;
    const std::string name = optionName(o);
    const std::string quoted = "'" + text + "'";
    switch (o.kind) {
    case OptionKind::Flag:
        return name + " takes no value";
    case OptionKind::Text:
    case OptionKind::Path:
        if (o.kind == OptionKind::Path && text.empty()) return name + " needs a file name";
        return std::nullopt;
    case OptionKind::Number: {
        if (!parseFiniteNumber(text, v.number)) {
            double any = 0;
            char* end = nullptr;
            any = std::strtod(text.c_str(), &end);
            if (!text.empty() && end && *end == '\0' && !std::isfinite(any))
                return name + " needs a finite number, not " + quoted;
            return name + " needs a number, not " + quoted;
        }
        if (!inRange(o, v.number))
            return name + " needs a number " + rangeText(o) + ", not " + quoted;
        return std::nullopt;
    }
    case OptionKind::Integer: {
        if (isDigits(text)) {
            if (!parseWholeNumber(text, v.integer))
                return name + " needs a whole number, and " + quoted + " is too large";
        } else {
            double d = 0;
            if (!parseFiniteNumber(text, d)) return name + " needs a number, not " + quoted;
            if (d != std::floor(d)) return name + " needs a whole number, not " + quoted;
            if (std::fabs(d) > 9007199254740992.0)
                return name + " needs a whole number, and " + quoted + " is too large";
            v.integer = std::int64_t(d);
        }
        v.number = double(v.integer);
        if (!inRange(o, v.number))
            return name + " needs a whole number " + rangeText(o) + ", not " + quoted;
        return std::nullopt;
    }
    case OptionKind::NumberList: {
        const std::string shape = o.count > 0
                                      ? std::to_string(o.count) + " finite numbers: " + withValue(o)
                                      : "finite numbers: " + withValue(o);
        std::stringstream in(text);
        v.numbers.clear();
        for (std::string part; std::getline(in, part, ',');) {
            double d = 0;
            if (!parseFiniteNumber(part, d)) return name + " needs " + shape + ", not " + quoted;
            v.numbers.push_back(d);
        }
        if (text.empty() || text.back() == ',' || v.numbers.empty() ||
            (o.count > 0 && v.numbers.size() != std::size_t(o.count)))
            return name + " needs " + shape + ", not " + quoted;
        for (double d : v.numbers)
            if (!inRange(o, d)) return name + " needs numbers " + rangeText(o) + ", not " + quoted;
        return std::nullopt;
    }
    case OptionKind::KeyValue: {
        const std::size_t eq = text.find('=');
        if (eq == std::string::npos || eq == 0)
            return name + " needs " + str(o.valueName) + ", not " + quoted;
        v.key = text.substr(0, eq);
        v.text = text.substr(eq + 1);
        if (o.numericValue && !parseFiniteNumber(v.text, v.number))
            return name + " needs " + str(o.valueName) + " with a finite number after '=', not " +
                   quoted;
        return std::nullopt;
    }
    case OptionKind::Choice: {
        for (std::string_view c : o.choices)
            if (c == text) return std::nullopt;
        std::string list;
        for (std::string_view c : o.choices)
            list += (list.empty() ? "" : ", ") + str(c);
        return name + " needs one of " + list + ", not " + quoted;
    }
    case OptionKind::Size: {
        const std::size_t x = text.find('x');
        std::int64_t w = 0, h = 0;
        const bool ok = x != std::string::npos && isDigits(text.substr(0, x)) &&
                        isDigits(text.substr(x + 1)) && parseWholeNumber(text.substr(0, x), w) &&
                        parseWholeNumber(text.substr(x + 1), h) && inRange(o, double(w)) &&
                        inRange(o, double(h)) && text[0] != '-' && text[0] != '+' &&
                        text[x + 1] != '-' && text[x + 1] != '+';
        if (!ok)
            return name + " needs " + str(o.valueName) + ", e.g. 800x600 (each " + rangeText(o) +
                   "), not " + quoted;
        v.width = int(w);
        v.height = int(h);
        return std::nullopt;
    }
    }
    return std::nullopt;
}

// Word wrapping for help text: `text` in lines of at most `width` columns,
// every line after the first indented by `indent` spaces.
std::string wrap(std::string_view text, std::size_t width, std::size_t indent) {
    std::string out, line;
    std::istringstream words{std::string(text)};
    std::size_t lineWidth = width;
    for (std::string word; words >> word;) {
        if (!line.empty() && line.size() + 1 + word.size() > lineWidth) {
            out += line + "\n" + std::string(indent, ' ');
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    return out + line;
}

std::string defaultNote(const OptionSpec& o) {
    return o.defaultValue.empty() ? std::string() : " (default " + str(o.defaultValue) + ")";
}

std::string optionLabel(const OptionSpec& o) {
    std::string label = o.shortName ? std::string("-") + o.shortName + ", " : std::string();
    return label + withValue(o);
}

std::vector<std::string> optionNames(const CommandSpec& spec) {
    std::vector<std::string> names;
    for (const OptionSpec& o : spec.options)
        names.push_back(optionName(o));
    names.push_back("--help");
    return names;
}

} // namespace

bool parseFiniteNumber(std::string_view text, double& out) {
    if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return false;
    const std::string s(text);
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(s.c_str(), &end);
    // Hexadecimal floats are not numbers a student means.
    if (!end || *end != '\0' || s.find_first_of("xX") != std::string::npos) return false;
    if (!std::isfinite(v)) return false;
    out = v;
    return true;
}

bool parseWholeNumber(std::string_view text, std::int64_t& out) {
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    std::int64_t v = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || ptr != text.data() + text.size() || text.empty()) return false;
    out = v;
    return true;
}

std::string closestMatch(std::string_view word, const std::vector<std::string>& candidates) {
    std::string best;
    std::size_t bestDistance = std::string::npos;
    for (const std::string& c : candidates) {
        const std::size_t d = text::editDistance(word, c);
        // A prefix ("--res" for "--resolution") is a likely meaning too.
        const bool prefix = word.size() >= 4 && c.rfind(word, 0) == 0;
        const std::size_t score = prefix ? 1 : d;
        if (score < bestDistance) {
            bestDistance = score;
            best = c;
        }
    }
    const std::size_t allowed = std::max<std::size_t>(1, std::min<std::size_t>(3, word.size() / 3));
    return bestDistance <= allowed ? best : std::string();
}

// ParsedArgs ------------------------------------------------------------------

const OptionSpec& ParsedArgs::spec(std::string_view name, OptionKind kind) const {
    for (const OptionSpec& o : spec_->options) {
        if (o.name != name) continue;
        const bool numeric = kind == OptionKind::Number &&
                             (o.kind == OptionKind::Number || o.kind == OptionKind::Integer);
        const bool textual =
            kind == OptionKind::Text && (o.kind == OptionKind::Text || o.kind == OptionKind::Path ||
                                         o.kind == OptionKind::Choice);
        if (o.kind != kind && !numeric && !textual)
            throw std::logic_error("functionlab " + str(spec_->name) + ": --" + str(name) +
                                   " is read as another kind than it is declared");
        return o;
    }
    throw std::logic_error("functionlab " + str(spec_->name) + " declares no option --" +
                           str(name));
}

const OptionValue* ParsedArgs::last(std::string_view name) const {
    const auto it = values_.find(name);
    return it == values_.end() || it->second.empty() ? nullptr : &it->second.back();
}

bool ParsedArgs::given(std::string_view name) const {
    bool declared = false;
    for (const OptionSpec& o : spec_->options)
        declared = declared || o.name == name;
    if (!declared)
        throw std::logic_error("functionlab " + str(spec_->name) + " declares no option --" +
                               str(name));
    return given_.contains(name);
}

bool ParsedArgs::flag(std::string_view name) const {
    spec(name, OptionKind::Flag);
    return given_.contains(name);
}

std::optional<double> ParsedArgs::number(std::string_view name) const {
    spec(name, OptionKind::Number);
    const OptionValue* v = last(name);
    return v ? std::optional<double>(v->number) : std::nullopt;
}

double ParsedArgs::number(std::string_view name, double fallback) const {
    return number(name).value_or(fallback);
}

std::optional<std::int64_t> ParsedArgs::integer(std::string_view name) const {
    spec(name, OptionKind::Integer);
    const OptionValue* v = last(name);
    return v ? std::optional<std::int64_t>(v->integer) : std::nullopt;
}

std::int64_t ParsedArgs::integer(std::string_view name, std::int64_t fallback) const {
    return integer(name).value_or(fallback);
}

std::string ParsedArgs::text(std::string_view name, std::string fallback) const {
    spec(name, OptionKind::Text);
    const OptionValue* v = last(name);
    return v ? v->text : fallback;
}

std::optional<std::vector<double>> ParsedArgs::numbers(std::string_view name) const {
    spec(name, OptionKind::NumberList);
    const OptionValue* v = last(name);
    return v ? std::optional<std::vector<double>>(v->numbers) : std::nullopt;
}

std::vector<std::pair<std::string, std::string>>
ParsedArgs::keyValues(std::string_view name) const {
    spec(name, OptionKind::KeyValue);
    std::vector<std::pair<std::string, std::string>> out;
    for (const OptionValue& v : values(name))
        out.emplace_back(v.key, v.text);
    return out;
}

std::vector<std::pair<std::string, double>> ParsedArgs::keyNumbers(std::string_view name) const {
    if (!spec(name, OptionKind::KeyValue).numericValue)
        throw std::logic_error("--" + str(name) + " does not take numbers");
    std::vector<std::pair<std::string, double>> out;
    for (const OptionValue& v : values(name))
        out.emplace_back(v.key, v.number);
    return out;
}

std::optional<std::pair<int, int>> ParsedArgs::size(std::string_view name) const {
    spec(name, OptionKind::Size);
    const OptionValue* v = last(name);
    return v ? std::optional<std::pair<int, int>>({v->width, v->height}) : std::nullopt;
}

const std::vector<OptionValue>& ParsedArgs::values(std::string_view name) const {
    static const std::vector<OptionValue> none;
    given(name); // declared?
    const auto it = values_.find(name);
    return it == values_.end() ? none : it->second;
}

std::string ParsedArgs::positional(std::string_view name) const {
    for (std::size_t i = 0; i < spec_->positionals.size(); ++i)
        if (spec_->positionals[i].name == name)
            return i < positionals_.size() ? positionals_[i] : std::string();
    throw std::logic_error("functionlab " + str(spec_->name) + " declares no argument " +
                           str(name));
}

// Parsing ---------------------------------------------------------------------

struct Parser {
    static ParseResult parse(const CommandSpec& spec, const Args& args) {
        ParseResult result;
        ParsedArgs parsed(spec);
        auto fail = [&](std::string message) {
            result.error.message = std::move(message);
            return result;
        };
        auto store = [&](const OptionSpec& o,
                         const std::string& text) -> std::optional<std::string> {
            OptionValue v;
            if (auto error = readValue(o, text, v)) return error;
            auto& list = parsed.values_[str(o.name)];
            if (!o.repeatable) list.clear(); // the last one counts
            list.push_back(std::move(v));
            parsed.given_[str(o.name)] = true;
            return std::nullopt;
        };
        auto findLong = [&](std::string_view name) -> const OptionSpec* {
            for (const OptionSpec& o : spec.options)
                if (o.name == name) return &o;
            return nullptr;
        };
        auto findShort = [&](char c) -> const OptionSpec* {
            for (const OptionSpec& o : spec.options)
                if (o.shortName && o.shortName == c) return &o;
            return nullptr;
        };
        bool optionsEnded = false;
        for (std::size_t i = 0; i < args.size(); ++i) {
            const std::string& a = args[i];
            if (optionsEnded) {
                parsed.positionals_.push_back(a);
                continue;
            }
            if (a == "--") {
                if (spec.doubleDash == DoubleDash::EndsOptions) {
                    optionsEnded = true;
                } else if (i + 1 < args.size()) {
                    parsed.positionals_.push_back(args[++i]);
                } else {
                    return fail("-- needs the argument that follows it");
                }
                continue;
            }
            if (a == "--help" || a == "-h") {
                parsed.help_ = true;
                continue;
            }
            const OptionSpec* o = nullptr;
            std::optional<std::string> inlineValue;
            std::string written = a;
            if (a.starts_with("--")) {
                const std::size_t eq = a.find('=');
                const std::string name = a.substr(2, eq == std::string::npos ? eq : eq - 2);
                if (eq != std::string::npos) {
                    inlineValue = a.substr(eq + 1);
                    written = a.substr(0, eq);
                }
                o = findLong(name);
                if (!o) {
                    std::string message = "unknown option '" + written + "'";
                    if (std::string near = closestMatch(written, optionNames(spec)); !near.empty())
                        message += " (did you mean " + near + "?)";
                    return fail(message);
                }
            } else if (a.size() == 2 && a[0] == '-' && findShort(a[1])) {
                o = findShort(a[1]);
            } else if (a.size() > 1 && a[0] == '-' && !spec.positionalsMayStartWithDash) {
                std::string message = "unknown option '" + a + "'";
                if (std::string near = closestMatch("-" + a, optionNames(spec)); !near.empty())
                    message += " (did you mean " + near + "?)";
                return fail(message);
            } else {
                parsed.positionals_.push_back(a);
                continue;
            }
            if (o->kind == OptionKind::Flag) {
                if (inlineValue) return fail(optionName(*o) + " takes no value");
                parsed.values_[str(o->name)].assign(1, OptionValue{});
                parsed.given_[str(o->name)] = true;
                continue;
            }
            // The next argument is the value whatever it begins with:
            // `--at -1,0,0`, `--formula "-x"`.
            std::string value;
            if (inlineValue) {
                value = *inlineValue;
            } else if (i + 1 < args.size()) {
                value = args[++i];
            } else {
                return fail(written + " needs a value: " + withValue(*o));
            }
            if (auto error = store(*o, value)) return fail(*error);
        }
        if (!parsed.help_) {
            const std::size_t declared = spec.positionals.size();
            const bool repeats = declared > 0 && spec.positionals.back().repeats;
            if (parsed.positionals_.size() > declared && !repeats) {
                const std::string& extra = parsed.positionals_[declared];
                return fail(declared == 0 ? "unexpected argument '" + extra + "'"
                                          : "unexpected argument '" + extra + "' (give one " +
                                                str(spec.positionals.back().name) +
                                                (spec.positionalsMayStartWithDash
                                                     ? "; quote it as one argument)"
                                                     : ")"));
            }
            for (std::size_t p = parsed.positionals_.size(); p < declared; ++p)
                if (spec.positionals[p].required)
                    return fail("missing " + str(spec.positionals[p].name));
        }
        // Defaults, read the same way as given values.
        for (const OptionSpec& o : spec.options) {
            if (o.defaultValue.empty() || parsed.values_.contains(o.name)) continue;
            OptionValue v;
            if (auto error = readValue(o, str(o.defaultValue), v))
                throw std::logic_error("functionlab " + str(spec.name) + ": the default of " +
                                       *error);
            parsed.values_[str(o.name)].push_back(std::move(v));
        }
        result.args.emplace(std::move(parsed));
        return result;
    }
};

ParseResult parseArguments(const CommandSpec& spec, const Args& args) {
    return Parser::parse(spec, args);
}

std::optional<ParsedArgs> parseOrExplain(const CommandSpec& spec, const Args& args, int& exitCode,
                                         std::ostream& out, std::ostream& err) {
    ParseResult r = parseArguments(spec, args);
    if (!r.ok()) {
        exitCode = usageError(spec, r.error.message, err);
        return std::nullopt;
    }
    if (r.args->help()) {
        out << helpText(spec);
        exitCode = 0;
        return std::nullopt;
    }
    return std::move(r.args);
}

int usageError(const CommandSpec& spec, const std::string& message, std::ostream& err) {
    err << "functionlab " << spec.name << ": " << message << "\n\n"
        << usageText(spec) << "Run `functionlab help " << spec.name << "` for the options.\n";
    return 2;
}

// Help and markdown -----------------------------------------------------------

namespace {
// One synopsis entry: its continuation lines (after '\n') indented under the
// arguments of its first line.
std::string synopsisLines(const CommandSpec& spec, std::string_view entry, std::size_t indent) {
    std::string out = "functionlab " + str(entry.substr(0, entry.find('\n'))) + "\n";
    const std::string pad(indent + std::string_view("functionlab ").size() + spec.name.size() + 1,
                          ' ');
    for (std::size_t at = entry.find('\n'); at != std::string_view::npos;) {
        const std::size_t next = entry.find('\n', at + 1);
        std::string_view line =
            entry.substr(at + 1, next == std::string_view::npos ? next : next - at - 1);
        while (!line.empty() && line.front() == ' ')
            line.remove_prefix(1);
        out += pad + str(line) + "\n";
        at = next;
    }
    return out;
}
} // namespace

std::string usageText(const CommandSpec& spec) {
    std::string out;
    for (std::size_t i = 0; i < spec.synopsis.size(); ++i)
        out += std::string(i ? "       " : "usage: ") + synopsisLines(spec, spec.synopsis[i], 7);
    return out;
}

std::string helpText(const CommandSpec& spec) {
    std::string out = usageText(spec) + "\n";
    if (!spec.description.empty()) out += str(spec.description) + "\n";
    if (!spec.positionals.empty()) {
        out += "arguments:\n";
        for (const PositionalSpec& p : spec.positionals) {
            std::string label = "  " + str(p.name);
            label.resize(std::max<std::size_t>(label.size() + 2, 24), ' ');
            out += label + wrap(p.help, 80 - 24, 24) + "\n";
        }
        out += "\n";
    }
    out += "options:\n";
    for (const OptionSpec& o : spec.options) {
        std::string label = "  " + optionLabel(o);
        std::string help = str(o.help) + defaultNote(o);
        if (label.size() + 2 > 24) {
            out += label + "\n" + std::string(24, ' ') + wrap(help, 80 - 24, 24) + "\n";
        } else {
            label.resize(24, ' ');
            out += label + wrap(help, 80 - 24, 24) + "\n";
        }
    }
    out += "  -h, --help            print this help\n";
    if (!spec.notes.empty()) out += "\n" + str(spec.notes);
    if (!spec.exitStatus.empty())
        out += "\n" + wrap("exit status: " + str(spec.exitStatus), 80, 0) + "\n";
    return out;
}

namespace {
std::string markdownCell(std::string_view text) {
    std::string out;
    for (char c : text) {
        if (c == '|')
            out += "\\|";
        else if (c == '\n')
            out += ' ';
        else
            out += c;
    }
    return out;
}
} // namespace

std::string markdownText(const CommandSpec& spec) {
    std::string out = "```\n";
    for (std::string_view entry : spec.synopsis)
        out += synopsisLines(spec, entry, 0);
    out += "```\n\n";
    auto row = [](const std::vector<std::string>& cells) {
        std::string line = "|";
        for (const std::string& c : cells)
            line += c.empty() ? " |" : " " + c + " |";
        return line + "\n";
    };
    out += row({"argument or option", "meaning", "default"}) + row({"---", "---", "---"});
    // Built with append: GCC 12 warns falsely (-Wrestrict, bug 105329) about
    // literal + std::string chains.
    auto code = [](std::string_view text) { return std::string("`").append(text).append("`"); };
    for (const PositionalSpec& p : spec.positionals)
        out += row({code(p.name)
                        .append(p.required ? "" : " (optional)")
                        .append(p.repeats ? " (one or more)" : ""),
                    markdownCell(p.help), ""});
    for (const OptionSpec& o : spec.options)
        out += row({code(markdownCell(optionLabel(o))).append(o.repeatable ? " (repeatable)" : ""),
                    markdownCell(o.help), o.defaultValue.empty() ? "" : code(o.defaultValue)});
    if (!spec.exitStatus.empty()) out += "\nExit status: " + str(spec.exitStatus) + ".\n";
    return out;
}

} // namespace fl::cli
