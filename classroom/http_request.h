#pragma once
// The head of an HTTP/1.1 request a browser sends the class server's web
// page (issue 32 §2), read from bytes a stranger sent: bounded, every part
// checked, nothing of it ever used as a file path (the page serves a fixed
// table of names). Also tells a WebSocket upgrade, which goes to the class.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fl::classroom {

inline constexpr std::size_t kMaxRequestHeadBytes = 8192;

struct HttpRequest {
    std::string method;                                       // "GET", "HEAD" ...
    std::string path;                                         // percent-decoded, begins with '/'
    std::vector<std::pair<std::string, std::string>> query;   // decoded name, value
    std::vector<std::pair<std::string, std::string>> headers; // names lower-cased

    // The first header of that (lower-case) name, or empty.
    std::string header(std::string_view name) const;
    std::optional<std::string> queryValue(std::string_view name) const;
    // `Upgrade: websocket` with `Connection: upgrade`.
    bool wantsWebSocket() const;
    bool acceptsGzip() const;
};

enum class HeadStatus { Incomplete, Complete, Invalid };

// Where the head ends ("\r\n\r\n"): Complete with its length, Incomplete
// while it may still come, Invalid past kMaxRequestHeadBytes.
HeadStatus findHeadEnd(std::string_view bytes, std::size_t& length);

// The head's request line and headers; none with `why` for anything that is
// not a well-formed HTTP/1.x request head (a path that is not absolute, that
// decodes to a NUL or control character or climbs with "..", a header line
// without a colon ...).
std::optional<HttpRequest> parseRequestHead(std::string_view head, std::string& why);

} // namespace fl::classroom
