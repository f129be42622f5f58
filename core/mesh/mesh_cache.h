#pragma once
// Meshes kept for reuse, keyed by what determines them: the definition (its
// compiled tape), the domain box and boundary, the displacement, the parameter
// values, the resolution and — only when the geometry reads t — the time. So a
// clock's hands (t only in their transforms) are meshed once, while a morphing
// shape is meshed per moment. Least recently used meshes go first when the
// byte budget is exceeded. Thread-safe; a mesh being made is made once even if
// two threads ask for it together.
#include "dual_contouring.h"
#include "parametric.h"

#include <atomic>
#include <cstddef>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

namespace fl::mesh {

class MeshCache {
  public:
    explicit MeshCache(std::size_t budgetBytes = 512u << 20) : budget_(budgetBytes) {}

    // The cached mesh, or `make()`'s result (stored when it succeeded).
    std::shared_ptr<const MeshResult> get(const ImplicitField& field, double resolution,
                                          const std::function<MeshResult()>& make);
    // The same for any key (keyOf below).
    std::shared_ptr<const MeshResult> get(const std::string& key,
                                          const std::function<MeshResult()>& make);
    // Convenience: meshImplicit with `options` at `resolution`.
    std::shared_ptr<const MeshResult> mesh(const ImplicitField& field, double resolution,
                                           MeshOptions options = {});

    std::size_t size() const;
    std::size_t bytes() const;
    std::size_t hits() const { return hits_; }
    std::size_t misses() const { return misses_; }
    void clear();

    // The key's text: exposed for tests.
    static std::string keyOf(const ImplicitField& field, double resolution);
    // A parametric object's (`points` > 0: as a cloud of that many points).
    static std::string keyOf(const ParametricField& field, const ParametricOptions& options,
                             std::size_t points = 0);

  private:
    struct Entry {
        std::string key;
        std::shared_ptr<const MeshResult> mesh;
        std::size_t bytes = 0;
    };
    void evict();

    std::size_t budget_;
    mutable std::mutex mutex_;
    std::list<Entry> lru_; // most recent first
    std::unordered_map<std::string, std::list<Entry>::iterator> index_;
    std::unordered_map<std::string, std::shared_ptr<std::mutex>> making_;
    std::size_t bytes_ = 0;
    std::atomic<std::size_t> hits_{0}, misses_{0}; // read without the lock (viewer counters)
};

std::size_t meshBytes(const Mesh& mesh);

} // namespace fl::mesh
