// Field values written as X3D XML attribute text: numbers separated by white
// space or commas, true/false, SFString as is, MFString as "quoted" "items".
#include "xml_reader.h"

#include "source_map.h"

#include <charconv>
#include <limits>

namespace fl::scene {
namespace {

bool isSep(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',';
}

bool parseNumber(std::string_view tok, FieldType single, double& out, std::string& problem) {
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
        if (s.find("e-") == std::string_view::npos && s.find("E-") == std::string_view::npos) {
            problem = std::string(tok.substr(0, 40)) + " is too large for a number";
            return false;
        }
        v = 0.0;
    } else if (ec != std::errc() || p != s.data() + s.size() || s.empty() ||
               !(s[0] == '.' || (s[0] >= '0' && s[0] <= '9'))) {
        // from_chars also takes "inf" and "nan"; X3D does not
        problem = "expected a number, found '" + std::string(tok.substr(0, 40)) + "'";
        return false;
    }
    out = negative ? -v : v;
    return true;
}

} // namespace

bool parseXmlAttributeValue(std::string_view text, FieldType type, FieldValue& out,
                            const StringOrigin& origin, std::string_view fileText,
                            std::string& problem) {
    out = {};
    out.type = type;
    const FieldType single = singleOf(type);
    if (type == FieldType::Unknown) {
        out.strings.emplace_back(text);
        out.stringOrigins.push_back(origin);
        return true;
    }
    if (single == FieldType::SFNode) {
        std::size_t i = 0;
        while (i < text.size() && isSep(text[i]))
            ++i;
        if (text.substr(i).starts_with("NULL") || text.substr(i).starts_with("null") ||
            i == text.size())
            return true;
        problem = "nodes are written as child elements, not in an attribute";
        return false;
    }
    if (type == FieldType::SFString) {
        out.strings.emplace_back(text);
        out.stringOrigins.push_back(origin);
        return true;
    }
    if (type == FieldType::MFString) {
        std::size_t i = 0;
        while (i < text.size() && isSep(text[i]))
            ++i;
        if (i < text.size() && text[i] != '"') {
            // One unquoted string: what people write for url and definition.
            std::size_t end = text.size();
            while (end > i && isSep(text[end - 1]))
                --end;
            out.strings.emplace_back(text.substr(i, end - i));
            StringOrigin o = origin;
            o.offset = origin.file >= 0 ? fileOffsetOf(fileText, origin, i) : 0;
            out.stringOrigins.push_back(o);
            return true;
        }
        while (i < text.size()) {
            if (text[i] != '"') {
                problem = "MFString items must each be in double quotes";
                return false;
            }
            const std::size_t contentStart = ++i;
            std::string item;
            while (i < text.size() && text[i] != '"') {
                if (text[i] == '\\' && i + 1 < text.size()) ++i;
                item += text[i++];
            }
            if (i >= text.size()) {
                problem = "a string in this MFString is never closed with '\"'";
                return false;
            }
            ++i;
            out.strings.push_back(std::move(item));
            StringOrigin o = origin;
            o.escapes = StringEscapes::XmlAttributeQuoted;
            o.offset = origin.file >= 0 ? fileOffsetOf(fileText, origin, contentStart) : 0;
            out.stringOrigins.push_back(o);
            while (i < text.size() && isSep(text[i]))
                ++i;
        }
        return true;
    }
    // numbers
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && isSep(text[i]))
            ++i;
        if (i >= text.size()) break;
        std::size_t j = i;
        while (j < text.size() && !isSep(text[j]))
            ++j;
        double v = 0;
        if (!parseNumber(text.substr(i, j - i), single, v, problem)) return false;
        out.numbers.push_back(v);
        i = j;
    }
    const int per = componentsPerElement(single);
    if (single == FieldType::SFImage) {
        // width height components pixels...; checked by count
        std::size_t k = 0;
        while (k < out.numbers.size()) {
            if (k + 3 > out.numbers.size()) {
                problem = "an SFImage needs width, height and components";
                return false;
            }
            const double pixels = out.numbers[k] * out.numbers[k + 1];
            if (pixels < 0 || k + 3 + pixels > out.numbers.size()) {
                problem = "the image declares more pixels than it has";
                return false;
            }
            k += 3 + static_cast<std::size_t>(pixels);
            if (!isMultiple(type) && k != out.numbers.size()) {
                problem = "the image has more pixels than it declares";
                return false;
            }
        }
        return true;
    }
    if (per > 0) {
        const std::size_t n = out.numbers.size();
        if (!isMultiple(type) && n != static_cast<std::size_t>(per)) {
            problem = std::string(fieldTypeName(type)) + " needs " + std::to_string(per) +
                      (per == 1 ? " value" : " values") + ", found " + std::to_string(n);
            return false;
        }
        if (isMultiple(type) && n % static_cast<std::size_t>(per) != 0) {
            problem = std::string(fieldTypeName(type)) + " needs values in groups of " +
                      std::to_string(per) + ", found " + std::to_string(n);
            return false;
        }
    }
    return true;
}

} // namespace fl::scene
