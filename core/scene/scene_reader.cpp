#include "scene_reader.h"

#include "classic_reader.h"
#include "function_definitions.h"
#include "gzip.h"
#include "implicit_sides.h"
#include "node_graph.h"
#include "preview_marker.h"
#include "scene_builder.h"
#include "scene_references.h"
#include "xml_reader.h"

#include <QString>

#include <cstdio>
#include <fstream>
#include <sstream>

namespace fl::scene {
namespace {

ReadResult failWith(const std::string& path, std::string message, std::string suggestion = {}) {
    ReadResult r;
    r.diagnostics.push_back({Severity::Error, path, {}, std::move(message), std::move(suggestion)});
    return r;
}

} // namespace

ReadResult readSceneBytes(std::string bytes, const std::string& path, const ReadOptions& options) {
    return readSceneIn(std::move(bytes), path, options, nullptr, {});
}

ReadResult readSceneIn(std::string bytes, const std::string& path, const ReadOptions& options,
                       ReferenceContext* context, const std::filesystem::path& baseDir) {
    if (bytes.size() > options.limits.maxFileBytes)
        return failWith(path,
                        "the file is larger than " + byteSizeText(options.limits.maxFileBytes));
    if (isGzip(bytes)) {
        std::string problem;
        std::optional<std::string> text = gunzip(bytes, options.limits.maxDecodedBytes, problem);
        if (!text) return failWith(path, problem);
        bytes = std::move(*text);
    }
    if (bytes.size() >= 2 && ((bytes[0] == '\xFF' && bytes[1] == '\xFE') ||
                              (bytes[0] == '\xFE' && bytes[1] == '\xFF'))) {
        // UTF-16 with a byte order mark: read as UTF-8 from here on.
        const bool little = bytes[0] == '\xFF';
        std::u16string units;
        for (std::size_t i = 2; i + 1 < bytes.size(); i += 2) {
            const auto lo = static_cast<unsigned char>(bytes[i + (little ? 0 : 1)]);
            const auto hi = static_cast<unsigned char>(bytes[i + (little ? 1 : 0)]);
            units.push_back(static_cast<char16_t>(lo | (hi << 8)));
        }
        bytes = QString::fromUtf16(units.data(), static_cast<qsizetype>(units.size()))
                    .toUtf8()
                    .toStdString();
    }
    if (bytes.starts_with("\xEF\xBB\xBF")) bytes.erase(0, 3); // UTF-8 byte order mark
    // A scene file is text. A NUL or another C0 control character (other than
    // tab and line breaks) has no place in it, and X3D XML cannot hold one at
    // all (form feed and vertical tab included), so a scene with one could not
    // be converted.
    for (std::size_t i = 0, line = 1, column = 1; i < bytes.size(); ++i) {
        const auto c = static_cast<unsigned char>(bytes[i]);
        if (c == '\n') {
            ++line;
            column = 1;
            continue;
        }
        if (c < 0x20 && c != '\t' && c != '\r') {
            char code[8];
            std::snprintf(code, sizeof code, "U+%04X", unsigned(c));
            ReadResult r;
            r.diagnostics.push_back({Severity::Error,
                                     path,
                                     {int(line), int(column)},
                                     std::string("the file holds the control character ") + code +
                                         "; a scene file is text",
                                     "remove it (was the file saved as binary?)"});
            return r;
        }
        if ((c & 0xC0) != 0x80) ++column;
    }
    ReadResult result;
    auto scene = std::make_unique<Scene>();
    scene->files.push_back({path, std::move(bytes)});
    const std::string& text = scene->files[0].text;
    SceneBuilder builder(*scene, 0, options.limits, result.diagnostics);
    ReferenceLoader references(options.followReferences ? context : nullptr, *scene, baseDir,
                               options, result.diagnostics);
    builder.setExternProtoResolver(
        [&](ProtoDeclaration& proto) { return references.resolveExternProto(proto); });
    try {
        if (looksLikeClassic(text)) {
            readClassic(builder);
        } else if (looksLikeXml(text)) {
            scene->encoding = Encoding::Xml;
            readXml(builder);
        } else {
            builder.fail({1, 1}, "this is not a scene file",
                         "a scene starts with '#VRML V2.0 utf8', '#X3D V3.3 utf8' or an XML <X3D> "
                         "document");
        }
        builder.finish();
    } catch (const StopReading&) {
        return result;
    }
    if (builder.hasErrors()) return result;
    // A preview written by `convert` is for other browsers, not part of the scene.
    std::erase_if(scene->roots, [](const Node* n) { return n && n->defName == kPreviewDefName; });
    references.resolveInlines();
    checkUnfoldedScene(*scene, options.limits.maxUnfoldedNodes, options.limits.maxUnfoldedDepth,
                       result.diagnostics);
    if (hasErrors(result.diagnostics)) return result;
    if (options.compileFunctions) {
        compileFunctionDefinitions(*scene, result.diagnostics, options.limits);
        if (hasErrors(result.diagnostics)) return result;
        for (SceneDiagnostic& d : checkImplicitSides(*scene))
            result.diagnostics.push_back(std::move(d));
    }
    result.scene = std::move(scene);
    return result;
}

ReadResult readSceneFile(const std::filesystem::path& path, const ReadOptions& options) {
    const std::string name = path.string();
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        return failWith(name, "this is a folder, not a scene file");
    std::ifstream in(path, std::ios::binary);
    if (!in) return failWith(name, "cannot open the file", "check the path and the permissions");
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > options.limits.maxFileBytes)
        return failWith(name,
                        "the file is larger than " + byteSizeText(options.limits.maxFileBytes));
    std::ostringstream content;
    content << in.rdbuf();
    // References are followed inside the folder the scene file is in.
    ReferenceContext context;
    context.bytesRead = ec ? 0 : std::size_t(size);
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
    context.root = canonical.parent_path();
    context.displayRoot = path.parent_path();
    context.loading.push_back(canonical);
    return readSceneIn(std::move(content).str(), name, options, &context, context.root);
}

} // namespace fl::scene
