#pragma once
// Reading one JSON object of the protocol, field by field, with every check
// in one place: a field of the wrong type, a number that is not a whole
// number a double holds exactly, a string too long or holding control
// characters. The first failure is kept (with the message's type and the
// path to the field) and every later read returns a harmless default, so a
// decoder reads straight through and asks once at the end. Both directions
// use it: the server's parser of client messages and the client's parser
// of server messages — no number is cast anywhere else.
#include "protocol.h"

#include <QJsonObject>
#include <QString>

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace fl::classroom {

// UTF-8 text as the QString a QJsonObject holds (both directions write with it).
inline QString qText(std::string_view utf8) {
    return QString::fromUtf8(utf8.data(), static_cast<qsizetype>(utf8.size()));
}

class JsonFields {
  public:
    // The largest whole number a JSON number (a double) holds exactly.
    static constexpr std::int64_t kMaxExactInteger = 9007199254740991; // 2^53 - 1

    JsonFields(QJsonObject object, std::string where, std::optional<ProtocolError>& failure)
        : object_(std::move(object)), where_(std::move(where)), failure_(failure) {}

    bool has(const char* field) const;
    void fail(ErrorCode code, std::string message);
    bool failed() const { return failure_.has_value(); }

    // A string; checked for length (characters, not bytes) and, when `clean`,
    // for control characters (line breaks only where allowed).
    struct TextRule {
        std::size_t maxChars = std::numeric_limits<std::size_t>::max();
        bool required = true;
        bool clean = true;
        bool lineBreaks = true;
        ErrorCode tooLong = ErrorCode::Malformed;
    };
    std::string text(const char* field, TextRule rule);
    std::string text(const char* field) { return text(field, TextRule{}); }

    // A whole number in [0, 2^53): nullopt when absent (and not required) or wrong.
    std::optional<std::int64_t> count(const char* field, bool required);
    std::int64_t count(const char* field) { return count(field, true).value_or(0); }
    bool boolean(const char* field, bool fallback);

    // A kind by its wire name (nameOf/…Named pairs of protocol.h).
    template <class Kind, class Named>
    std::optional<Kind> kind(const char* field, Named named, bool required) {
        if (!required && !has(field)) return std::nullopt;
        const std::string name = text(field, TextRule{64, required, true, false});
        if (failed()) return std::nullopt;
        if (auto known = named(name)) return known;
        fail(ErrorCode::Malformed, where_ + ": \"" + field + "\" has no value '" + name + "'");
        return std::nullopt;
    }

    // A nested object: nullopt when absent or null (`holder: null`).
    std::optional<JsonFields> object(const char* field);
    // An array of objects, each read on its own (at most maxItems).
    std::vector<JsonFields> objects(const char* field, bool required,
                                    std::size_t maxItems = 100'000);

  private:
    const QJsonObject object_;
    const std::string where_;
    std::optional<ProtocolError>& failure_;
};

// A frame's outer shape, the same both ways: a JSON object whose "type"
// names a message. An unknown type is ErrorCode::UnknownType (its name shown
// with control characters replaced).
struct TypedObject {
    MessageType type = MessageType::Heartbeat;
    QJsonObject object;
};
std::variant<TypedObject, ProtocolError> readTypedObject(std::string_view frame);

} // namespace fl::classroom
