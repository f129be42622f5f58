#include "pde_data_url.h"

#include <array>
#include <cstdint>

namespace fl::pde {
namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

std::string base64(std::string_view bytes) {
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t n = std::uint32_t(std::uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) n |= std::uint32_t(std::uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) n |= std::uint8_t(bytes[i + 2]);
        out += kAlphabet[(n >> 18) & 63];
        out += kAlphabet[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? kAlphabet[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kAlphabet[n & 63] : '=';
    }
    return out;
}

// Strict base64: whitespace between groups allowed (a scene may wrap it),
// padding only at the end. Nullopt with the offending position otherwise.
std::optional<std::string> unbase64(std::string_view text, std::size_t& bad) {
    std::array<int, 256> value;
    value.fill(-1);
    for (int i = 0; i < 64; ++i)
        value[std::uint8_t(kAlphabet[i])] = i;
    std::string out;
    out.reserve(text.size() / 4 * 3);
    std::uint32_t n = 0;
    int have = 0, padding = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == ' ' || c == '\n' || c == '\r' || c == '\t') continue;
        if (c == '=') {
            ++padding;
            if (padding > 2) return bad = i, std::nullopt;
            continue;
        }
        const int v = value[std::uint8_t(c)];
        if (v < 0 || padding) return bad = i, std::nullopt;
        n = (n << 6) | std::uint32_t(v);
        if (++have == 4) {
            out += char((n >> 16) & 0xff);
            out += char((n >> 8) & 0xff);
            out += char(n & 0xff);
            n = 0;
            have = 0;
        }
    }
    if (have + padding != 0 && have + padding != 4) return bad = text.size(), std::nullopt;
    if (have == 2) out += char((n >> 4) & 0xff);
    if (have == 3) {
        out += char((n >> 10) & 0xff);
        out += char((n >> 2) & 0xff);
    }
    return out;
}

} // namespace

bool isDataUrl(std::string_view url) {
    return url.size() >= 5 && (url.substr(0, 5) == "data:" || url.substr(0, 5) == "DATA:");
}

std::string dataUrlOf(const Model& model, const EncodeOptions& options) {
    return "data:" + std::string(kPdeMediaType) + ";base64," + base64(encodeBinary(model, options));
}

ReadResult readDataUrl(std::string_view url, std::string_view name) {
    ReadResult r;
    const std::size_t comma = url.find(',');
    if (!isDataUrl(url) || comma == std::string_view::npos ||
        url.substr(0, comma).find(";base64") == std::string_view::npos) {
        r.error = std::string(name) +
                  ": a data url of a PDE model is data:" + std::string(kPdeMediaType) +
                  ";base64,... (functionlab pde fit --scene writes one)";
        return r;
    }
    const std::string_view text = url.substr(comma + 1);
    if (text.size() / 4 * 3 > kMaxFileBytes) {
        r.error = std::string(name) + ": more than " + std::to_string(kMaxFileBytes >> 20) +
                  " MiB in a data url";
        return r;
    }
    std::size_t bad = 0;
    const auto bytes = unbase64(text, bad);
    if (!bytes) {
        r.error = std::string(name) + ": character " + std::to_string(comma + 2 + bad) +
                  " of the data url is not base64";
        return r;
    }
    return readModel(*bytes, name);
}

} // namespace fl::pde
