#pragma once
// Registers for a tape's values by liveness, shared by the tape builder and
// the simplifier (tape_simplify.h): a register freed by a value's last use is
// the next one taken. An instruction takes its output register before its
// operands' are released, so it never writes a register it reads (the batch
// loops and the gradient rows rely on that to run without alias checks).
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace fl::formula {

class RegisterPool {
  public:
    explicit RegisterPool(std::int32_t first) : next_(first) {}

    std::int32_t take() {
        if (free_.empty()) return next_++;
        const std::int32_t r = free_.back();
        free_.pop_back();
        return r;
    }
    // The registers of the operands that die at an instruction (-1: none),
    // each released once, in operand order.
    void release(const std::array<std::int32_t, 3>& dying) {
        for (std::size_t k = 0; k < dying.size(); ++k)
            if (dying[k] >= 0 && std::find(dying.begin(), dying.begin() + std::ptrdiff_t(k),
                                           dying[k]) == dying.begin() + std::ptrdiff_t(k))
                free_.push_back(dying[k]);
    }
    void release(std::int32_t r) { free_.push_back(r); }
    // Registers used so far (the tape's registerCount).
    std::int32_t count() const { return next_; }

  private:
    std::int32_t next_;
    std::vector<std::int32_t> free_;
};

} // namespace fl::formula
