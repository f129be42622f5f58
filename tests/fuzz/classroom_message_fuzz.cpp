// libFuzzer target: classroom messages (outside input both ways). The input
// is one or more frames separated by the byte 0x1E; each is parsed as a
// client's frame and as a server's (the client's decoder), then handled by
// a class an instructor has joined, so the parser, the scene checks and the
// chat commands all see it. No crash, no hang; every answer the server
// gives decodes with the client's own decoder; the version never goes back.
#include "classroom/class_session.h"
#include "classroom/protocol.h"
#include "classroom/server_message.h"

#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

void checkAnswers(const std::vector<fl::classroom::Delivery>& out) {
    for (const auto& d : out) {
        const auto parsed = fl::classroom::parseServerMessage(d.frame.toStdString());
        if (!std::holds_alternative<fl::classroom::ServerMessage>(parsed)) std::abort();
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace fl::classroom;
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    ManualClock clock;
    ClassConfig config;
    config.classCode = "C";
    config.instructorKey = "k";
    config.initialScene = "#X3D V3.3 utf8\nPROFILE Immersive\n"
                          "DEF CLASS FShape { geometry FGeometry { definition \"sphere(1)\" } }\n";
    ClassSession session(config, clock, nullptr);
    const ConnectionId teacher = *session.connect("a");
    checkAnswers(session.receive(
        teacher, R"({"type":"join","class":"C","name":"T","role":"instructor","key":"k"})"));
    const ConnectionId student = *session.connect("b");
    checkAnswers(session.receive(student, R"({"type":"join","class":"C","name":"S"})"));
    std::size_t start = 0;
    std::int64_t version = session.version();
    int frames = 0;
    while (start <= input.size() && frames++ < 16) {
        const std::size_t end = std::min(input.find('\x1e', start), input.size());
        const std::string_view frame = input.substr(start, end - start);
        (void)parseClientMessage(frame);
        (void)parseServerMessage(frame);
        checkAnswers(session.receive(frames % 2 ? student : teacher, frame));
        clock.advance(250);
        checkAnswers(session.tick());
        if (session.version() < version) std::abort();
        version = session.version();
        start = end + 1;
    }
    return 0;
}
