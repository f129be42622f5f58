#include "number_text.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>

namespace fl::scene {

bool parseNumberText(std::string_view tok, FieldType single, double& out, std::string& problem) {
    if (single == FieldType::SFBool) {
        if (tok == "true" || tok == "TRUE") {
            out = 1;
            return true;
        }
        if (tok == "false" || tok == "FALSE") {
            out = 0;
            return true;
        }
        problem = "expected true or false, found '" + std::string(tok.substr(0, 40)) + "'";
        return false;
    }
    std::string_view s = tok;
    bool negative = false;
    if (!s.empty() && (s[0] == '+' || s[0] == '-')) {
        negative = s[0] == '-';
        s.remove_prefix(1);
    }
    if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
        std::uint64_t u = 0;
        auto [p, ec] = std::from_chars(s.data() + 2, s.data() + s.size(), u, 16);
        if (ec != std::errc() || p != s.data() + s.size() || u > 0xFFFFFFFFull) {
            problem = "malformed hexadecimal number '" + std::string(tok.substr(0, 40)) + "'";
            return false;
        }
        out = single == FieldType::SFImage ? static_cast<double>(u)
                                           : static_cast<double>(static_cast<std::int32_t>(u));
        if (negative) out = -out;
        return true;
    }
    if (single == FieldType::SFInt32 || single == FieldType::SFImage) {
        long long v = 0;
        auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
        if (ec != std::errc() || p != s.data() + s.size()) {
            problem = "expected a whole number, found '" + std::string(tok.substr(0, 40)) + "'";
            return false;
        }
        if (negative) v = -v;
        if (single == FieldType::SFInt32 && (v < std::numeric_limits<std::int32_t>::min() ||
                                             v > std::numeric_limits<std::int32_t>::max())) {
            problem = std::string(tok) + " does not fit in SFInt32";
            return false;
        }
        out = static_cast<double>(v);
        return true;
    }
    double v = 0;
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec == std::errc::result_out_of_range && p == s.data() + s.size()) {
        // from_chars does not say which way it left the range; strtod does.
        // Underflow to (nearly) zero is harmless; overflow is not.
        v = std::strtod(std::string(s).c_str(), nullptr);
        if (std::isinf(v)) {
            problem = std::string(tok.substr(0, 40)) + " is too large for a number";
            return false;
        }
    } else if (ec != std::errc() || p != s.data() + s.size() || s.empty() ||
               !(s[0] == '.' || (s[0] >= '0' && s[0] <= '9'))) {
        // from_chars also takes "inf" and "nan"; X3D does not
        problem = "expected a number, found '" + std::string(tok.substr(0, 40)) + "'";
        return false;
    }
    out = negative ? -v : v;
    return true;
}

} // namespace fl::scene
