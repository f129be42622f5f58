#include "scene_texture.h"

#include "scene/field_access.h"

#include <cmath>
#include <filesystem>
#include <system_error>

namespace fl::mesh {
namespace {

using scene::Node;

const Node* textureNode(const Node* appearance) {
    if (!appearance) return nullptr;
    const Node* t = scene::effectiveNode(scene::nodeField(*appearance, "texture"));
    // MultiTexture: its first texture (the others need multi-texturing).
    if (t && t->kind() == scene::NodeKind::MultiTexture) {
        const auto all = scene::nodesField(*t, "texture");
        t = all.empty() ? nullptr : scene::effectiveNode(all.front());
    }
    return t;
}

// A url as a file next to the scene: relative to the scene file's folder,
// file:// stripped; remote urls are not fetched.
std::optional<std::string> localFile(const std::string& url, const std::filesystem::path& folder) {
    std::string u = url;
    if (u.rfind("file://", 0) == 0) u = u.substr(7);
    if (u.find("://") != std::string::npos || u.empty()) return std::nullopt;
    std::filesystem::path p(u);
    if (p.is_relative()) p = folder / p;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec)) return std::nullopt;
    return std::filesystem::absolute(p, ec).lexically_normal().string();
}

SurfaceTexture pixelTexture(const Node& t, std::vector<std::string>& warnings) {
    SurfaceTexture s;
    const auto v = scene::numbersField(t, "image");
    if (v.size() < 3) return s;
    const double w = v[0], h = v[1], c = v[2];
    if (!(w >= 1 && h >= 1 && c >= 1 && c <= 4) || w * h > 16.0 * 1024 * 1024 ||
        v.size() < 3 + std::size_t(w * h)) {
        warnings.push_back("PixelTexture: its image is empty, too large or shorter than width x "
                           "height pixels; drawn without it");
        return s;
    }
    s.width = int(w);
    s.height = int(h);
    s.components = int(c);
    s.rgba.reserve(std::size_t(w * h) * 4);
    for (std::size_t i = 0; i < std::size_t(w * h); ++i) {
        const auto p = std::uint32_t(std::int64_t(v[3 + i]) & 0xFFFFFFFF);
        auto byte = [&](int k) { return std::uint8_t((p >> (8 * k)) & 0xFF); };
        switch (s.components) {
        case 1:
            s.rgba.insert(s.rgba.end(), {byte(0), byte(0), byte(0), 255});
            break;
        case 2:
            s.rgba.insert(s.rgba.end(), {byte(1), byte(1), byte(1), byte(0)});
            break;
        case 3:
            s.rgba.insert(s.rgba.end(), {byte(2), byte(1), byte(0), 255});
            break;
        default:
            s.rgba.insert(s.rgba.end(), {byte(3), byte(2), byte(1), byte(0)});
            break;
        }
    }
    return s;
}

} // namespace

std::optional<SurfaceTexture> textureOf(const scene::Scene& scene, const Node* appearance,
                                        std::vector<std::string>& warnings) {
    const Node* t = textureNode(appearance);
    if (!t) return std::nullopt;
    SurfaceTexture s;
    if (t->kind() == scene::NodeKind::ImageTexture) {
        const std::filesystem::path folder =
            std::filesystem::path(scene.pathOf(t->file)).parent_path();
        const auto urls = scene::stringsField(*t, "url");
        for (const std::string& url : urls)
            if (auto file = localFile(url, folder)) {
                s.file = *file;
                break;
            }
        if (s.file.empty()) {
            std::string list;
            for (const std::string& url : urls)
                list += (list.empty() ? "'" : ", '") + url + "'";
            warnings.push_back(
                "ImageTexture: " + (list.empty() ? std::string("no url") : "no file " + list) +
                " next to the scene (remote urls are not fetched); drawn without it");
            return std::nullopt;
        }
    } else if (t->kind() == scene::NodeKind::PixelTexture) {
        s = pixelTexture(*t, warnings);
        if (s.rgba.empty()) return std::nullopt;
    } else {
        return std::nullopt; // MovieTexture and others: not drawn
    }
    s.repeatS = scene::boolField(*t, "repeatS");
    s.repeatT = scene::boolField(*t, "repeatT");
    return s;
}

void applyTextureTransform(const Node* appearance, Mesh& mesh) {
    if (!appearance || mesh.texCoords.empty()) return;
    const Node* tt = scene::effectiveNode(scene::nodeField(*appearance, "textureTransform"));
    if (!tt || tt->kind() != scene::NodeKind::TextureTransform) return;
    const double cx = scene::numberField(*tt, "center", 0),
                 cy = scene::numberField(*tt, "center", 1);
    const double sx = scene::numberField(*tt, "scale", 0, 1),
                 sy = scene::numberField(*tt, "scale", 1, 1);
    const double tx = scene::numberField(*tt, "translation", 0),
                 ty = scene::numberField(*tt, "translation", 1);
    const double r = scene::numberField(*tt, "rotation");
    const double c = std::cos(r), s = std::sin(r);
    for (auto& st : mesh.texCoords) {
        // T, then C, then R, then S, then -C.
        double x = st[0] + tx + cx, y = st[1] + ty + cy;
        const double rx = c * x - s * y, ry = s * x + c * y;
        x = rx * sx - cx;
        y = ry * sy - cy;
        st = {float(x), float(y)};
    }
}

} // namespace fl::mesh
