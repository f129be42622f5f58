// libFuzzer target: the request head a browser (or anyone) sends the class
// server's port (classroom/http_request.h). No crash, no hang; a parsed
// head's path begins with '/', never climbs (no "." or ".." segment) and
// holds no control character; findHeadEnd never reports a head longer than
// its bound.
#include "classroom/http_request.h"

#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace fl::classroom;
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    std::size_t length = 0;
    const HeadStatus status = findHeadEnd(input, length);
    if (status == HeadStatus::Complete && length > kMaxRequestHeadBytes) std::abort();
    std::string why;
    const auto request = parseRequestHead(input, why);
    if (!request) return 0;
    const std::string& p = request->path;
    if (p.empty() || p.front() != '/') std::abort();
    for (const char c : p)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) std::abort();
    if (p.find("/../") != std::string::npos || p.ends_with("/..") ||
        p.find("/./") != std::string::npos)
        std::abort();
    (void)request->wantsWebSocket();
    (void)request->acceptsGzip();
    return 0;
}
