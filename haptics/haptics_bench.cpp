#include "haptics_bench.h"

#include "measure/percentiles.h"

#include "device/device_limits.h"
#include "field/ray_march.h"
#include "force_model.h"
#include "mesh/dual_contouring.h"
#include "pointer_device.h"
#include "scene/scene_reader.h"
#include "servo_loop.h"
#include "tangible_scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <thread>

namespace fl::haptics {

using field::Vec3;

namespace {

using Clock = std::chrono::steady_clock;

void percentiles(std::vector<double> us, TickCost& row) {
    if (us.empty()) return;
    const measure::Spread s = measure::spreadOf(std::move(us));
    row.p50Us = s.p50;
    row.p99Us = s.p99;
    row.p999Us = s.p999;
    row.maxUs = s.max;
}

// Ticks the model along `points` (scene coordinates) at 1 kHz, `passes`
// times; each tick timed alone. `error(tick, force sample)` says how far that
// tick's touch is from the true one (negative: not counted).
template <class Error>
TickCost walk(const std::string& name, std::shared_ptr<const TangibleScene> scene,
              const std::vector<Vec3>& points, double seconds, int passes, Error error) {
    TickCost row;
    row.name = name;
    std::vector<double> us;
    double errorSum = 0;
    std::size_t errorCount = 0;
    const double rate = 1000;
    for (int pass = 0; pass < passes; ++pass) {
        ForceModel model(settingsFor(limitsOf(DeviceModel::Simulated), rate));
        model.setScene(scene);
        const int ticks = int(seconds * rate);
        // Along the polyline at constant speed, by arc length.
        std::vector<double> at{0};
        for (std::size_t i = 1; i < points.size(); ++i)
            at.push_back(at.back() + field::length(field::minus(points[i], points[i - 1])));
        for (int k = 0; k <= ticks; ++k) {
            const double s = at.back() * double(k) / ticks;
            std::size_t i = 1;
            while (i + 1 < at.size() && at[i] < s)
                ++i;
            const double span = at[i] - at[i - 1];
            const Vec3 p = span > 0
                               ? field::along(points[i - 1], field::minus(points[i], points[i - 1]),
                                              (s - at[i - 1]) / span)
                               : points[i];
            const Vec3 v = field::scaled(field::minus(points[i], points[i - 1]),
                                         span > 0 ? at.back() / seconds / span : 0);
            const std::int64_t ns = std::int64_t(double(k) * 1e6);
            const auto begin = Clock::now();
            const ForceSample f = model.tick({p, v, {ns, ns, 0}});
            const auto end = Clock::now();
            us.push_back(std::chrono::duration<double, std::micro>(end - begin).count());
            ++row.ticks;
            if (f.contact == ContactKind::Surface) ++row.surfaceTicks;
            if (const double e = error(std::size_t(k), f); e >= 0) {
                errorSum += e;
                ++errorCount;
                row.maxError = std::max(row.maxError, e);
            }
            if (f.contact == ContactKind::Inside) ++row.insideTicks;
        }
    }
    percentiles(std::move(us), row);
    if (errorCount) row.meanError = errorSum / double(errorCount);
    return row;
}

std::unique_ptr<scene::Scene> read(const std::filesystem::path& file,
                                   std::vector<std::string>& notes) {
    scene::ReadResult r = scene::readSceneFile(file);
    if (!r.ok()) notes.push_back(file.string() + " could not be read");
    return std::move(r.scene);
}

// Corner to corner through the tangible shapes' boxes, and back.
std::vector<Vec3> throughShapes(const TangibleScene& t) {
    field::Box3 all{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
    for (const TangibleShape& s : t.shapes) {
        const field::Box3 b = field::boundsOf(s.container, s.toScene);
        for (std::size_t k = 0; k < 3; ++k) {
            all.lo[k] = std::min(all.lo[k], b.lo[k]);
            all.hi[k] = std::max(all.hi[k], b.hi[k]);
        }
    }
    const Vec3 c = field::scaled(field::plus(all.lo, all.hi), 0.5);
    return {all.lo, c, all.hi, {all.lo[0], all.hi[1], all.hi[2]}, c, all.lo};
}

} // namespace

std::vector<Vec3> pathUnderSurface(const field::ImplicitField& field, double depth) {
    // Rays from the box's faces' centres and corners towards its centre: where
    // each first meets the surface, a little under it.
    field::FieldSampler sampler(field);
    const Vec3 c = field::scaled(field::plus(field.box.lo, field.box.hi), 0.5);
    const double d = depth * field.box.diagonal();
    std::vector<Vec3> out;
    for (int i = 0; i < 26; ++i) {
        const int a = i < 13 ? i : i + 1; // the 26 neighbours of the middle of 3x3x3
        const Vec3 dir{double(a % 3) - 1, double(a / 3 % 3) - 1, double(a / 9) - 1};
        Vec3 from = c;
        for (std::size_t k = 0; k < 3; ++k)
            from[k] = dir[k] < 0 ? field.box.lo[k] : dir[k] > 0 ? field.box.hi[k] : c[k];
        field::MarchOptions mo;
        mo.limit = 1;
        const auto hit = field::marchToSurface(sampler, from, field::minus(c, from), mo);
        if (!hit || hit->onBoxFace) continue;
        if (out.empty()) out.push_back(field::along(hit->point, hit->normal, 2 * d)); // approach
        out.push_back(field::along(hit->point, hit->normal, -d));
    }
    return out;
}

std::vector<TickCost> touchSweep(const field::ImplicitField& field, const std::vector<Vec3>& path,
                                 const std::vector<double>& resolutions, int passes,
                                 const std::atomic<bool>* cancel,
                                 const std::function<void(const TickCost&)>& onRow,
                                 std::vector<std::string>* notes) {
    std::vector<TickCost> rows;
    if (path.size() < 2) return rows;
    // The shape as a surface with nothing else: contact alone is measured.
    TangibleScene scene;
    TangibleShape shape;
    shape.name = "shape";
    shape.field = std::make_shared<const field::ImplicitField>(field);
    shape.container = field.box;
    shape.geometryBox = field.box;
    shape.surface = true;
    scene.shapes.push_back(shape);
    // The function's touch is the true one: each polygon tick is compared with
    // it — the distance between the two proxies (a missed contact: the tool's
    // distance from the true proxy), a fraction of the box diagonal.
    const double diagonal = field.box.diagonal();
    field::FieldSampler sampler(field);
    std::vector<ForceSample> truth;
    auto onSurface = [&](std::size_t, const ForceSample& f) {
        if (truth.size() < 1u << 24) truth.push_back(f);
        if (f.contact != ContactKind::Surface) return -1.0;
        const formula::Dual d = sampler.gradient(f.proxy);
        const double g = field::length(d.d);
        return g > 0 ? std::abs(d.v) / g / diagonal : -1.0;
    };
    auto add = [&](TickCost row) {
        rows.push_back(row);
        if (onRow) onRow(row);
    };
    add(walk("function", std::make_shared<TangibleScene>(scene), path, 2, passes, onSurface));
    auto againstTruth = [&](std::size_t k, const ForceSample& f) {
        if (k >= truth.size()) return -1.0;
        const ForceSample& t = truth[k];
        if (t.contact != ContactKind::Surface && f.contact != ContactKind::Surface) return -1.0;
        return field::length(field::minus(f.proxy, t.proxy)) / diagonal;
    };
    for (double r : resolutions) {
        if (cancel && *cancel) break;
        mesh::MeshOptions mo;
        mo.resolution = r;
        mo.threads = 1;
        mo.cancel = cancel;
        const mesh::MeshResult m = mesh::meshImplicit(field, mo);
        if (!m.error.empty() || m.mesh.triangleCount() == 0) {
            if (notes)
                notes->push_back("polygons at " + std::to_string(r) + ": " +
                                 (m.error.empty() ? "no triangles" : m.error));
            continue;
        }
        TangibleScene polygons = scene;
        polygons.shapes.front().triangles = std::make_shared<const TriangleBvh>(m.mesh);
        char name[48];
        std::snprintf(name, sizeof name, "polygons at %g", r);
        TickCost row =
            walk(name, std::make_shared<TangibleScene>(polygons), path, 2, passes, againstTruth);
        row.resolution = r;
        row.triangles = m.mesh.triangleCount();
        add(row);
    }
    return rows;
}

HapticsBenchResult runHapticsBench(const HapticsBenchOptions& o) {
    HapticsBenchResult out;
    auto none = [](std::size_t, const ForceSample&) { return -1.0; };
    // 1. One force tick, per example scene.
    for (const auto& [name, file, at] :
         {std::tuple<const char*, const char*, double>{"watermelon", "watermelon.x3d", 0},
          {"fan", "fan.x3d", 0.25},
          {"shark", "shark.x3d", 0}}) {
        const auto scene = read(o.examples / file, out.notes);
        if (!scene) continue;
        auto t = std::make_shared<const TangibleScene>(makeTangibleScene(*scene, at));
        if (t->empty()) {
            out.notes.push_back(std::string(name) + ": nothing tangible");
            continue;
        }
        TickCost row = walk(name, t, throughShapes(*t), 2, o.passes, none);
        out.scenes.push_back(row);
    }

    // 2. Function against polygon contact on the watermelon's surface: a
    // circle 0.6 mm under the sphere's skin, clear of the cut.
    if (const auto melon = read(o.examples / "watermelon.x3d", out.notes)) {
        const TangibleScene whole = makeTangibleScene(*melon, 0);
        if (!whole.shapes.empty()) {
            std::vector<Vec3> path{{0.6, 0, -1.3}};
            for (int k = 0; k <= 64; ++k) {
                const double a = 2 * std::numbers::pi * k / 64;
                path.push_back({0.6 * std::cos(a), 0.6 * std::sin(a), -0.7995});
            }
            out.contact = touchSweep(*whole.shapes.front().field, path, o.resolutions, o.passes,
                                     nullptr, {}, &out.notes);
        }
    }

    // 3. The real-time loop: the mouse's device resting inside the watermelon.
    if (const auto melon = read(o.examples / "watermelon.x3d", out.notes)) {
        PointerDevice device(limitsOf(DeviceModel::Simulated));
        device.moveTo({0, 0, -0.9});
        ServoOptions so;
        so.rateHz = o.rateHz;
        ServoLoop loop(device, so);
        loop.setScene(std::make_shared<const TangibleScene>(makeTangibleScene(*melon, 0)));
        loop.start();
        std::this_thread::sleep_for(std::chrono::duration<double>(o.loopSeconds));
        loop.stop();
        const JitterFigures j = loop.jitter();
        const ServoStatus s = loop.status();
        out.loopRateHz = s.measuredRateHz;
        out.loopTicks = s.ticks;
        out.realTime = s.realTime;
        out.lateTicks = s.lateTicks;
        out.jitterP50Us = j.p50;
        out.jitterP99Us = j.p99;
        out.jitterP999Us = j.p999;
        out.jitterMaxUs = j.max;
    }
    return out;
}

namespace {

std::string fmt(const char* f, double v) {
    char b[64];
    std::snprintf(b, sizeof b, f, v);
    return b;
}

std::string rowJson(const TickCost& r) {
    std::string s =
        "{\"name\": \"" + r.name + "\", \"ticks\": " + std::to_string(r.ticks) +
        ", \"p50_us\": " + fmt("%.4g", r.p50Us) + ", \"p99_us\": " + fmt("%.4g", r.p99Us) +
        ", \"p999_us\": " + fmt("%.4g", r.p999Us) + ", \"max_us\": " + fmt("%.4g", r.maxUs) +
        ", \"surface_ticks\": " + std::to_string(r.surfaceTicks) +
        ", \"inside_ticks\": " + std::to_string(r.insideTicks);
    if (r.resolution > 0)
        s += ", \"resolution\": " + fmt("%g", r.resolution) +
             ", \"triangles\": " + std::to_string(r.triangles);
    if (r.meanError >= 0)
        s += ", \"mean_error\": " + fmt("%.3e", r.meanError) +
             ", \"max_error\": " + fmt("%.3e", r.maxError);
    return s + "}";
}

} // namespace

std::string hapticsBenchText(const HapticsBenchResult& r) {
    std::string s = "One force tick (µs), along a path through the tangible shapes:\n";
    s += "  scene            p50      p99    p99.9      max   ticks  surface  inside\n";
    for (const TickCost& t : r.scenes)
        s += "  " + t.name + std::string(15 - std::min<std::size_t>(15, t.name.size()), ' ') +
             fmt("%8.2f", t.p50Us) + " " + fmt("%8.2f", t.p99Us) + " " + fmt("%8.2f", t.p999Us) +
             " " + fmt("%8.2f", t.maxUs) + " " + fmt("%7.0f", double(t.ticks)) + " " +
             fmt("%8.0f", double(t.surfaceTicks)) + " " + fmt("%7.0f", double(t.insideTicks)) +
             "\n";
    s += "\nFunction against polygon contact, sliding on the watermelon (error: the function's\n"
         "row, the proxy's distance from the surface; the others', from the function's proxy,\n"
         "tick by tick; a fraction of the box diagonal):\n";
    s += "  contact          triangles      p50      p99    p99.9   mean error    max error\n";
    for (const TickCost& t : r.contact)
        s += "  " + t.name + std::string(16 - std::min<std::size_t>(16, t.name.size()), ' ') +
             fmt("%9.0f", double(t.triangles)) + " " + fmt("%8.2f", t.p50Us) + " " +
             fmt("%8.2f", t.p99Us) + " " + fmt("%8.2f", t.p999Us) + "   " +
             fmt("%10.2e", t.meanError) + "   " + fmt("%10.2e", t.maxError) + "\n";
    s += "\nThe real-time loop" +
         std::string(r.realTime ? " (real-time priority)" : " (no real-time priority granted)") +
         ": " + fmt("%.1f", r.loopRateHz) + " Hz over " + std::to_string(r.loopTicks) + " ticks (" +
         std::to_string(r.lateTicks) + " late); period jitter p50 " + fmt("%.1f", r.jitterP50Us) +
         " µs, p99 " + fmt("%.1f", r.jitterP99Us) + " µs, p99.9 " + fmt("%.1f", r.jitterP999Us) +
         " µs, max " + fmt("%.1f", r.jitterMaxUs) + " µs\n";
    for (const std::string& n : r.notes)
        s += "note: " + n + "\n";
    return s;
}

std::string hapticsBenchJson(const HapticsBenchResult& r) {
    std::string s = "{\"scenes\": [";
    for (std::size_t i = 0; i < r.scenes.size(); ++i)
        s += (i ? ", " : "") + rowJson(r.scenes[i]);
    s += "], \"contact\": [";
    for (std::size_t i = 0; i < r.contact.size(); ++i)
        s += (i ? ", " : "") + rowJson(r.contact[i]);
    s += "], \"loop\": {\"real_time_priority\": " + std::string(r.realTime ? "true" : "false") +
         ", \"rate_hz\": " + fmt("%.2f", r.loopRateHz) +
         ", \"ticks\": " + std::to_string(r.loopTicks) +
         ", \"late_ticks\": " + std::to_string(r.lateTicks) +
         ", \"jitter_p50_us\": " + fmt("%.2f", r.jitterP50Us) +
         ", \"jitter_p99_us\": " + fmt("%.2f", r.jitterP99Us) +
         ", \"jitter_p999_us\": " + fmt("%.2f", r.jitterP999Us) +
         ", \"jitter_max_us\": " + fmt("%.2f", r.jitterMaxUs) + "}}\n";
    return s;
}

} // namespace fl::haptics
