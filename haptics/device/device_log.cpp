#include "device/device_log.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <system_error>

namespace fl::haptics {

namespace {

constexpr std::size_t kFieldsWithoutVelocity = 9; // t x y z qw qx qy qz buttons
constexpr std::size_t kFieldsWithVelocity = 12;   // t x y z qw qx qy qz vx vy vz buttons

struct Token {
    std::string_view text;
    int column; // 1-based
};

std::vector<Token> tokenize(std::string_view line) {
    std::vector<Token> tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
            ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t')
            ++i;
        if (i > start) tokens.push_back({line.substr(start, i - start), int(start) + 1});
    }
    return tokens;
}

std::string quoted(std::string_view text) {
    // Errors quote what they read; a hostile token is cut short and its
    // control bytes shown as '?', so the message stays one readable line.
    std::string out = "\"";
    for (std::size_t i = 0; i < text.size() && i < 40; ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        out += c < 0x20 || c == 0x7f ? '?' : char(c);
    }
    if (text.size() > 40) out += "…";
    return out + "\"";
}

class Parser {
  public:
    Parser(std::string_view text, std::string_view file) : text_(text), file_(file) {}

    LogRead run() {
        if (text_.size() > kMaxDeviceLogBytes)
            return fail(1, 1,
                        "the log is " + std::to_string(text_.size()) + " bytes, more than the " +
                            std::to_string(kMaxDeviceLogBytes >> 20) +
                            " MiB a device log may have: record shorter sessions");
        if (text_.empty()) return {std::nullopt, header("", 1)};
        std::size_t pos = 0;
        int lineNo = 0;
        while (pos < text_.size()) {
            const std::size_t end = std::min(text_.find('\n', pos), text_.size());
            std::string_view line = text_.substr(pos, end - pos);
            pos = end + 1;
            ++lineNo;
            if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
            if (line.size() > kMaxDeviceLogLine)
                return fail(lineNo, int(kMaxDeviceLogLine) + 1,
                            "the line is longer than " + std::to_string(kMaxDeviceLogLine) +
                                " bytes: a device log has one short sample a line");
            if (lineNo == 1) {
                if (auto error = header(line, lineNo)) return {std::nullopt, error};
                continue;
            }
            const std::vector<Token> tokens = tokenize(line);
            if (tokens.empty() || tokens[0].text[0] == '#') continue;
            std::optional<LogError> error;
            if (tokens[0].text == "device")
                error = deviceLine(line, tokens, lineNo);
            else if (tokens[0].text == "limits")
                error = limitsLine(tokens, lineNo);
            else
                error = sample(tokens, lineNo);
            if (error) return {std::nullopt, error};
        }
        if (log_.samples.empty())
            return fail(lineNo, 1,
                        "the log has no samples: a sample line is \"t x y z qw qx qy qz "
                        "buttons\", optionally with \"vx vy vz\" before buttons");
        if (!log_.hasVelocity) estimateVelocities(log_.samples);
        return {std::move(log_), std::nullopt};
    }

  private:
    LogRead fail(int line, int column, std::string message) const {
        return {std::nullopt, error(line, column, std::move(message))};
    }
    LogError error(int line, int column, std::string message) const {
        return LogError{std::string(file_), line, column, std::move(message)};
    }

    std::optional<LogError> header(std::string_view line, int lineNo) {
        const std::vector<Token> tokens = tokenize(line);
        const std::string expected =
            std::string(kDeviceLogMagic) + " " + std::to_string(kDeviceLogVersion);
        if (tokens.size() != 2 || tokens[0].text != kDeviceLogMagic)
            return error(lineNo, 1,
                         "this is not a FunctionLab device log: its first line must be \"" +
                             expected + "\"");
        int version = 0;
        const Token& v = tokens[1];
        const auto [ptr, ec] =
            std::from_chars(v.text.data(), v.text.data() + v.text.size(), version);
        if (ec != std::errc() || ptr != v.text.data() + v.text.size() || version < 1)
            return error(lineNo, v.column,
                         "the version " + quoted(v.text) + " is not a positive whole number");
        if (version > kDeviceLogVersion)
            return error(lineNo, v.column,
                         "the log is version " + std::to_string(version) +
                             ", newer than the version " + std::to_string(kDeviceLogVersion) +
                             " this FunctionLab reads: update FunctionLab to replay it");
        return std::nullopt;
    }

    std::optional<LogError> beforeSamples(const Token& keyword, int lineNo) const {
        if (!log_.samples.empty())
            return error(lineNo, keyword.column,
                         "\"" + std::string(keyword.text) +
                             "\" must come before the first sample: move it up to the header");
        return std::nullopt;
    }

    std::optional<LogError> deviceLine(std::string_view line, const std::vector<Token>& tokens,
                                       int lineNo) {
        if (auto e = beforeSamples(tokens[0], lineNo)) return e;
        if (sawDevice_)
            return error(lineNo, tokens[0].column,
                         "a second \"device\" line: a log records one device");
        sawDevice_ = true;
        if (tokens.size() < 2) return std::nullopt; // an unnamed device
        std::string_view name = line.substr(std::size_t(tokens[1].column - 1));
        while (!name.empty() && (name.back() == ' ' || name.back() == '\t'))
            name.remove_suffix(1);
        if (name.size() > kMaxDeviceNameBytes)
            return error(lineNo, tokens[1].column,
                         "the device name is longer than " + std::to_string(kMaxDeviceNameBytes) +
                             " bytes");
        for (std::size_t i = 0; i < name.size(); ++i) {
            const unsigned char c = static_cast<unsigned char>(name[i]);
            if ((c < 0x20 && c != '\t') || c == 0x7f)
                return error(lineNo, tokens[1].column + int(i),
                             "the device name has a control character: write plain text");
        }
        log_.deviceName = std::string(name);
        return std::nullopt;
    }

    std::optional<LogError> number(const Token& token, int lineNo, double& out,
                                   std::string_view what) const {
        const char* first = token.text.data();
        const char* last = first + token.text.size();
        const auto [ptr, ec] = std::from_chars(first, last, out);
        if (ec != std::errc() || ptr != last || !std::isfinite(out))
            return error(lineNo, token.column,
                         std::string(what) + " " + quoted(token.text) +
                             " is not a finite number (write it as 0.125 or 1.25e-3)");
        return std::nullopt;
    }

    std::optional<LogError> limitsLine(const std::vector<Token>& tokens, int lineNo) {
        if (auto e = beforeSamples(tokens[0], lineNo)) return e;
        if (log_.limits)
            return error(lineNo, tokens[0].column,
                         "a second \"limits\" line: a log records one device");
        if (tokens.size() != 5)
            return error(lineNo, tokens[0].column,
                         "\"limits\" takes four numbers: max force (N), max stiffness (N/m), "
                         "max damping (N·s/m), workspace radius (m)");
        double v[4];
        static constexpr std::string_view names[4] = {"max force", "max stiffness", "max damping",
                                                      "workspace radius"};
        for (int k = 0; k < 4; ++k) {
            if (auto e = number(tokens[k + 1], lineNo, v[k], names[k])) return e;
            if (v[k] < 0)
                return error(lineNo, tokens[k + 1].column,
                             std::string(names[k]) + " is negative: limits are 0 or more");
        }
        log_.limits = DeviceLimits{v[0], v[1], v[2], v[3]};
        return std::nullopt;
    }

    std::optional<LogError> sample(const std::vector<Token>& tokens, int lineNo) {
        const std::size_t n = tokens.size();
        for (std::size_t i = 1; i < n; ++i)
            if (tokens[i].text[0] == '#')
                return error(lineNo, tokens[i].column,
                             "a # comment must be on a line of its own, not after a sample");
        // A line that does not even start with a number is a misspelt
        // keyword or not a log line at all: say what lines there are.
        double probe;
        const Token& first = tokens[0];
        if (std::from_chars(first.text.data(), first.text.data() + first.text.size(), probe).ec !=
            std::errc())
            return error(lineNo, first.column,
                         quoted(first.text) +
                             " starts no known line: a line is a sample, \"device\", "
                             "\"limits\" or a # comment");
        if (n != kFieldsWithoutVelocity && n != kFieldsWithVelocity) {
            const int column =
                n > kFieldsWithVelocity ? tokens[kFieldsWithVelocity].column : tokens.back().column;
            return error(lineNo, column,
                         "a sample has 9 fields (t x y z qw qx qy qz buttons) or 12 (vx vy vz "
                         "before buttons); this line has " +
                             std::to_string(n));
        }
        const bool withVelocity = n == kFieldsWithVelocity;
        if (log_.samples.empty()) {
            log_.hasVelocity = withVelocity;
        } else if (withVelocity != log_.hasVelocity) {
            return error(lineNo, tokens[0].column,
                         "this sample has " + std::to_string(n) + " fields but the first had " +
                             std::to_string(log_.hasVelocity ? kFieldsWithVelocity
                                                             : kFieldsWithoutVelocity) +
                             ": write the velocity on every sample or on none");
        }
        if (log_.samples.size() >= kMaxDeviceLogSamples)
            return error(lineNo, 1,
                         "more than " + std::to_string(kMaxDeviceLogSamples) +
                             " samples: record shorter sessions");
        DeviceState s;
        if (auto e = number(tokens[0], lineNo, s.time, "time")) return e;
        if (!log_.samples.empty() && !(s.time > log_.samples.back().time)) {
            char previous[32];
            const auto r =
                std::to_chars(previous, previous + sizeof previous, log_.samples.back().time);
            return error(lineNo, tokens[0].column,
                         "time " + std::string(tokens[0].text) + " is not after the previous " +
                             "sample's " + std::string(previous, r.ptr) +
                             ": samples must be in increasing time order");
        }
        static constexpr std::string_view axis[3] = {"x", "y", "z"};
        for (int k = 0; k < 3; ++k)
            if (auto e = number(tokens[1 + k], lineNo, s.position[k], axis[k])) return e;
        static constexpr std::string_view quat[4] = {"qw", "qx", "qy", "qz"};
        for (int k = 0; k < 4; ++k)
            if (auto e = number(tokens[4 + k], lineNo, s.orientation[k], quat[k])) return e;
        const double norm =
            std::sqrt(s.orientation[0] * s.orientation[0] + s.orientation[1] * s.orientation[1] +
                      s.orientation[2] * s.orientation[2] + s.orientation[3] * s.orientation[3]);
        if (!(std::abs(norm - 1) <= kQuaternionNormTolerance))
            return error(lineNo, tokens[4].column,
                         "the orientation qw qx qy qz is not a unit quaternion (its length is " +
                             std::to_string(norm) + "): write 1 0 0 0 for no rotation");
        if (withVelocity) {
            static constexpr std::string_view vel[3] = {"vx", "vy", "vz"};
            for (int k = 0; k < 3; ++k)
                if (auto e = number(tokens[8 + k], lineNo, s.velocity[k], vel[k])) return e;
        }
        const Token& b = tokens[n - 1];
        const auto [ptr, ec] =
            std::from_chars(b.text.data(), b.text.data() + b.text.size(), s.buttons);
        if (ec != std::errc() || ptr != b.text.data() + b.text.size())
            return error(lineNo, b.column,
                         "buttons " + quoted(b.text) +
                             " is not a whole number from 0 to 4294967295 (bit i: button i)");
        log_.samples.push_back(s);
        return std::nullopt;
    }

    std::string_view text_;
    std::string_view file_;
    DeviceLog log_;
    bool sawDevice_ = false;
};

void appendNumber(std::string& out, double v) {
    char buffer[32];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
    out.append(buffer, r.ptr);
}

} // namespace

std::string LogError::text() const {
    return file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message;
}

LogRead parseDeviceLog(std::string_view text, std::string_view fileName) {
    return Parser(text, fileName).run();
}

LogRead readDeviceLog(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) return {std::nullopt, LogError{name, 0, 0, "cannot read the log: " + ec.message()}};
    if (size > kMaxDeviceLogBytes)
        return {std::nullopt,
                LogError{name, 1, 1,
                         "the log is " + std::to_string(size) + " bytes, more than the " +
                             std::to_string(kMaxDeviceLogBytes >> 20) +
                             " MiB a device log may have: record shorter sessions"}};
    std::ifstream in(path, std::ios::binary);
    std::string text(static_cast<std::size_t>(size), '\0');
    if (!in || !in.read(text.data(), std::streamsize(size)))
        return {std::nullopt, LogError{name, 0, 0, "cannot read the log"}};
    return parseDeviceLog(text, name);
}

std::string formatLogHeader(std::string_view deviceName, const std::optional<DeviceLimits>& limits,
                            bool withVelocity) {
    std::string out = std::string(kDeviceLogMagic) + " " + std::to_string(kDeviceLogVersion) + "\n";
    out += withVelocity ? "# t x y z qw qx qy qz vx vy vz buttons\n"
                        : "# t x y z qw qx qy qz buttons\n";
    // A name is one line: control bytes that would break it are dropped,
    // and the ends trimmed as the reader trims them.
    std::string name;
    for (char c : deviceName.substr(0, kMaxDeviceNameBytes))
        if ((static_cast<unsigned char>(c) >= 0x20 || c == '\t') && c != 0x7f) name += c;
    const std::size_t first = name.find_first_not_of(" \t");
    name = first == std::string::npos
               ? ""
               : name.substr(first, name.find_last_not_of(" \t") + 1 - first);
    if (!name.empty()) out += "device " + name + "\n";
    if (limits) {
        out += "limits";
        for (double v : {limits->maxForce, limits->maxStiffness, limits->maxDamping,
                         limits->workspaceRadius}) {
            out += ' ';
            appendNumber(out, std::isfinite(v) && v >= 0 ? v : 0.0);
        }
        out += '\n';
    }
    return out;
}

std::string formatLogSample(const DeviceState& s, bool withVelocity) {
    std::string out;
    appendNumber(out, s.time);
    for (double v : s.position) {
        out += ' ';
        appendNumber(out, v);
    }
    for (double v : s.orientation) {
        out += ' ';
        appendNumber(out, v);
    }
    if (withVelocity)
        for (double v : s.velocity) {
            out += ' ';
            appendNumber(out, v);
        }
    out += ' ';
    out += std::to_string(s.buttons);
    out += '\n';
    return out;
}

std::string formatDeviceLog(const DeviceLog& log) {
    std::string out = formatLogHeader(log.deviceName, log.limits, log.hasVelocity);
    for (const DeviceState& s : log.samples)
        out += formatLogSample(s, log.hasVelocity);
    return out;
}

void estimateVelocities(std::vector<DeviceState>& samples) {
    const std::size_t n = samples.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (n < 2) {
            samples[i].velocity = {};
            continue;
        }
        const std::size_t a = i == 0 ? 0 : i - 1;
        const std::size_t b = i + 1 == n ? n - 1 : i + 1;
        const double dt = samples[b].time - samples[a].time;
        const field::Vec3 dp = field::minus(samples[b].position, samples[a].position);
        const field::Vec3 v = field::scaled(dp, 1 / dt);
        // Times 1e-300 apart or positions 1e300 apart overflow: no estimate.
        samples[i].velocity = field::isFinite(v) ? v : field::Vec3{};
    }
}

} // namespace fl::haptics
