#include "muparser_peer.h"

#include <stdexcept>

#ifdef FUNCTIONLAB_HAVE_MUPARSER
#include <muParser.h>

#include <cmath>
#include <vector>

#ifdef FUNCTIONLAB_HAVE_OPENMP
#include <omp.h>
#endif

namespace fl::bench {

struct MuParserPeer::Impl {
    mu::Parser parser;
    double x = 0, y = 0, z = 0, t = 0;
    std::vector<double> tArray;
};

bool MuParserPeer::available() {
    return true;
}

MuParserPeer::MuParserPeer(const std::string& expression) : impl_(std::make_unique<Impl>()) {
#ifdef FUNCTIONLAB_HAVE_OPENMP
    // every engine in the comparison runs on one thread
    omp_set_num_threads(1);
#endif
    try {
        impl_->parser.SetExpr(expression);
    } catch (const mu::Parser::exception_type& e) {
        throw std::runtime_error("muParser: " + e.GetMsg());
    }
}

MuParserPeer::~MuParserPeer() = default;

void MuParserPeer::evaluateBulk(const Grid& grid, double* out) {
    // bulk mode reads variable k of point i at address var + i
    impl_->tArray.assign(grid.size(), grid.t);
    mu::Parser& p = impl_->parser;
    p.ClearVar();
    p.DefineVar("x", const_cast<double*>(grid.x.data()));
    p.DefineVar("y", const_cast<double*>(grid.y.data()));
    p.DefineVar("z", const_cast<double*>(grid.z.data()));
    p.DefineVar("t", impl_->tArray.data());
    p.Eval(out, static_cast<int>(grid.size()));
}

void MuParserPeer::evaluatePerPoint(const Grid& grid, double* out) {
    mu::Parser& p = impl_->parser;
    p.ClearVar();
    p.DefineVar("x", &impl_->x);
    p.DefineVar("y", &impl_->y);
    p.DefineVar("z", &impl_->z);
    p.DefineVar("t", &impl_->t);
    impl_->t = grid.t;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        impl_->x = grid.x[i];
        impl_->y = grid.y[i];
        impl_->z = grid.z[i];
        out[i] = p.Eval();
    }
}

} // namespace fl::bench

#else

namespace fl::bench {
struct MuParserPeer::Impl {};
bool MuParserPeer::available() {
    return false;
}
MuParserPeer::MuParserPeer(const std::string&) {
    throw std::runtime_error("built without muParser");
}
MuParserPeer::~MuParserPeer() = default;
void MuParserPeer::evaluateBulk(const Grid&, double*) {}
void MuParserPeer::evaluatePerPoint(const Grid&, double*) {}
} // namespace fl::bench

#endif
