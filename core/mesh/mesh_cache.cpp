#include "mesh_cache.h"

#include <cstring>

namespace fl::mesh {
namespace {

void append(std::string& key, const void* data, std::size_t n) {
    key.append(static_cast<const char*>(data), n);
}
template <class T>
void append(std::string& key, const T& value) {
    append(key, &value, sizeof value);
}

void appendTape(std::string& key, const formula::Tape& tape) {
    append(key, tape.code.size());
    for (const formula::Instruction& i : tape.code) {
        append(key, i.op);
        append(key, i.out);
        for (const formula::Operand* o : {&i.a, &i.b, &i.c}) {
            append(key, o->reg);
            append(key, o->value);
        }
        append(key, i.imm0);
        append(key, i.imm1);
    }
    for (const formula::OutputInfo& o : tape.outputs) {
        append(key, o.value.reg);
        append(key, o.value.value);
    }
    for (const formula::ParameterInfo& p : tape.params) {
        key += p.name;
        append(key, p.defaultValue);
    }
}

bool readsTime(const ImplicitField& f) {
    const auto t = std::size_t(formula::Input::T);
    return f.tape.usesInput[t] || (f.displacement && f.displacement->tape.usesInput[t]);
}

} // namespace

std::size_t meshBytes(const Mesh& m) {
    return m.positions.size() * sizeof(Vec3f) + m.normals.size() * sizeof(Vec3f) +
           m.colours.size() * sizeof(m.colours[0]) + m.parameters.size() * sizeof(m.parameters[0]) +
           m.texCoords.size() * sizeof(m.texCoords[0]) + m.segments.size() * sizeof(Segment) +
           m.triangles.size() * sizeof(Triangle) + sizeof(MeshResult);
}

std::string MeshCache::keyOf(const ImplicitField& f, double resolution) {
    std::string key;
    appendTape(key, f.tape);
    append(key, f.box);
    append(key, f.boundary);
    append(key, resolution);
    // Time enters the key only when the geometry depends on it.
    const double t = readsTime(f) ? f.t : 0.0;
    append(key, t);
    for (const auto& [name, v] : f.parameters) {
        key += name;
        append(key, v);
    }
    if (f.displacement) {
        key += "displacement";
        appendTape(key, f.displacement->tape);
        append(key, f.displacement->componentBox);
    }
    return key;
}

std::string MeshCache::keyOf(const ParametricField& f, const ParametricOptions& o,
                             std::size_t points) {
    std::string key = "parametric";
    appendTape(key, f.tape);
    append(key, f.ranges);
    append(key, f.box);
    append(key, o.resolution);
    append(key, o.adaptive);
    append(key, o.tolerance);
    append(key, o.tubeRadius);
    append(key, o.tubeSides);
    append(key, points);
    const double t = f.tape.usesInput[std::size_t(formula::Input::T)] ? f.t : 0.0;
    append(key, t);
    for (const auto& [name, v] : f.parameters) {
        key += name;
        append(key, v);
    }
    return key;
}

std::shared_ptr<const MeshResult> MeshCache::get(const ImplicitField& field, double resolution,
                                                 const std::function<MeshResult()>& make) {
    return get(keyOf(field, resolution), make);
}

std::shared_ptr<const MeshResult> MeshCache::get(const std::string& key,
                                                 const std::function<MeshResult()>& make) {
    std::shared_ptr<std::mutex> gate;
    {
        std::lock_guard lock(mutex_);
        if (auto it = index_.find(key); it != index_.end()) {
            lru_.splice(lru_.begin(), lru_, it->second);
            ++hits_;
            return it->second->mesh;
        }
        auto& g = making_[key];
        if (!g) g = std::make_shared<std::mutex>();
        gate = g;
    }
    // One maker per key; others wait for it and then find the mesh.
    std::lock_guard making(*gate);
    {
        std::lock_guard lock(mutex_);
        if (auto it = index_.find(key); it != index_.end()) {
            lru_.splice(lru_.begin(), lru_, it->second);
            ++hits_;
            return it->second->mesh;
        }
        ++misses_;
    }
    auto result = std::make_shared<const MeshResult>(make());
    std::lock_guard lock(mutex_);
    making_.erase(key);
    if (!result->ok()) return result; // errors and cancellations are not kept
    const std::size_t bytes = meshBytes(result->mesh);
    lru_.push_front({key, result, bytes});
    index_[key] = lru_.begin();
    bytes_ += bytes;
    evict();
    return result;
}

std::shared_ptr<const MeshResult> MeshCache::mesh(const ImplicitField& field, double resolution,
                                                  MeshOptions options) {
    options.resolution = resolution;
    return get(field, resolution, [&] { return meshImplicit(field, options); });
}

void MeshCache::evict() {
    // Keep at least the newest mesh, whatever its size.
    while (bytes_ > budget_ && lru_.size() > 1) {
        bytes_ -= lru_.back().bytes;
        index_.erase(lru_.back().key);
        lru_.pop_back();
    }
}

std::size_t MeshCache::size() const {
    std::lock_guard lock(mutex_);
    return lru_.size();
}

std::size_t MeshCache::bytes() const {
    std::lock_guard lock(mutex_);
    return bytes_;
}

void MeshCache::clear() {
    std::lock_guard lock(mutex_);
    lru_.clear();
    index_.clear();
    bytes_ = 0;
}

} // namespace fl::mesh
