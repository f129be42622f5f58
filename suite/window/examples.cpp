#include "examples.h"

#include "courseware/catalogue.h"

namespace fl::suite {

QString examplesFolder() {
    return QString::fromStdString((courseware::coursewareFolder() / "examples").string());
}

} // namespace fl::suite
