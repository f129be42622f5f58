#include "member_name.h"

#include <QChar>
#include <QRegularExpression>
#include <QString>

namespace fl::classroom {

namespace {

QString fromUtf8(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

// Controls that reorder the text around them (an override reverses the rest
// of a line: a name can make "Ana holds the lock" read otherwise).
bool isDirectionControl(char32_t c) {
    return (c >= 0x202A && c <= 0x202E) || (c >= 0x2066 && c <= 0x2069) || c == 0x200E ||
           c == 0x200F || c == 0x061C;
}

bool isControl(char32_t c) {
    return QChar::category(c) == QChar::Other_Control || c == 0x2028 || c == 0x2029;
}

// Drawn as something a reader can see (not a space, a joiner, a format
// character or a combining mark alone).
bool isVisible(char32_t c) {
    switch (QChar::category(c)) {
    case QChar::Separator_Space:
    case QChar::Separator_Line:
    case QChar::Separator_Paragraph:
    case QChar::Other_Control:
    case QChar::Other_Format:
    case QChar::Mark_NonSpacing:
    case QChar::Mark_Enclosing:
    case QChar::Mark_SpacingCombining:
        return false;
    default:
        return c != 0x3164 && c != 0x115F && c != 0x1160 && c != 0xFFA0; // Hangul fillers
    }
}

bool isSpace(char32_t c) {
    return QChar::isSpace(c) || QChar::category(c) == QChar::Separator_Space;
}

} // namespace

std::size_t characterCount(std::string_view utf8) {
    std::size_t n = 0;
    for (char c : utf8)
        n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    return n;
}

std::string memberNameKey(std::string_view name) {
    return fromUtf8(name).normalized(QString::NormalizationForm_C).toCaseFolded().toStdString();
}

std::optional<std::string> memberNameProblem(std::string_view name, std::size_t maxChars) {
    if (name.empty()) return "a name is needed";
    if (characterCount(name) > maxChars)
        return "a name has at most " + std::to_string(maxChars) + " characters";
    const QList<uint> chars = fromUtf8(name).toUcs4();
    bool visible = false;
    for (const uint c : chars) {
        if (isControl(c)) return "a name may not hold control characters or line breaks";
        if (isDirectionControl(c))
            return "a name may not hold characters that change the direction of the text "
                   "around it (U+202A-U+202E, U+2066-U+2069, U+200E, U+200F, U+061C)";
        visible = visible || isVisible(c);
    }
    if (!visible) return "a name needs at least one visible character";
    if (isSpace(chars.front()) || isSpace(chars.back()))
        return "a name may not start or end with a space";
    // The names the class itself gives: roles, the server, the anonymous
    // aliases. A member called so would pass for them.
    const QString key = QString::fromStdString(memberNameKey(name)).simplified();
    static const QRegularExpression reserved(
        QStringLiteral("^(instructor|student|observer|server|everyone|learner( \\d+)?)$"));
    if (reserved.match(key).hasMatch())
        return "'" + std::string(name) + "' is what the class calls a role or an anonymous member";
    return std::nullopt;
}

} // namespace fl::classroom
