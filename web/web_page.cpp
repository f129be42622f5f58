#include "web_page.h"

#include "mesh/mesh_export.h"
#include "page_script.h"
#include "scene/gzip.h"
#include "scene/scene_writer.h"
#include "text/json_text.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

namespace fl::web {
namespace {

namespace fs = std::filesystem;

// X_ITE 15's components that live in files of their own, loaded on demand
// with import(), which a page opened from a file may not do: the page loads
// those the scene needs with <script> tags instead (page_script.h).
constexpr std::array kSeparateComponents = {"Annotation",
                                            "CADGeometry",
                                            "CubeMapTexturing",
                                            "DIS",
                                            "EventUtilities",
                                            "Geometry2D",
                                            "Geospatial",
                                            "HAnim",
                                            "KeyDeviceSensor",
                                            "Layout",
                                            "NURBS",
                                            "ParticleSystems",
                                            "Picking",
                                            "RigidBodyPhysics",
                                            "Text",
                                            "TextureProjection",
                                            "Texturing3D",
                                            "VolumeRendering",
                                            "WebXR"};

bool isSeparate(std::string_view component) {
    return std::find(kSeparateComponents.begin(), kSeparateComponents.end(), component) !=
           kSeparateComponents.end();
}

bool readFile(const fs::path& path, std::string& bytes, std::string& error) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    if (!in && !in.eof()) {
        error = path.string() + ": cannot be read";
        return false;
    }
    bytes = s.str();
    return true;
}

class FolderWriter {
  public:
    FolderWriter(fs::path dir, PageResult& result) : dir_(std::move(dir)), result_(result) {}

    bool write(const fs::path& relative, std::string_view bytes, std::string& error) {
        std::error_code ec;
        const fs::path path = dir_ / relative;
        fs::create_directories(path.parent_path(), ec);
        if (ec) {
            error = path.parent_path().string() + ": " + ec.message();
            return false;
        }
        if (!mesh::writeFileReplacing(path, bytes, error)) return false;
        result_.written.push_back(relative);
        result_.bytes += bytes.size();
        return true;
    }

    bool copy(const fs::path& from, const fs::path& relative, std::string& error) {
        std::string bytes;
        return readFile(from, bytes, error) && write(relative, bytes, error);
    }

  private:
    fs::path dir_;
    PageResult& result_;
};

std::string titleOf(const scene::Scene& source) {
    for (const auto& [name, content] : source.meta)
        if (name == "title" && !content.empty()) return content;
    const std::string& path = source.pathOf(0);
    return path.empty() ? "FunctionLab scene" : fs::path(path).stem().string();
}

std::string numberList(const std::vector<double>& numbers) {
    std::string out;
    for (double n : numbers) {
        if (!out.empty()) out += ", ";
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", n);
        out += buf;
    }
    return out;
}

std::string base64(std::string_view bytes) {
    static constexpr char kDigits[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        std::uint32_t v = 0;
        for (std::size_t k = 0; k < 3; ++k)
            v = (v << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        for (std::size_t k = 0; k < 4; ++k)
            out += k <= n ? kDigits[(v >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

// The page's copy of the scene with each image it names carried inside it
// as a data: url: a page opened from a file may not fetch files/..., but
// may read data: urls. scene.x3d keeps the files' names for other
// browsers. Images only, each up to 8 MiB, 32 MiB in all; a name the
// writer had to escape is left as it is (it still loads over HTTP).
std::string imagesInside(std::string x3d, const BakeResult& baked) {
    constexpr std::uintmax_t kMaxImage = 8u << 20, kMaxImages = 32u << 20;
    std::uintmax_t total = 0;
    for (const BakedFile& f : baked.files) {
        std::string ext = fs::path(f.target).extension().string();
        for (char& c : ext)
            c = char(std::tolower(static_cast<unsigned char>(c)));
        const char* type = ext == ".png"                     ? "image/png"
                           : ext == ".jpg" || ext == ".jpeg" ? "image/jpeg"
                           : ext == ".gif"                   ? "image/gif"
                           : ext == ".webp"                  ? "image/webp"
                                                             : nullptr;
        std::error_code ec;
        const std::uintmax_t size = fs::file_size(f.source, ec);
        if (!type || ec || size > kMaxImage || total + size > kMaxImages) continue;
        std::string bytes, ignored;
        if (!readFile(f.source, bytes, ignored)) continue;
        total += size;
        const std::string from = "&quot;" + f.target + "&quot;";
        const std::string to =
            "&quot;data:" + std::string(type) + ";base64," + base64(bytes) + "&quot;";
        for (std::size_t at = x3d.find(from); at != std::string::npos;
             at = x3d.find(from, at + to.size()))
            x3d.replace(at, from.size(), to);
    }
    return x3d;
}

std::string sceneScript(const BakeResult& baked, const std::string& x3d,
                        const std::vector<std::string>& components) {
    std::string s = "// Written by functionlab export-web: the scene of scene.x3d (its images\n"
                    "// inside), gzipped, for\n"
                    "// a page opened from a file, which may not fetch it.\n"
                    "window.FunctionLabScene = {\n  clocks: [";
    for (std::size_t i = 0; i < baked.clocks.size(); ++i) {
        const BakedClock& c = baked.clocks[i];
        char buf[96];
        std::snprintf(buf, sizeof buf, ", start: %.17g, cycle: %.17g}", c.startSeconds,
                      c.cycleSeconds);
        s += (i ? ",\n    " : "\n    ");
        s += "{timeSensor: " + javaScriptString(c.timeSensor) +
             ", base: " + javaScriptString(clockBaseName(c.base)) + buf;
    }
    s += "],\n  components: [";
    for (std::size_t i = 0; i < components.size(); ++i)
        s += (i ? ", " : "") + javaScriptString(components[i]);
    s += "],\n  x3dGzipBase64: \"" + base64(scene::gzip(x3d)) + "\"\n};\n";
    return s;
}

std::string indexHtml(const scene::Scene& source, const std::string& sourceLink,
                      const std::vector<std::string>& components, const PageOptions& options) {
    const std::string title = htmlText(titleOf(source));
    std::string h;
    h += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<meta name=\"generator\" content=\"FunctionLab export-web\">\n";
    h += "<title>" + title + " \u2014 FunctionLab</title>\n";
    h += "<link rel=\"stylesheet\" href=\"viewer/page.css\">\n"
         "<script src=\"viewer/x_ite.min.js\"></script>\n"
         "<script src=\"viewer/x_ite_css.js\"></script>\n";
    for (const std::string& c : components)
        h += "<script src=\"viewer/components/" + htmlText(c) + "Component.js\"></script>\n";
    h += "<script src=\"scene.js\"></script>\n"
         "<script src=\"viewer/functionlab-page.js\"></script>\n"
         "</head>\n<body>\n<header>\n<h1>" +
         title + "</h1>\n";
    h += "<p>A FunctionLab scene in your browser: drag to turn it, scroll to come closer. "
         "Function shapes are shown as meshes";
    if (!options.resolutions.empty())
        h += " at " + numberList(options.resolutions) + " cells, finer as you come closer";
    if (options.frames > 0)
        h += "; what changes with time plays as " + std::to_string(options.frames) +
             " frames per cycle";
    h += ".</p>\n<p class=\"limits\">A browser cannot feel the scene (haptics) or edit it. Open "
         "<a href=\"" +
         htmlText(sourceLink) +
         "\">the scene's source</a> in FunctionLab for that; <a href=\"scene.x3d\">scene.x3d</a> "
         "is what this page shows, for any X3D browser.</p>\n";
    h += "<p id=\"status\" role=\"status\"></p>\n</header>\n"
         "<x3d-canvas id=\"scene\" contextMenu=\"false\" splashScreen=\"false\"></x3d-canvas>\n"
         "<footer>Made with FunctionLab; drawn by <a href=\"viewer/LICENSE.md\">X_ITE</a>."
         "</footer>\n</body>\n</html>\n";
    return h;
}

} // namespace

std::string javaScriptString(std::string_view text) {
    // JSON's string is JavaScript's; then what a page or an old engine
    // would still read as more than text: < and > (no "</script>" can end
    // a script), DEL, and U+2028/U+2029 (line ends before ES2019).
    const std::string json = text::jsonString(text);
    std::string out;
    out.reserve(json.size());
    for (std::size_t i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (c == '<')
            out += "\\u003c";
        else if (c == '>')
            out += "\\u003e";
        else if (c == '\x7f')
            out += "\\u007f";
        else if (json.compare(i, 3, "\xe2\x80\xa8") == 0)
            out += "\\u2028", i += 2;
        else if (json.compare(i, 3, "\xe2\x80\xa9") == 0)
            out += "\\u2029", i += 2;
        else
            out += c;
    }
    return out;
}

std::string withImagesInside(std::string x3d, const BakeResult& baked) {
    return imagesInside(std::move(x3d), baked);
}

std::string htmlText(std::string_view text) {
    std::string shown;
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if ((u >= 0x20 && u != 0x7f) || c == '\t' || c == '\n') shown += c;
    }
    return scene::xmlEscape(shown);
}

std::optional<fs::path> findXite(std::string& why) {
    std::vector<fs::path> candidates;
    if (const char* env = std::getenv("FUNCTIONLAB_X_ITE_DIR"); env && *env)
        candidates.emplace_back(env);
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) candidates.push_back(exe.parent_path() / ".." / "share" / "functionlab" / "x_ite");
    candidates.emplace_back(FUNCTIONLAB_X_ITE_BUILD_DIR);
    for (const fs::path& c : candidates)
        if (fs::is_regular_file(c / "x_ite.min.js", ec)) return fs::weakly_canonical(c, ec);
    why = "X_ITE, the X3D browser the page ships, is not installed: run scripts/run once (it "
          "installs it from npm, pinned by web/package-lock.json), or set FUNCTIONLAB_X_ITE_DIR "
          "to the dist folder of the npm package x_ite";
    return std::nullopt;
}

bool writeWebFolder(const BakeResult& baked, const scene::Scene& source, const fs::path& dir,
                    const PageOptions& options, PageResult& result, std::string& error) {
    FolderWriter out(dir, result);
    std::vector<std::string> components;
    bool text = false;
    for (const scene::Component& c : baked.scene.components) {
        if (isSeparate(c.name)) components.push_back(c.name);
        text = text || c.name == "Text";
    }
    const std::string x3d = scene::writeScene(baked.scene, scene::Encoding::Xml);

    // The scene's own source, to open in FunctionLab: its text and the texts
    // its Inlines read, as they were read, where they lie below its folder.
    std::string sourceLink = "scene.x3d";
    const std::string& scenePath = source.pathOf(0);
    if (!scenePath.empty()) {
        std::error_code ec;
        const fs::path root = fs::weakly_canonical(fs::absolute(scenePath).parent_path(), ec);
        for (const scene::SourceFile& f : source.files) {
            const fs::path file = fs::weakly_canonical(fs::absolute(f.path), ec);
            const fs::path relative = fs::relative(file, root, ec);
            if (ec || relative.empty() || *relative.begin() == "..") continue;
            // Written as it was read: a gzipped scene (.x3d.gz, .x3dz ...) gzipped again.
            const std::string ext = relative.extension().string();
            const bool gzipped = ext == ".gz" || ext == ".x3dz" || ext == ".x3dvz" || ext == ".wrz";
            if (!out.write("source" / relative, gzipped ? scene::gzip(f.text) : f.text, error))
                return false;
        }
        sourceLink = "source/" + fs::path(scenePath).filename().generic_string();
    }
    for (const BakedFile& f : baked.files)
        if (!out.copy(f.source, f.target, error)) return false;

    // X_ITE: its script, its style (also as a script, for a page opened from
    // a file), its licences, and the separate components the scene needs.
    const fs::path& x = options.xIteDir;
    std::string css;
    if (!readFile(x / "x_ite.css", css, error)) return false;
    if (!out.copy(x / "x_ite.min.js", "viewer/x_ite.min.js", error) ||
        !out.write("viewer/x_ite.css", css, error) ||
        !out.write("viewer/x_ite_css.js",
                   "window.FunctionLabXiteCss = " + javaScriptString(css) + ";\n", error))
        return false;
    for (const char* licence : {"LICENSE.md", "LICENSES/MIT.txt", "LICENSES/Apache-2.0.txt"}) {
        std::error_code ec;
        if (fs::is_regular_file(x / ".." / licence, ec) &&
            !out.copy(x / ".." / licence, fs::path("viewer") / licence, error))
            return false;
    }
    for (const std::string& c : components) {
        std::string code;
        if (!readFile(x / "assets" / "components" / (c + "Component.min.js"), code, error))
            return false;
        // Each component declares the same top-level const: a block keeps
        // one <script> from clashing with the next.
        if (!out.write("viewer/components/" + c + "Component.js", "{\n" + code + "\n}\n", error))
            return false;
    }
    if (text) {
        std::error_code ec;
        for (const auto& e : fs::recursive_directory_iterator(x / "assets" / "fonts", ec))
            if (e.is_regular_file(ec) &&
                !out.copy(e.path(),
                          "viewer/assets/fonts" /
                              fs::relative(e.path(), x / "assets" / "fonts", ec),
                          error))
                return false;
    }
    return out.write("viewer/functionlab-page.js", kPageScript, error) &&
           out.write("viewer/page.css", kPageStyle, error) && out.write("scene.x3d", x3d, error) &&
           out.write("scene.js", sceneScript(baked, imagesInside(x3d, baked), components), error) &&
           out.write("index.html", indexHtml(source, sourceLink, components, options), error);
}

} // namespace fl::web
