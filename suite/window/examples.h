#pragma once
// The examples folder, as the window names it (Qt strings): the courseware
// catalogue finds it and reads the examples' titles (courseware/catalogue.h).
#include <QString>

namespace fl::suite {

QString examplesFolder();

} // namespace fl::suite
