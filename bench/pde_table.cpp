#include "pde_table.h"

#include "measure/log_plot.h"
#include "mesh/obj_reader.h"
#include "mesh/surface_distance.h"
#include "pde/fit_measure.h"
#include "pde/mesh_fit.h"
#include "text/json_text.h"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace fl::bench {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

double diagonalOf(const mesh::Mesh& m) {
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (const auto& p : m.positions)
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], double(p[std::size_t(k)]));
            hi[k] = std::max(hi[k], double(p[std::size_t(k)]));
        }
    return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

// Draco at `bits` of position quantisation, the slowest and smallest
// setting (draco_encoder -cl 10); the bytes and the decoded mesh.
std::pair<std::size_t, mesh::Mesh> draco(const mesh::Mesh& m, int bits) {
    draco::TriangleSoupMeshBuilder builder;
    builder.Start(int(m.triangles.size()));
    const int pos = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    for (std::size_t f = 0; f < m.triangles.size(); ++f) {
        const auto& t = m.triangles[f];
        builder.SetAttributeValuesForFace(pos, draco::FaceIndex(std::uint32_t(f)),
                                          m.positions[t[0]].data(), m.positions[t[1]].data(),
                                          m.positions[t[2]].data());
    }
    const std::unique_ptr<draco::Mesh> dm = builder.Finalize();
    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, bits);
    encoder.SetSpeedOptions(0, 0);
    draco::EncoderBuffer buffer;
    if (!dm || !encoder.EncodeMeshToBuffer(*dm, &buffer).ok()) return {0, {}};
    draco::DecoderBuffer in;
    in.Init(buffer.data(), buffer.size());
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&in);
    mesh::Mesh out;
    if (!decoded.ok()) return {buffer.size(), out};
    const draco::Mesh& d = *decoded.value();
    const draco::PointAttribute* p = d.GetNamedAttribute(draco::GeometryAttribute::POSITION);
    for (std::uint32_t i = 0; i < d.num_points(); ++i) {
        mesh::Vec3f v{};
        p->GetMappedValue(draco::PointIndex(i), v.data());
        out.positions.push_back(v);
    }
    for (std::uint32_t f = 0; f < d.num_faces(); ++f) {
        const auto& face = d.face(draco::FaceIndex(f));
        out.triangles.push_back({face[0].value(), face[1].value(), face[2].value()});
    }
    return {buffer.size(), out};
}

// meshoptimizer's simplifier to `error` of the diagonal (its own unit is the
// mesh's extent, the largest side), unused vertices dropped.
mesh::Mesh simplified(const mesh::Mesh& m, double error, double diagonal) {
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (const auto& p : m.positions)
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], double(p[std::size_t(k)]));
            hi[k] = std::max(hi[k], double(p[std::size_t(k)]));
        }
    const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    std::vector<unsigned> indices;
    for (const auto& t : m.triangles)
        indices.insert(indices.end(), t.begin(), t.end());
    std::vector<unsigned> out(indices.size());
    const std::size_t n = meshopt_simplify(
        out.data(), indices.data(), indices.size(), &m.positions[0][0], m.positions.size(),
        sizeof(mesh::Vec3f), 0, float(error * diagonal / extent), 0, nullptr);
    mesh::Mesh s;
    std::vector<long> remap(m.positions.size(), -1);
    for (std::size_t i = 0; i + 2 < n; i += 3) {
        mesh::Triangle t{};
        for (int k = 0; k < 3; ++k) {
            long& r = remap[out[i + std::size_t(k)]];
            if (r < 0) {
                r = long(s.positions.size());
                s.positions.push_back(m.positions[out[i + std::size_t(k)]]);
            }
            t[std::size_t(k)] = std::uint32_t(r);
        }
        s.triangles.push_back(t);
    }
    return s;
}

std::string fixed(double v, const char* format) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

} // namespace

std::vector<PdeRow> runPdeBench(const std::string& path, const PdeBenchOptions& o,
                                std::string& why) {
    const mesh::ObjReadResult read = mesh::readObjFile(path);
    if (!read.ok()) {
        why = read.error;
        return {};
    }
    const mesh::Mesh& m = *read.mesh;
    const double diagonal = diagonalOf(m);
    std::vector<PdeRow> rows;
    std::error_code ec;
    rows.push_back(
        {"obj", "the file", std::size_t(std::filesystem::file_size(path, ec)), -1, -1, 0});
    auto measure = [&](PdeRow row, const mesh::Mesh& other) {
        const mesh::SurfaceDistance d = mesh::compareSurfaces(m, other, o.samples);
        row.rms = d.rms / diagonal;
        row.hausdorff = d.hausdorff / diagonal;
        rows.push_back(std::move(row));
    };
    auto pde = [&](pde::MeshFitOptions fo, const std::string& setting) {
        const auto started = Clock::now();
        std::string reason;
        const auto fit = pde::fitMesh(m, fo, &reason, &read.triangleLines);
        const double ms = msSince(started);
        if (!fit) {
            why = reason;
            return;
        }
        pde::MeasureOptions mo;
        mo.samples = o.samples;
        const auto measured = pde::measureFit(m, fit->model, mo, &why);
        if (!measured) return;
        rows.push_back({"pde",
                        setting + " (" + std::to_string(fit->model.patches.size()) + " patches)",
                        measured->bytes.size(), measured->distance.rms / diagonal,
                        measured->distance.hausdorff / diagonal, ms});
    };
    pde({}, "default --error");
    for (double p : o.patches) {
        pde::MeshFitOptions fo;
        fo.patches = std::size_t(p);
        fo.radii = o.radii;
        pde(fo, "--patches " + std::to_string(std::size_t(p)));
    }
    for (double bits : o.dracoBits) {
        const auto started = Clock::now();
        auto [bytes, decoded] = draco(m, int(bits));
        measure({"draco", "qp " + std::to_string(int(bits)), bytes, 0, 0, msSince(started)},
                decoded);
    }
    for (double e : o.simplifyErrors) {
        const auto started = Clock::now();
        const mesh::Mesh s = simplified(m, e, diagonal);
        auto [bytes, decoded] = draco(s, 11);
        measure({"simplify+draco",
                 "error " + fixed(e, "%g") + ", " + std::to_string(s.triangles.size()) +
                     " triangles, qp 11",
                 bytes, 0, 0, msSince(started)},
                decoded);
    }
    // The paper's figures are for this one mesh (the Stanford bunny, 539 KB as OBJ).
    if (std::filesystem::path(path).filename() == "bunny.obj") {
        rows.push_back({"paper", "bunny, 180 patches", 86000, -1, -1, 0});
        rows.push_back({"paper", "bunny, 250 patches", 120000, -1, -1, 0});
    }
    return rows;
}

std::string formatPdeTable(const std::string& mesh, const std::vector<PdeRow>& rows) {
    std::ostringstream o;
    o << mesh << " (errors: fractions of the diagonal; RMS and symmetric Hausdorff)\n";
    char line[256];
    std::snprintf(line, sizeof line, "%-16s %-40s %10s %10s %10s %10s\n", "method", "setting",
                  "bytes", "RMS %", "Hausdorff %", "ms");
    o << line;
    for (const PdeRow& r : rows) {
        std::snprintf(
            line, sizeof line, "%-16s %-40s %10zu %10s %10s %10.0f\n", r.method.c_str(),
            r.setting.c_str(), r.bytes, r.rms < 0 ? "-" : fixed(100 * r.rms, "%.3f").c_str(),
            r.hausdorff < 0 ? "-" : fixed(100 * r.hausdorff, "%.3f").c_str(), r.milliseconds);
        o << line;
    }
    return o.str();
}

std::string pdeRowsJson(const std::string& mesh, const std::vector<PdeRow>& rows) {
    std::ostringstream o;
    for (const PdeRow& r : rows)
        o << "{\"mesh\": " << text::jsonString(mesh)
          << ", \"method\": " << text::jsonString(r.method)
          << ", \"setting\": " << text::jsonString(r.setting) << ", \"bytes\": " << r.bytes
          << ", \"rms\": " << (r.rms < 0 ? "null" : fixed(r.rms, "%.6g"))
          << ", \"hausdorff\": " << (r.hausdorff < 0 ? "null" : fixed(r.hausdorff, "%.6g"))
          << ", \"ms\": " << fixed(r.milliseconds, "%.1f") << "}\n";
    return o.str();
}

std::string pdePlotSvg(const std::string& mesh, const std::vector<PdeRow>& rows) {
    const struct {
        const char* method;
        const char* name;
        const char* colour;
    } kinds[] = {{"pde", "PDE model (pde fit)", "#1f77b4"},
                 {"draco", "Draco (qp 7-14)", "#d62728"},
                 {"simplify+draco", "meshoptimizer + Draco", "#2ca02c"}};
    std::vector<measure::PlotSeries> series;
    for (const auto& k : kinds) {
        measure::PlotSeries& se = series.emplace_back(measure::PlotSeries{k.name, k.colour, {}});
        for (const PdeRow& r : rows)
            if (r.method == k.method && r.rms > 0)
                se.points.push_back({double(r.bytes), r.rms, r.setting});
        std::sort(
            se.points.begin(), se.points.end(),
            [](const measure::PlotPoint& a, const measure::PlotPoint& b) { return a.x < b.x; });
    }
    return measure::logLogPlotSvg("bytes against RMS error: " +
                                      std::filesystem::path(mesh).filename().string(),
                                  "bytes", "RMS distance / box diagonal", series);
}

} // namespace fl::bench
