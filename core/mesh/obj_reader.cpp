#include "obj_reader.h"

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>

namespace fl::mesh {
namespace {

// Statements of the OBJ format that a polygon mesh can hold besides v and
// f, read past. Anything else is not an OBJ mesh (or not one we can draw).
constexpr std::array<std::string_view, 17> kReadPast = {
    "vn", "vt", "vp",  "g",     "o",        "s",        "usemtl",     "mtllib",   "l",
    "p",  "mg", "lod", "bevel", "c_interp", "d_interp", "shadow_obj", "trace_obj"};

std::string printable(std::string_view s) {
    std::string out;
    for (char c : s.substr(0, 32))
        out += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
    return out + (s.size() > 32 ? "..." : "");
}

struct Token {
    std::string_view text;
    std::size_t column;
};

} // namespace

ObjReadResult readObj(std::string_view bytes, std::string_view name) {
    ObjReadResult out;
    Mesh m;
    std::size_t lineNo = 0;
    auto fail = [&](std::size_t column, const std::string& what) {
        out.error = std::string(name) + ":" + std::to_string(lineNo) + ":" +
                    std::to_string(column) + ": " + what;
        return out;
    };
    if (bytes.size() > kMaxObjBytes) {
        out.error = std::string(name) + ": " + std::to_string(bytes.size()) +
                    " bytes; an OBJ mesh may have at most " + std::to_string(kMaxObjBytes >> 20) +
                    " MiB";
        return out;
    }
    std::vector<Token> t;
    std::vector<std::uint32_t> polygon;
    std::size_t pos = 0;
    while (pos < bytes.size()) {
        const std::size_t eol = std::min(bytes.find('\n', pos), bytes.size());
        std::string_view line = bytes.substr(pos, eol - pos);
        pos = eol + 1;
        ++lineNo;
        // A backslash at the end joins the next line (rare; read as one).
        t.clear();
        for (std::size_t i = 0; i < line.size();) {
            const char c = line[i];
            if (c == ' ' || c == '\t' || c == '\r' || c == '\\') {
                ++i;
                continue;
            }
            if (c == '#') break;
            const std::size_t start = i;
            while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r' &&
                   line[i] != '#')
                ++i;
            t.push_back({line.substr(start, i - start), start + 1});
        }
        if (t.empty()) continue;
        const std::string_view key = t[0].text;
        if (key == "v") {
            if (t.size() < 4)
                return fail(line.size() + 1, "a vertex needs three coordinates (v X Y Z)");
            Vec3f p{};
            for (std::size_t k = 0; k < 3; ++k) {
                double d = 0;
                const auto s = t[1 + k].text;
                const auto r = std::from_chars(s.data(), s.data() + s.size(), d);
                if (r.ec != std::errc() || r.ptr != s.data() + s.size())
                    return fail(t[1 + k].column,
                                "expected a coordinate, not '" + printable(s) + "'");
                if (!std::isfinite(d) || std::abs(d) > 1e30)
                    return fail(t[1 + k].column, "the coordinate '" + printable(s) +
                                                     "' is not a finite number of at most 1e30");
                p[k] = float(d);
            }
            if (m.positions.size() >= 0x7fffffffu) return fail(1, "more than 2^31 vertices");
            m.positions.push_back(p);
            out.vertexLines.push_back(std::uint32_t(lineNo));
        } else if (key == "f") {
            if (t.size() < 4) return fail(t[0].column, "a face needs at least three vertices");
            polygon.clear();
            for (std::size_t k = 1; k < t.size(); ++k) {
                const auto s = t[k].text;
                const auto slash = s.find('/');
                const auto index = s.substr(0, slash);
                long long i = 0;
                const auto r = std::from_chars(index.data(), index.data() + index.size(), i);
                if (r.ec != std::errc() || r.ptr != index.data() + index.size() || i == 0)
                    return fail(t[k].column,
                                "expected a vertex number (1, 2, ... or -1 for the last), not '" +
                                    printable(s) + "'");
                const auto count = static_cast<long long>(m.positions.size());
                const long long at = i > 0 ? i - 1 : count + i;
                if (at < 0 || at >= count)
                    return fail(t[k].column, "vertex " + std::to_string(i) +
                                                 " is not defined above (" + std::to_string(count) +
                                                 " so far)");
                polygon.push_back(std::uint32_t(at));
            }
            for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
                m.triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
                out.triangleLines.push_back(std::uint32_t(lineNo));
            }
        } else {
            bool known = false;
            for (std::string_view k : kReadPast)
                known = known || key == k;
            if (!known)
                return fail(t[0].column, "'" + printable(key) +
                                             "' is not an OBJ mesh statement (v, f, vn, vt, g, o, "
                                             "s, usemtl, mtllib ...): is this an OBJ file?");
        }
    }
    if (m.positions.empty() || m.triangles.empty()) {
        out.error = std::string(name) + ": " +
                    (m.positions.empty() ? "no vertices ('v' lines): not an OBJ mesh"
                                         : "no faces ('f' lines): a point cloud, not a mesh");
        return out;
    }
    out.mesh = std::move(m);
    return out;
}

ObjReadResult readObjFile(const std::string& path) {
    ObjReadResult r;
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) {
        r.error = path + ": cannot be opened";
        return r;
    }
    const auto size = static_cast<std::size_t>(in.tellg());
    if (size > kMaxObjBytes) {
        r.error = path + ": " + std::to_string(size >> 20) + " MiB; an OBJ mesh may have at most " +
                  std::to_string(kMaxObjBytes >> 20) + " MiB";
        return r;
    }
    in.seekg(0);
    std::string bytes(size, '\0');
    if (!in.read(bytes.data(), std::streamsize(size))) {
        r.error = path + ": cannot be read";
        return r;
    }
    return readObj(bytes, path);
}

} // namespace fl::mesh
