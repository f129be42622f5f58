#include "http_request.h"

#include <algorithm>
#include <cctype>

namespace fl::classroom {
namespace {

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
        s.remove_suffix(1);
    return s;
}

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// Percent-decoding ('+' as a space in a query); none for a broken escape or
// a control character after decoding.
std::optional<std::string> decode(std::string_view s, bool query) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        char c = s[i];
        if (c == '%') {
            if (i + 2 >= s.size()) return std::nullopt;
            const int hi = hexDigit(s[i + 1]), lo = hexDigit(s[i + 2]);
            if (hi < 0 || lo < 0) return std::nullopt;
            c = char(hi * 16 + lo);
            i += 2;
        } else if (query && c == '+') {
            c = ' ';
        }
        const unsigned char u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7f) return std::nullopt;
        out += c;
    }
    return out;
}

bool hasToken(std::string_view list, std::string_view token) {
    const std::string l = lower(list);
    std::size_t start = 0;
    while (start <= l.size()) {
        const std::size_t comma = l.find(',', start);
        const std::string_view item = trim(std::string_view(l).substr(
            start, comma == std::string::npos ? std::string::npos : comma - start));
        if (item == token || item.starts_with(std::string(token) + ";")) return true;
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return false;
}

} // namespace

std::string HttpRequest::header(std::string_view name) const {
    for (const auto& [n, v] : headers)
        if (n == name) return v;
    return {};
}

std::optional<std::string> HttpRequest::queryValue(std::string_view name) const {
    for (const auto& [n, v] : query)
        if (n == name) return v;
    return std::nullopt;
}

bool HttpRequest::wantsWebSocket() const {
    return lower(header("upgrade")) == "websocket" && hasToken(header("connection"), "upgrade");
}

bool HttpRequest::acceptsGzip() const {
    return hasToken(header("accept-encoding"), "gzip");
}

HeadStatus findHeadEnd(std::string_view bytes, std::size_t& length) {
    const std::size_t end = bytes.substr(0, kMaxRequestHeadBytes).find("\r\n\r\n");
    if (end != std::string_view::npos) {
        length = end + 4;
        return HeadStatus::Complete;
    }
    return bytes.size() >= kMaxRequestHeadBytes ? HeadStatus::Invalid : HeadStatus::Incomplete;
}

std::optional<HttpRequest> parseRequestHead(std::string_view head, std::string& why) {
    if (head.size() > kMaxRequestHeadBytes) {
        why = "the request head is longer than 8 KiB";
        return std::nullopt;
    }
    HttpRequest r;
    std::size_t lineEnd = head.find("\r\n");
    if (lineEnd == std::string_view::npos) {
        why = "no request line";
        return std::nullopt;
    }
    const std::string_view line = head.substr(0, lineEnd);
    const std::size_t a = line.find(' ');
    const std::size_t b = a == std::string_view::npos ? a : line.find(' ', a + 1);
    if (b == std::string_view::npos || line.find(' ', b + 1) != std::string_view::npos) {
        why = "the request line is not METHOD TARGET VERSION";
        return std::nullopt;
    }
    r.method = std::string(line.substr(0, a));
    const std::string_view target = line.substr(a + 1, b - a - 1);
    const std::string_view version = line.substr(b + 1);
    if (r.method.empty() || !std::all_of(r.method.begin(), r.method.end(),
                                         [](char c) { return c >= 'A' && c <= 'Z'; })) {
        why = "the method is not a word in capitals";
        return std::nullopt;
    }
    if (version != "HTTP/1.1" && version != "HTTP/1.0") {
        why = "not HTTP/1.0 or HTTP/1.1";
        return std::nullopt;
    }
    if (target.empty() || target.front() != '/') {
        why = "the target is not an absolute path";
        return std::nullopt;
    }
    const std::size_t q = target.find('?');
    const auto path = decode(target.substr(0, q), false);
    if (!path) {
        why = "the path has a broken escape or a control character";
        return std::nullopt;
    }
    // No segment may climb: the page serves names, never files, but a
    // request that tries is refused as what it is.
    for (std::size_t s = 0; s <= path->size();) {
        const std::size_t next = path->find('/', s);
        const std::string_view segment = std::string_view(*path).substr(
            s, next == std::string::npos ? std::string::npos : next - s);
        if (segment == ".." || segment == ".") {
            why = "the path climbs with . or ..";
            return std::nullopt;
        }
        if (next == std::string::npos) break;
        s = next + 1;
    }
    r.path = *path;
    if (q != std::string_view::npos) {
        std::string_view rest = target.substr(q + 1);
        while (!rest.empty()) {
            const std::size_t amp = rest.find('&');
            const std::string_view pair = rest.substr(0, amp);
            const std::size_t eq = pair.find('=');
            const auto name = decode(pair.substr(0, eq), true);
            const auto value = eq == std::string_view::npos ? std::optional<std::string>("")
                                                            : decode(pair.substr(eq + 1), true);
            if (!name || !value) {
                why = "the query has a broken escape or a control character";
                return std::nullopt;
            }
            if (!name->empty()) r.query.emplace_back(*name, *value);
            if (amp == std::string_view::npos) break;
            rest.remove_prefix(amp + 1);
        }
    }
    std::string_view rest = head.substr(lineEnd + 2);
    while (!rest.empty()) {
        lineEnd = rest.find("\r\n");
        const std::string_view h = rest.substr(0, lineEnd);
        if (lineEnd == std::string_view::npos)
            rest = {};
        else
            rest.remove_prefix(lineEnd + 2);
        if (h.empty()) break;
        const std::size_t colon = h.find(':');
        if (colon == std::string_view::npos || colon == 0) {
            why = "a header line has no name and colon";
            return std::nullopt;
        }
        const std::string_view value = trim(h.substr(colon + 1));
        if (std::any_of(value.begin(), value.end(), [](char c) {
                const auto u = static_cast<unsigned char>(c);
                return (u < 0x20 && c != '\t') || u == 0x7f;
            })) {
            why = "a header has a control character";
            return std::nullopt;
        }
        r.headers.emplace_back(lower(trim(h.substr(0, colon))), std::string(value));
    }
    return r;
}

} // namespace fl::classroom
