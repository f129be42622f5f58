#pragma once
// Writing JSON by hand, the two pieces every writer needs: a string with
// its escapes, and a number (JSON has no NaN or infinity: those are null).
// Header-only, so the command line, the haptics device listing and the
// benchmarks write the same JSON without a library between them.
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

namespace fl::text {

inline std::string jsonString(std::string_view s) {
    std::string out = "\"";
    for (char c : s) {
        switch (c) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\r':
            out += "\\r";
            break;
        case '\t':
            out += "\\t";
            break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned char>(c));
                out += buf;
            } else {
                out += c;
            }
        }
    }
    return out + "\"";
}

// Someone else's name (a student id from a gradebook, a file name) for a
// message on a terminal: as it is when every character is printable, else
// as a JSON string, so a control character (an escape sequence) is shown,
// never obeyed.
inline std::string shownName(std::string_view s) {
    for (char c : s)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return jsonString(s);
    return std::string(s);
}

inline std::string jsonNumber(double v) {
    if (!std::isfinite(v)) return "null";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

} // namespace fl::text
