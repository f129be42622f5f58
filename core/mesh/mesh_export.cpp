#include "mesh_export.h"

#include "mesh_topology.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace fl::mesh {
namespace {

void putBytes(std::string& out, const void* data, std::size_t n) {
    out.append(static_cast<const char*>(data), n);
}
template <class T>
void put(std::string& out, T value) { // little-endian: every machine we build for
    putBytes(out, &value, sizeof value);
}

std::string number(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", double(v));
    return buf;
}

// "a b c" with a separator before it; += piece by piece (GCC 12 warns falsely,
// -Wrestrict, about chains of literal + std::string).
void appendTriple(std::string& out, const char* separator, float a, float b, float c) {
    out += separator;
    out += number(a);
    out += ' ';
    out += number(b);
    out += ' ';
    out += number(c);
}

Vec3f unitNormal(const Mesh& m, std::size_t i) {
    if (i < m.normals.size()) {
        const Vec3f& n = m.normals[i];
        const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (len > 0) return {n[0] / len, n[1] / len, n[2] / len};
    }
    return {0, 0, 1};
}

Vec3f faceNormal(const Mesh& m, const Triangle& t) {
    const Vec3f &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
    const float u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const float v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    Vec3f n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (len > 0)
        for (float& c2 : n)
            c2 /= len;
    return n;
}

std::string stl(const Mesh& m) {
    std::string out;
    std::string header = "FunctionLab binary STL";
    header.resize(80, ' ');
    out += header;
    put<std::uint32_t>(out, std::uint32_t(m.triangles.size()));
    for (const Triangle& t : m.triangles) {
        const Vec3f n = faceNormal(m, t);
        putBytes(out, n.data(), 12);
        for (std::uint32_t i : t)
            putBytes(out, m.positions[i].data(), 12);
        put<std::uint16_t>(out, 0);
    }
    return out;
}

std::string obj(const Mesh& m) {
    std::string out = "# FunctionLab mesh: " + std::to_string(m.vertexCount()) + " vertices, ";
    out +=
        m.isPointCloud() ? "a point cloud\n" : std::to_string(m.triangleCount()) + " triangles\n";
    const bool colours = m.colours.size() == m.positions.size();
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const Vec3f& p = m.positions[i];
        appendTriple(out, "v ", p[0], p[1], p[2]);
        if (colours) // the widespread "v x y z r g b" extension
            appendTriple(out, " ", m.colours[i][0], m.colours[i][1], m.colours[i][2]);
        out += '\n';
    }
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const Vec3f n = unitNormal(m, i);
        appendTriple(out, "vn ", n[0], n[1], n[2]);
        out += '\n';
    }
    for (const Segment& g : m.segments) {
        out += 'l';
        for (std::uint32_t i : g) {
            out += ' ';
            out += std::to_string(i + 1);
        }
        out += '\n';
    }
    for (const Triangle& t : m.triangles) {
        out += 'f';
        for (std::uint32_t i : t) {
            const std::string index = std::to_string(i + 1);
            out += ' ';
            out += index;
            out += "//";
            out += index;
        }
        out += '\n';
    }
    return out;
}

std::string ply(const Mesh& m) {
    const bool colours = m.colours.size() == m.positions.size();
    std::string out = "ply\nformat binary_little_endian 1.0\ncomment FunctionLab mesh\n";
    out += "element vertex " + std::to_string(m.vertexCount()) + "\n";
    out += "property float x\nproperty float y\nproperty float z\n";
    out += "property float nx\nproperty float ny\nproperty float nz\n";
    if (colours)
        out +=
            "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n";
    out += "element face " + std::to_string(m.triangleCount()) + "\n";
    out += "property list uchar uint vertex_indices\n";
    if (!m.segments.empty()) {
        out += "element edge " + std::to_string(m.segments.size()) + "\n";
        out += "property int vertex1\nproperty int vertex2\n";
    }
    out += "end_header\n";
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        putBytes(out, m.positions[i].data(), 12);
        const Vec3f n = unitNormal(m, i);
        putBytes(out, n.data(), 12);
        if (colours)
            for (float c : m.colours[i])
                put<std::uint8_t>(out, std::uint8_t(std::lround(std::clamp(c, 0.0f, 1.0f) * 255)));
    }
    for (const Triangle& t : m.triangles) {
        put<std::uint8_t>(out, 3);
        putBytes(out, t.data(), 12);
    }
    for (const Segment& g : m.segments)
        putBytes(out, g.data(), 8);
    return out;
}

std::string glb(const Mesh& m) {
    const bool colours = m.colours.size() == m.positions.size();
    std::string bin;
    std::string json = R"({"asset":{"version":"2.0","generator":"FunctionLab"},"scene":0,)";
    if (m.empty()) {
        json += R"("scenes":[{"nodes":[]}]})";
    } else {
        Vec3f lo = m.positions[0], hi = lo;
        for (const Vec3f& p : m.positions)
            for (std::size_t k = 0; k < 3; ++k) {
                lo[k] = std::min(lo[k], p[k]);
                hi[k] = std::max(hi[k], p[k]);
            }
        const std::size_t n = m.vertexCount();
        const std::size_t positionsAt = bin.size();
        for (const Vec3f& p : m.positions)
            putBytes(bin, p.data(), 12);
        const std::size_t normalsAt = bin.size();
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3f nn = unitNormal(m, i);
            putBytes(bin, nn.data(), 12);
        }
        const std::size_t coloursAt = bin.size();
        if (colours)
            for (const auto& c : m.colours)
                putBytes(bin, c.data(), 16);
        const std::size_t indicesAt = bin.size();
        const bool points = m.isPointCloud(); // mode POINTS, no indices
        if (m.isLines())
            for (const Segment& g : m.segments)
                putBytes(bin, g.data(), 8);
        else if (!points)
            for (const Triangle& t : m.triangles)
                putBytes(bin, t.data(), 12);
        auto view = [](std::size_t offset, std::size_t length, int target) {
            return "{\"buffer\":0,\"byteOffset\":" + std::to_string(offset) +
                   ",\"byteLength\":" + std::to_string(length) +
                   ",\"target\":" + std::to_string(target) + "}";
        };
        json += R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)";
        json += R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1)";
        if (colours) json += R"(,"COLOR_0":2)";
        json += '}';
        if (points) {
            json += R"(,"mode":0}]}],)";
        } else {
            json += colours ? R"(,"indices":3,"mode":)" : R"(,"indices":2,"mode":)";
            json += m.isLines() ? "1}]}]," : "4}]}],"; // LINES or TRIANGLES
        }
        json += "\"bufferViews\":[" + view(positionsAt, normalsAt - positionsAt, 34962) + "," +
                view(normalsAt, coloursAt - normalsAt, 34962);
        if (colours) {
            json += ',';
            json += view(coloursAt, indicesAt - coloursAt, 34962);
        }
        if (!points) {
            json += ',';
            json += view(indicesAt, bin.size() - indicesAt, 34963);
        }
        json += "],";
        const std::string count = std::to_string(n);
        int v = 0;
        auto accessor = [&](const std::string& type, int componentType, const std::string& c,
                            const std::string& extra) {
            return "{\"bufferView\":" + std::to_string(v++) +
                   ",\"componentType\":" + std::to_string(componentType) + ",\"count\":" + c +
                   ",\"type\":\"" + type + "\"" + extra + "}";
        };
        std::string bounds = ",\"min\":[";
        appendTriple(bounds, "", lo[0], lo[1], lo[2]);
        bounds += "],\"max\":[";
        appendTriple(bounds, "", hi[0], hi[1], hi[2]);
        bounds += ']';
        for (char& c : bounds) // appendTriple separates with spaces; JSON lists want commas
            if (c == ' ') c = ',';
        json += "\"accessors\":[";
        json += accessor("VEC3", 5126, count, bounds);
        json += ',';
        json += accessor("VEC3", 5126, count, "");
        if (colours) {
            json += ',';
            json += accessor("VEC4", 5126, count, "");
        }
        if (!points) {
            json += ',';
            json += accessor(
                "SCALAR", 5125,
                std::to_string(m.isLines() ? 2 * m.segments.size() : 3 * m.triangleCount()), "");
        }
        json += "],";
        json += "\"buffers\":[{\"byteLength\":" + std::to_string(bin.size()) + "}]}";
    }
    while (json.size() % 4)
        json += ' ';
    while (bin.size() % 4)
        bin += '\0';
    std::string out;
    const std::size_t total = 12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size());
    put<std::uint32_t>(out, 0x46546C67); // "glTF"
    put<std::uint32_t>(out, 2);
    put<std::uint32_t>(out, std::uint32_t(total));
    put<std::uint32_t>(out, std::uint32_t(json.size()));
    put<std::uint32_t>(out, 0x4E4F534A); // "JSON"
    out += json;
    if (!bin.empty()) {
        put<std::uint32_t>(out, std::uint32_t(bin.size()));
        put<std::uint32_t>(out, 0x004E4942); // "BIN\0"
        out += bin;
    }
    return out;
}

std::string x3d(const Mesh& m) {
    const bool colours = m.colours.size() == m.positions.size();
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                      "<X3D profile='Interchange' version='3.3'>\n"
                      "  <head><meta name='generator' content='FunctionLab'/></head>\n"
                      "  <Scene>\n    <Shape>\n"
                      "      <Appearance><Material diffuseColor='0.8 0.8 0.8'/></Appearance>\n";
    const bool lines = m.isLines();
    const bool points = m.isPointCloud() || lines; // no normals, no faces
    // A point cloud: a PointSet; lines: an IndexedLineSet (both unlit).
    if (lines) {
        out += "      <IndexedLineSet coordIndex='";
        for (std::size_t i = 0; i < m.segments.size(); ++i) {
            if (i) out += ' ';
            out += std::to_string(m.segments[i][0]);
            out += ' ';
            out += std::to_string(m.segments[i][1]);
            out += " -1";
        }
        out += "'>\n        <Coordinate point='";
    } else {
        // Open surfaces (parametric sheets, shapes cut by their box) are
        // seen from both sides; closed ones only from outside.
        const bool closed = !points && analyseTopology(weldedByPosition(m)).closed();
        out += points   ? "      <PointSet>\n        <Coordinate point='"
               : closed ? "      <IndexedFaceSet solid='true' ccw='true' normalPerVertex='true' "
                          "coordIndex='"
                        : "      <IndexedFaceSet solid='false' ccw='true' normalPerVertex='true' "
                          "coordIndex='";
    }
    for (std::size_t i = 0; !points && i < m.triangles.size(); ++i) {
        for (std::uint32_t v : m.triangles[i]) {
            if (i || v != m.triangles[i][0]) out += ' ';
            out += std::to_string(v);
        }
        out += " -1";
    }
    if (!points) out += "'>\n        <Coordinate point='";
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const Vec3f& p = m.positions[i];
        appendTriple(out, i ? ", " : "", p[0], p[1], p[2]);
    }
    out += "'/>\n";
    if (!points) {
        out += "        <Normal vector='";
        for (std::size_t i = 0; i < m.positions.size(); ++i) {
            const Vec3f n = unitNormal(m, i);
            appendTriple(out, i ? ", " : "", n[0], n[1], n[2]);
        }
        out += "'/>\n";
    }
    if (colours) {
        // Opaque colours as Color: a ColorRGBA makes viewers (view3dscene)
        // blend the shape as see-through, and a two-sided open mesh then
        // shows its back faces through its front.
        const bool opaque = std::all_of(m.colours.begin(), m.colours.end(),
                                        [](const auto& c) { return c[3] >= 1.0f; });
        out += opaque ? "        <Color color='" : "        <ColorRGBA color='";
        for (std::size_t i = 0; i < m.colours.size(); ++i) {
            const auto& c = m.colours[i];
            appendTriple(out, i ? ", " : "", c[0], c[1], c[2]);
            if (!opaque) {
                out += ' ';
                out += number(c[3]);
            }
        }
        out += "'/>\n";
    }
    out += lines    ? "      </IndexedLineSet>\n"
           : points ? "      </PointSet>\n"
                    : "      </IndexedFaceSet>\n";
    out += "    </Shape>\n  </Scene>\n</X3D>\n";
    return out;
}

} // namespace

std::optional<MeshFormat> meshFormatForPath(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".stl") return MeshFormat::Stl;
    if (ext == ".obj") return MeshFormat::Obj;
    if (ext == ".ply") return MeshFormat::Ply;
    if (ext == ".glb") return MeshFormat::Glb;
    if (ext == ".x3d") return MeshFormat::X3d;
    return std::nullopt;
}

std::string_view meshFormatName(MeshFormat f) {
    switch (f) {
    case MeshFormat::Stl:
        return "STL (binary)";
    case MeshFormat::Obj:
        return "OBJ";
    case MeshFormat::Ply:
        return "PLY (binary)";
    case MeshFormat::Glb:
        return "glTF 2.0 binary";
    case MeshFormat::X3d:
        return "X3D";
    }
    return "";
}

std::string encodeMesh(const Mesh& mesh, MeshFormat format) {
    switch (format) {
    case MeshFormat::Stl:
        return stl(mesh);
    case MeshFormat::Obj:
        return obj(mesh);
    case MeshFormat::Ply:
        return ply(mesh);
    case MeshFormat::Glb:
        return glb(mesh);
    case MeshFormat::X3d:
        return x3d(mesh);
    }
    return {};
}

bool writeMesh(const Mesh& mesh, const std::filesystem::path& path, std::string& error) {
    const auto format = meshFormatForPath(path);
    if (!format) {
        error = "unknown mesh format '" + path.extension().string() +
                "': use .stl, .obj, .ply, .glb or .x3d";
        return false;
    }
    if (*format == MeshFormat::Stl && mesh.isLines()) {
        error = "STL holds triangles only; write lines as .ply, .obj, .glb or .x3d";
        return false;
    }
    if (*format == MeshFormat::Stl && mesh.isPointCloud()) {
        error = "STL holds triangles only; write a point cloud as .ply, .obj, .glb or .x3d";
        return false;
    }
    return writeFileReplacing(path, encodeMesh(mesh, *format), error);
}

bool writeFileReplacing(const std::filesystem::path& path, std::string_view bytes,
                        std::string& error) {
    std::filesystem::path temporary = path;
    temporary += ".partial";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) {
            error = "cannot write " + path.string() + ": check the folder exists and is writable";
            return false;
        }
        out.write(bytes.data(), std::streamsize(bytes.size()));
        if (!out) {
            error = "writing " + path.string() + " failed (disk full?)";
            return false;
        }
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        error = "cannot write " + path.string() + ": " + ec.message();
        return false;
    }
    return true;
}

} // namespace fl::mesh
