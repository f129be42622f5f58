#include "json_fields.h"

#include "member_name.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonParseError>
#include <QJsonValue>

#include <cmath>

namespace fl::classroom {

bool JsonFields::has(const char* field) const {
    return object_.contains(QLatin1String(field));
}

void JsonFields::fail(ErrorCode code, std::string message) {
    if (!failure_) failure_ = ProtocolError{code, std::move(message)};
}

std::string JsonFields::text(const char* field, TextRule rule) {
    const QJsonValue v = object_.value(QLatin1String(field));
    if (v.isUndefined()) {
        if (rule.required) fail(ErrorCode::Malformed, where_ + " needs a \"" + field + "\" string");
        return {};
    }
    if (!v.isString()) {
        fail(ErrorCode::Malformed, where_ + ": \"" + field + "\" must be a string");
        return {};
    }
    std::string utf8 = v.toString().toStdString();
    if (rule.maxChars != std::numeric_limits<std::size_t>::max() &&
        characterCount(utf8) > rule.maxChars) { // characters, not UTF-16 units
        fail(rule.tooLong, where_ + ": \"" + field + "\" is longer than " +
                               std::to_string(rule.maxChars) + " characters");
        return {};
    }
    if (rule.clean && !isCleanText(utf8, rule.lineBreaks)) {
        fail(ErrorCode::Malformed, where_ + ": \"" + field + "\" holds control characters");
        return {};
    }
    return utf8;
}

std::optional<std::int64_t> JsonFields::count(const char* field, bool required) {
    const QJsonValue v = object_.value(QLatin1String(field));
    if (v.isUndefined()) {
        if (required) fail(ErrorCode::Malformed, where_ + " needs a \"" + field + "\" number");
        return std::nullopt;
    }
    // JSON numbers are doubles: whole, non-negative, and exact (below 2^53).
    const double d = v.isDouble() ? v.toDouble() : -1;
    if (!(d >= 0) || d != std::floor(d) || d > static_cast<double>(kMaxExactInteger)) {
        fail(ErrorCode::Malformed, where_ + ": \"" + field + "\" must be a whole number >= 0");
        return std::nullopt;
    }
    return static_cast<std::int64_t>(d);
}

bool JsonFields::boolean(const char* field, bool fallback) {
    const QJsonValue v = object_.value(QLatin1String(field));
    if (v.isUndefined()) return fallback;
    if (!v.isBool()) {
        fail(ErrorCode::Malformed, where_ + ": \"" + field + "\" must be true or false");
        return fallback;
    }
    return v.toBool();
}

std::optional<JsonFields> JsonFields::object(const char* field) {
    const QJsonValue v = object_.value(QLatin1String(field));
    if (v.isUndefined() || v.isNull()) return std::nullopt;
    if (!v.isObject()) {
        fail(ErrorCode::Malformed, where_ + ": \"" + field + "\" must be an object or null");
        return std::nullopt;
    }
    return JsonFields(v.toObject(), where_ + "." + field, failure_);
}

std::vector<JsonFields> JsonFields::objects(const char* field, bool required,
                                            std::size_t maxItems) {
    std::vector<JsonFields> out;
    const QJsonValue v = object_.value(QLatin1String(field));
    if (v.isUndefined()) {
        if (required) fail(ErrorCode::Malformed, where_ + " needs a \"" + field + "\" list");
        return out;
    }
    if (!v.isArray()) {
        fail(ErrorCode::Malformed, where_ + ": \"" + field + "\" must be a list");
        return out;
    }
    const QJsonArray list = v.toArray();
    if (static_cast<std::size_t>(list.size()) > maxItems) {
        fail(ErrorCode::TooLarge,
             where_ + ": \"" + field + "\" has more than " + std::to_string(maxItems) + " entries");
        return out;
    }
    for (qsizetype i = 0; i < list.size(); ++i) {
        const std::string at = where_ + "." + field + "[" + std::to_string(i) + "]";
        if (!list[i].isObject()) {
            fail(ErrorCode::Malformed, at + " must be an object");
            return {};
        }
        out.emplace_back(list[i].toObject(), at, failure_);
    }
    return out;
}

std::variant<TypedObject, ProtocolError> readTypedObject(std::string_view frame) {
    QJsonParseError error{};
    const QJsonDocument doc = QJsonDocument::fromJson(
        QByteArray::fromRawData(frame.data(), static_cast<qsizetype>(frame.size())), &error);
    if (error.error != QJsonParseError::NoError)
        return ProtocolError{ErrorCode::Malformed, "not JSON at byte " +
                                                       std::to_string(error.offset) + ": " +
                                                       error.errorString().toStdString()};
    if (!doc.isObject())
        return ProtocolError{ErrorCode::Malformed, "a message is a JSON object with a \"type\""};
    QJsonObject object = doc.object();
    const QJsonValue typeValue = object.value(QLatin1String("type"));
    if (!typeValue.isString())
        return ProtocolError{ErrorCode::Malformed, "a message needs a \"type\" string"};
    const std::string typeName = typeValue.toString().left(64).toStdString();
    const auto type = messageTypeNamed(typeName);
    if (!type) {
        std::string shown;
        for (char c : typeName)
            shown += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
        return ProtocolError{ErrorCode::UnknownType, "unknown message type '" + shown + "'"};
    }
    return TypedObject{*type, std::move(object)};
}

} // namespace fl::classroom
