#pragma once
// Compiled code, shared: every thread's evaluator of one formula (a mesher
// runs several) uses one copy, made once. Code and its constants are never
// written after they are made, so sharing is safe. Keyed by text that
// identifies what was compiled exactly; the oldest of kEntries goes first
// (evaluators holding it keep their copy).
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

namespace fl::formula {

template <class Code>
class JitCache {
  public:
    static constexpr std::size_t kEntries = 256;

    std::shared_ptr<const Code> find(const std::string& key) {
        std::lock_guard lock(mutex_);
        auto it = byKey_.find(key);
        return it == byKey_.end() ? nullptr : it->second;
    }
    // Keeps `made` under `key`, or returns what another thread kept there first.
    std::shared_ptr<const Code> keep(std::string key, std::shared_ptr<const Code> made) {
        std::lock_guard lock(mutex_);
        auto [it, added] = byKey_.emplace(std::move(key), std::move(made));
        if (added) {
            order_.push_back(it->first);
            if (order_.size() > kEntries) {
                byKey_.erase(order_.front());
                order_.erase(order_.begin());
            }
        }
        return it->second;
    }

  private:
    std::mutex mutex_;
    std::unordered_map<std::string, std::shared_ptr<const Code>> byKey_;
    std::vector<std::string> order_; // oldest first
};

// Appends v's bytes to a key (numbers by their bits).
template <class T>
void appendKey(std::string& key, const T& v) {
    key.append(reinterpret_cast<const char*>(&v), sizeof v);
}

} // namespace fl::formula
