#pragma once
// muParser as a benchmark peer (never a dependency of the product itself).
#include "eval_formulas.h"

#include <memory>
#include <string>

namespace fl::bench {

class MuParserPeer {
  public:
    static bool available();
    // Throws std::runtime_error with muParser's message when it cannot parse.
    explicit MuParserPeer(const std::string& expression);
    ~MuParserPeer();
    void evaluateBulk(const Grid& grid, double* out);
    void evaluatePerPoint(const Grid& grid, double* out);

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace fl::bench
