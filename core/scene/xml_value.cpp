// Field values written as X3D XML attribute text: numbers separated by white
// space or commas, true/false, SFString as is, MFString as "quoted" "items".
#include "xml_reader.h"

#include "number_text.h"
#include "source_map.h"

#include <charconv>
#include <limits>

namespace fl::scene {
namespace {

bool isSep(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',';
}

} // namespace

std::string_view trimmedUnknownValue(std::string_view text) {
    auto separator = [](char c) { return isSep(c) || c == ','; };
    while (!text.empty() && separator(text.back()))
        text.remove_suffix(1);
    while (!text.empty() && separator(text.front()))
        text.remove_prefix(1);
    return text;
}

bool parseXmlAttributeValue(std::string_view text, FieldType type, FieldValue& out,
                            const StringOrigin& origin, std::string_view fileText,
                            std::string& problem) {
    out = {};
    out.type = type;
    const FieldType single = singleOf(type);
    if (type == FieldType::Unknown) {
        out.strings.emplace_back(trimmedUnknownValue(text));
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
        if (!parseNumberText(text.substr(i, j - i), single, v, problem)) return false;
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
