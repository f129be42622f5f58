// The message parser: every client type, and what hostile or mistaken
// frames get (a ProtocolError naming the field, never a crash).
#include "classroom/protocol.h"

#include <gtest/gtest.h>

#include <string>

namespace fl::classroom {
namespace {

ClientMessage parsed(const std::string& frame) {
    auto result = parseClientMessage(frame);
    if (auto* e = std::get_if<ProtocolError>(&result)) {
        ADD_FAILURE() << frame << ": " << e->message;
        return {};
    }
    return std::get<ClientMessage>(result);
}

ProtocolError failure(const std::string& frame, const ClassroomLimits& limits = {}) {
    auto result = parseClientMessage(frame, limits);
    if (auto* e = std::get_if<ProtocolError>(&result)) return *e;
    ADD_FAILURE() << frame << " was accepted";
    return {};
}

TEST(ClassroomProtocol, JoinWithEveryField) {
    const ClientMessage m = parsed(
        R"({"type":"join","class":"MATH1","name":"Ana","role":"instructor","key":"k","resume":"abc","since":7})");
    ASSERT_EQ(m.type, MessageType::Join);
    const auto& j = std::get<JoinMessage>(m.body);
    EXPECT_EQ(j.classCode, "MATH1");
    EXPECT_EQ(j.name, "Ana");
    EXPECT_EQ(j.role, Role::Instructor);
    EXPECT_EQ(j.key, "k");
    EXPECT_EQ(j.resume, "abc");
    EXPECT_EQ(j.since, 7);
}

TEST(ClassroomProtocol, JoinDefaultsToStudent) {
    const auto j = std::get<JoinMessage>(parsed(R"({"type":"join","class":"C","name":"Bo"})").body);
    EXPECT_EQ(j.role, Role::Student);
    EXPECT_FALSE(j.since.has_value());
}

TEST(ClassroomProtocol, EveryClientType) {
    EXPECT_EQ(std::get<EditMessage>(parsed(R"({"type":"edit","version":3,"scene":"<X3D/>"})").body)
                  .version,
              3);
    EXPECT_EQ(parsed(R"({"type":"release"})").type, MessageType::Release);
    EXPECT_EQ(std::get<ChatMessage>(parsed(R"({"type":"chat","text":"hi"})").body).text, "hi");
    EXPECT_EQ(parsed(R"({"type":"heartbeat"})").type, MessageType::Heartbeat);
    EXPECT_EQ(std::get<HistoryMessage>(parsed(R"({"type":"history","version":2})").body).version,
              2);
    EXPECT_EQ(parsed(R"({"type":"take-lock"})").type, MessageType::TakeLock);
    EXPECT_EQ(parsed(R"({"type":"break-lock"})").type, MessageType::BreakLock);
    EXPECT_FALSE(
        std::get<FreezeMessage>(parsed(R"({"type":"freeze","frozen":false})").body).frozen);
    EXPECT_EQ(std::get<PushMessage>(parsed(R"({"type":"push","scene":"s"})").body).scene, "s");
    EXPECT_EQ(std::get<SnapshotMessage>(parsed(R"({"type":"snapshot","label":"end"})").body).label,
              "end");
    EXPECT_TRUE(std::get<AnonymiseMessage>(parsed(R"({"type":"anonymise"})").body).anonymous);
}

TEST(ClassroomProtocol, NamesRoundTrip) {
    for (auto t : {MessageType::Join, MessageType::Welcome, MessageType::Refused,
                   MessageType::TakeLock, MessageType::Version})
        EXPECT_EQ(messageTypeNamed(nameOf(t)), t);
    for (auto r : {RefusalReason::Locked, RefusalReason::Stale, RefusalReason::Invalid,
                   RefusalReason::ReadOnly, RefusalReason::Rate, RefusalReason::TooLarge})
        EXPECT_EQ(refusalReasonNamed(nameOf(r)), r);
    EXPECT_EQ(nameOf(RefusalReason::ReadOnly), "read-only");
    EXPECT_EQ(nameOf(RefusalReason::TooLarge), "too-large");
    EXPECT_EQ(errorCodeNamed(nameOf(ErrorCode::WrongClass)), ErrorCode::WrongClass);
    EXPECT_EQ(roleNamed("observer"), Role::Observer);
}

TEST(ClassroomProtocol, MalformedFramesSayWhy) {
    EXPECT_EQ(failure("not json").code, ErrorCode::Malformed);
    EXPECT_EQ(failure("[1,2]").code, ErrorCode::Malformed);
    EXPECT_EQ(failure("{}").code, ErrorCode::Malformed);
    EXPECT_EQ(failure(R"({"type":7})").code, ErrorCode::Malformed);
    EXPECT_EQ(failure(R"({"type":"dance"})").code, ErrorCode::UnknownType);
    EXPECT_EQ(failure(R"({"type":"welcome"})").code, ErrorCode::UnknownType);
    const ProtocolError noVersion = failure(R"({"type":"edit","scene":"x"})");
    EXPECT_NE(noVersion.message.find("version"), std::string::npos);
    EXPECT_EQ(failure(R"({"type":"edit","version":-1,"scene":"x"})").code, ErrorCode::Malformed);
    EXPECT_EQ(failure(R"({"type":"edit","version":1.5,"scene":"x"})").code, ErrorCode::Malformed);
    EXPECT_EQ(failure(R"({"type":"edit","version":"1","scene":"x"})").code, ErrorCode::Malformed);
    EXPECT_EQ(failure(R"({"type":"edit","version":1,"scene":5})").code, ErrorCode::Malformed);
    EXPECT_EQ(failure(R"({"type":"join","class":"C","name":"A","role":"king"})").code,
              ErrorCode::Malformed);
    EXPECT_EQ(failure(R"({"type":"freeze","frozen":"yes"})").code, ErrorCode::Malformed);
}

TEST(ClassroomProtocol, NamesAreBoundedAndClean) {
    EXPECT_EQ(failure(R"({"type":"join","class":"C","name":")" + std::string(41, 'a') + "\"}").code,
              ErrorCode::BadName);
    EXPECT_EQ(failure(R"({"type":"join","class":"C","name":"a\u0007b"})").code,
              ErrorCode::Malformed);
    EXPECT_EQ(failure(R"({"type":"join","class":"C","name":"a\nb"})").code, ErrorCode::Malformed);
    // Scene text may hold line breaks; names may not.
    EXPECT_EQ(
        std::get<EditMessage>(parsed(R"({"type":"edit","version":1,"scene":"a\nb"})").body).scene,
        "a\nb");
}

TEST(ClassroomProtocol, OversizedMessagesAreRefusedBeforeParsing) {
    ClassroomLimits limits;
    limits.maxMessageBytes = 100;
    EXPECT_EQ(failure(R"({"type":"chat","text":")" + std::string(200, 'x') + "\"}", limits).code,
              ErrorCode::TooLarge);
    // A chat text over its length is too large (issue 26 §6), not malformed.
    EXPECT_EQ(failure(R"({"type":"chat","text":")" + std::string(2001, 'x') + "\"}").code,
              ErrorCode::TooLarge);
}

TEST(ClassroomProtocol, AnEmptyRoleIsNoRole) {
    EXPECT_EQ(failure(R"({"type":"join","class":"C","name":"Ana","role":""})").code,
              ErrorCode::Malformed);
}

TEST(ClassroomProtocol, DeepNestingIsAnErrorNotACrash) {
    std::string deep(100000, '[');
    EXPECT_EQ(failure(deep).code, ErrorCode::Malformed);
}

TEST(ClassroomProtocol, CleanTextChecksUtf8) {
    EXPECT_TRUE(isCleanText("Zoë 名前", false));
    EXPECT_FALSE(isCleanText("\xc3", false));
    EXPECT_FALSE(isCleanText("\xff", false));
    EXPECT_FALSE(isCleanText("a\tb", false));
    EXPECT_TRUE(isCleanText("a\tb\n", true));
}

} // namespace
} // namespace fl::classroom
