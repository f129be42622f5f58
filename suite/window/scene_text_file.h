#pragma once
// A scene file as the editor holds it: its text (a gzip-compressed scene,
// .x3dz or .wrl.gz, as the text it holds), at most 64 MiB, read and written
// whole; and the text File → New starts from.
#include <QString>

#include <optional>

namespace fl::suite {

// The text, or none with `problem` saying why in a sentence.
std::optional<QString> readSceneText(const QString& path, QString& problem);
// Written whole or not at all (a temporary file renamed); false with `problem`.
bool writeSceneText(const QString& path, const QString& text, QString& problem);

// A sphere coloured by a parametric FMaterial, seen from the front.
QString newSceneText();

} // namespace fl::suite
