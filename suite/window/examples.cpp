#include "examples.h"

#include "catalogue.h"

namespace fl::suite {

QString examplesFolder() {
    return QString::fromStdString((courseware::coursewareFolder() / "examples").string());
}

} // namespace fl::suite
