// The protocol's two encoders and decoders: writing a message and reading it
// back is the identity for every message type, both ways, with hostile text;
// and every number the wire holds is range-checked in one place, so a frame
// with a negative, fractional, huge or mistyped number is refused naming the
// field instead of being cast.
#include "classroom/protocol.h"
#include "classroom/server_message.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

namespace fl::classroom {
namespace {

// Text another member could send: markup, quotes, escapes, non-ASCII.
const std::vector<std::string> kHostileTexts = {
    "",
    "Ana",
    "<b>bold</b> & \"quoted\" \\ back",
    "line one\nline two\ttab",
    "\xc3\xa9t\xc3\xa9 \xe2\x80\xae reversed \xf0\x9f\x98\x80",
    std::string(3000, 'x'),
};

ServerMessage roundTrip(const ServerMessage& m) {
    const std::string frame = encodeServerMessage(m);
    auto parsed = parseServerMessage(frame);
    if (auto* e = std::get_if<ProtocolError>(&parsed)) {
        ADD_FAILURE() << frame << ": " << e->message;
        return m;
    }
    return std::get<ServerMessage>(parsed);
}

ProtocolError refusal(const std::string& frame) {
    auto parsed = parseServerMessage(frame);
    if (auto* e = std::get_if<ProtocolError>(&parsed)) return *e;
    ADD_FAILURE() << frame << " was accepted";
    return {};
}

std::vector<ServerMessage> everyServerMessage(const std::string& text, std::int64_t n) {
    WelcomeMessage welcome;
    welcome.id = n;
    welcome.token = "9fe1";
    welcome.name = text;
    welcome.role = Role::Instructor;
    welcome.version = n;
    welcome.scene = text;
    welcome.frozen = true;
    welcome.resumed = true;
    welcome.members = {{1, text, Role::Student, true}, {n, "Bo", Role::Observer, false}};
    welcome.lock = LockHolderEntry{1, text};
    welcome.missed = std::vector<MissedVersion>{{n, text, EditKind::Undo}, {2, "", EditKind::Push}};
    welcome.chat = std::vector<EarlierChat>{{text, text, n}};
    welcome.limits = {1 << 20, 256 << 10, 5000, 16 << 10, 2000, 10000};
    WelcomeMessage bare = welcome; // no lock, no missed list, no chat
    bare.lock.reset();
    bare.missed.reset();
    bare.chat.reset();
    return {
        welcome,
        bare,
        ErrorMessage{ErrorCode::TooManyJoins, text},
        SceneMessage{n, text, n, EditKind::Command, text},
        SceneMessage{n, "server", std::nullopt, EditKind::Start, text},
        RefusedMessage{RefusalReason::Locked, text, n, "", LockHolderEntry{n, text}, {}},
        RefusedMessage{RefusalReason::Invalid,
                       text,
                       n,
                       "/add " + text,
                       std::nullopt,
                       {{4, 41, DiagnosticSeverity::Error, text, "sin"},
                        {0, 0, DiagnosticSeverity::Warning, "w", ""}}},
        ChatLineMessage{text, n, text},
        NoticeMessage{text},
        PresenceMessage{{{n, text, Role::Student, false}}},
        PresenceMessage{},
        LockMessage{LockHolderEntry{n, text}, 10000},
        LockMessage{},
        FrozenMessage{true},
        FrozenMessage{false},
        SavedMessage{n, 7, text},
        VersionMessage{n, text, EditKind::Edit, n / 3, text},
    };
}

TEST(ServerMessage, WriteThenReadIsTheIdentityForEveryType) {
    std::mt19937_64 random(42);
    std::uniform_int_distribution<std::int64_t> numbers(0, (std::int64_t(1) << 53) - 1);
    for (const std::string& text : kHostileTexts)
        for (std::int64_t n :
             {std::int64_t(0), std::int64_t(1), numbers(random), (std::int64_t(1) << 53) - 1})
            for (const ServerMessage& m : everyServerMessage(text, n)) {
                const ServerMessage back = roundTrip(m);
                EXPECT_EQ(typeOf(back), typeOf(m));
                EXPECT_TRUE(back == m) << encodeServerMessage(m);
            }
}

TEST(ServerMessage, TheWireFormatIsTheDocumentedOne) {
    // docs/classroom-protocol.md: tools outside this repository read these.
    EXPECT_EQ(encodeServerMessage(LockMessage{LockHolderEntry{3, "Ana"}, 10000}),
              R"({"expiresInMs":10000,"holder":{"id":3,"name":"Ana"},"type":"lock"})");
    EXPECT_EQ(encodeServerMessage(LockMessage{}), R"({"holder":null,"type":"lock"})");
    EXPECT_EQ(
        encodeServerMessage(SceneMessage{19, "Ana", 3, EditKind::Edit, "s"}),
        R"({"author":"Ana","authorId":3,"kind":"edit","scene":"s","type":"scene","version":19})");
    EXPECT_EQ(
        encodeServerMessage(RefusedMessage{RefusalReason::Locked,
                                           "Bo is editing the scene",
                                           19,
                                           "",
                                           LockHolderEntry{4, "Bo"},
                                           {}}),
        R"({"holder":"Bo","holderId":4,"message":"Bo is editing the scene","reason":"locked","type":"refused","version":19})");
}

TEST(ServerMessage, NumbersAreRangeCheckedNamingTheField) {
    for (const char* frame : {
             R"({"type":"scene","version":-1,"scene":"s"})",
             R"({"type":"scene","version":1.5,"scene":"s"})",
             R"({"type":"scene","version":9007199254740993,"scene":"s"})",
             R"({"type":"scene","version":1e300,"scene":"s"})",
             R"({"type":"scene","version":"7","scene":"s"})",
         }) {
        const ProtocolError e = refusal(frame);
        EXPECT_EQ(e.code, ErrorCode::Malformed) << frame;
        EXPECT_NE(e.message.find("\"version\""), std::string::npos) << e.message;
    }
    const ProtocolError nested =
        refusal(R"({"type":"presence","members":[{"id":1,"name":"a"},{"id":-2,"name":"b"}]})");
    EXPECT_NE(nested.message.find("presence.members[1]"), std::string::npos) << nested.message;
    const ProtocolError holder = refusal(R"({"type":"lock","holder":{"id":0.5,"name":"x"}})");
    EXPECT_NE(holder.message.find("lock.holder"), std::string::npos) << holder.message;
}

TEST(ServerMessage, WrongShapesAreRefusedNotGuessed) {
    EXPECT_EQ(refusal("not json").code, ErrorCode::Malformed);
    EXPECT_EQ(refusal("[1,2]").code, ErrorCode::Malformed);
    EXPECT_EQ(refusal(R"({"type":"scene"})").code, ErrorCode::Malformed); // no version
    EXPECT_EQ(refusal(R"({"type":"presence","members":[1,2]})").code, ErrorCode::Malformed);
    EXPECT_EQ(refusal(R"({"type":"presence","members":{}})").code, ErrorCode::Malformed);
    EXPECT_EQ(refusal(R"({"type":"lock","holder":"Ana"})").code, ErrorCode::Malformed);
    EXPECT_EQ(refusal(R"({"type":"refused","reason":"bored","message":"m","version":1})").code,
              ErrorCode::Malformed);
    EXPECT_EQ(refusal(R"({"type":"error","code":"teapot","message":"m"})").code,
              ErrorCode::Malformed);
    EXPECT_EQ(refusal(R"({"type":"frozen","frozen":"yes"})").code, ErrorCode::Malformed);
    // A newer server's message: unknown, to be passed over.
    EXPECT_EQ(refusal(R"({"type":"fireworks"})").code, ErrorCode::UnknownType);
    // A client's message is not the server's.
    EXPECT_EQ(refusal(R"({"type":"edit","version":1,"scene":"s"})").code, ErrorCode::UnknownType);
}

TEST(ClientMessage, WriteThenReadIsTheIdentityForEveryType) {
    for (const std::string& raw : kHostileTexts) {
        // What parseClientMessage accepts: names without line breaks, short enough.
        const std::string name = raw.substr(0, 30).find('\n') == std::string::npos
                                     ? raw.substr(0, 30)
                                     : std::string("Ana");
        const std::string safeName = name.find('\t') == std::string::npos ? name : "Ana";
        const std::vector<ClientMessage> messages = {
            {MessageType::Join, JoinMessage{"MATH1", safeName.empty() ? "A" : safeName,
                                            Role::Instructor, "key", "tok", 7}},
            {MessageType::Join, JoinMessage{"MATH1", "Bo", Role::Student, "", "", std::nullopt}},
            {MessageType::Edit, EditMessage{12, raw}},
            {MessageType::Chat, ChatMessage{raw.substr(0, 1000)}},
            {MessageType::Freeze, FreezeMessage{false}},
            {MessageType::Push, PushMessage{raw}},
            {MessageType::Snapshot, SnapshotMessage{safeName}},
            {MessageType::Anonymise, AnonymiseMessage{false}},
            {MessageType::History, HistoryMessage{(std::int64_t(1) << 53) - 1}},
            {MessageType::Release, std::monostate{}},
            {MessageType::Heartbeat, std::monostate{}},
            {MessageType::TakeLock, std::monostate{}},
            {MessageType::BreakLock, std::monostate{}},
        };
        for (const ClientMessage& m : messages) {
            const std::string frame = encodeClientMessage(m);
            auto parsed = parseClientMessage(frame);
            if (auto* e = std::get_if<ProtocolError>(&parsed)) {
                ADD_FAILURE() << frame << ": " << e->message;
                continue;
            }
            EXPECT_TRUE(std::get<ClientMessage>(parsed) == m) << frame;
        }
    }
}

} // namespace
} // namespace fl::classroom
