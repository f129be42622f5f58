#include "texture_image.h"

#include <cstring>

namespace fl::viewer {
namespace {

bool anyAlphaBelowOne(const QImage& rgba) {
    for (int y = 0; y < rgba.height(); ++y) {
        const uchar* row = rgba.constScanLine(y);
        for (int x = 0; x < rgba.width(); ++x)
            if (row[4 * x + 3] < 255) return true;
    }
    return false;
}

} // namespace

std::optional<TextureImage> TextureImages::get(const mesh::SurfaceTexture& t) {
    if (t.file.empty()) {
        if (t.width <= 0 || t.height <= 0 ||
            t.rgba.size() != std::size_t(t.width) * std::size_t(t.height) * 4)
            return std::nullopt;
        TextureImage out;
        out.components = t.components;
        out.image = QImage(t.width, t.height, QImage::Format_RGBA8888);
        for (int row = 0; row < t.height; ++row) // SFImage rows run upwards
            std::memcpy(out.image.scanLine(t.height - 1 - row),
                        t.rgba.data() + std::size_t(row) * std::size_t(t.width) * 4,
                        std::size_t(t.width) * 4);
        out.seeThrough = anyAlphaBelowOne(out.image);
        return out;
    }
    auto found = files_.find(t.file);
    if (found != files_.end()) return found->second;
    std::optional<TextureImage> out;
    const QImage read(QString::fromStdString(t.file));
    if (!read.isNull()) {
        TextureImage image;
        const bool alpha = read.hasAlphaChannel();
        image.components = read.isGrayscale() ? (alpha ? 2 : 1) : (alpha ? 4 : 3);
        image.image = read.convertToFormat(QImage::Format_RGBA8888);
        image.seeThrough = alpha && anyAlphaBelowOne(image.image);
        out = std::move(image);
    }
    files_.emplace(t.file, out);
    return out;
}

} // namespace fl::viewer
