#pragma once
// The example scenes that come with FunctionLab (courseware/examples): where
// they are, and each one's title and description from its own head.
#include <QList>
#include <QString>

namespace fl::suite {

struct Example {
    QString path;
    QString title;       // WorldInfo title, else the file name
    QString description; // the head's "description" meta, may be empty
};

// The examples folder: next to the executable once installed
// (../share/functionlab/examples), else the source tree's.
QString examplesFolder();
QList<Example> listExamples(const QString& folder = examplesFolder());

} // namespace fl::suite
