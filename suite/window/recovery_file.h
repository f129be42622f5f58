#pragma once
// Unsaved text kept on disk (every couple of seconds after a change), so a
// crash or a power cut never loses a student's work; offered back at the
// next start.
#include <QString>

#include <optional>

namespace fl::suite {

struct KeptText {
    QString text;
    QString of; // the file it was the unsaved text of ("" for none)
};

void keepUnsavedText(const QString& text, const QString& of);
std::optional<KeptText> keptText();
void forgetKeptText();

} // namespace fl::suite
