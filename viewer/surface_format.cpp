#include "surface_format.h"

#include <QSurfaceFormat>

namespace fl::viewer {

void useViewerSurfaceFormat(int samples) {
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    if (samples > 0) format.setSamples(samples);
    QSurfaceFormat::setDefaultFormat(format);
}

} // namespace fl::viewer
