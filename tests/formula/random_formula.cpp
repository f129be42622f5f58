#include "random_formula.h"

#include <array>
#include <sstream>

namespace fl::formula::testing {

namespace {
std::string leaf(std::mt19937_64& rng) {
    static const std::array<const char*, 7> names = {"x", "y", "z", "x", "y", "z", "t"};
    std::uniform_int_distribution<int> pick(0, 9);
    int k = pick(rng);
    if (k < 7) return names[k];
    std::uniform_real_distribution<double> value(-3.0, 3.0);
    std::ostringstream os;
    os.precision(17);
    os << "(" << value(rng) << ")";
    return os.str();
}
} // namespace

std::string randomFormula(std::mt19937_64& rng, int depth) {
    if (depth <= 0) return leaf(rng);
    static const std::array<const char*, 17> unary = {
        "sin", "cos",  "exp", "log",  "sqrt", "abs",  "atan", "tanh", "floor",
        "-",   "cbrt", "tan", "asin", "acos", "cosh", "sinh", "sign"};
    static const std::array<const char*, 12> binaryOps = {"+", "-",  "*", "/",  "^",  "&",
                                                          "|", "\\", "<", ">=", "&&", "||"};
    static const std::array<const char*, 8> binaryFns = {"min", "max",        "atan2",  "hypot",
                                                         "mod", "rintersect", "runion", "pow"};
    std::uniform_int_distribution<int> kind(0, 9);
    int k = kind(rng);
    auto sub = [&]() { return randomFormula(rng, depth - 1); };
    if (k == 0) return leaf(rng);
    if (k <= 2) {
        const char* f = unary[std::uniform_int_distribution<std::size_t>(0, unary.size() - 1)(rng)];
        const std::string fn = f;
        // a sine and a cosine of one value: the tape pairs them (one sincos)
        if ((fn == "sin" || fn == "cos") && kind(rng) < 4) {
            const std::string e = sub();
            return "(sin(" + e + ") " + (kind(rng) < 5 ? "*" : "-") + " cos(" + e + "))";
        }
        return fn + "(" + sub() + ")";
    }
    if (k <= 5) {
        const char* op =
            binaryOps[std::uniform_int_distribution<std::size_t>(0, binaryOps.size() - 1)(rng)];
        std::string rhs = sub();
        if (std::string(op) == "^") {
            // integer powers are the common case; keep some general ones
            std::uniform_int_distribution<int> e(-3, 4);
            if (kind(rng) < 7) rhs = std::to_string(e(rng));
        }
        return "(" + sub() + " " + op + " " + rhs + ")";
    }
    if (k <= 7) {
        const char* f =
            binaryFns[std::uniform_int_distribution<std::size_t>(0, binaryFns.size() - 1)(rng)];
        std::string extra;
        if ((std::string(f) == "rintersect" || std::string(f) == "runion") && kind(rng) < 4)
            extra = ", " + std::to_string(std::uniform_int_distribution<int>(1, 2)(rng));
        return std::string(f) + "(" + sub() + ", " + sub() + extra + ")";
    }
    if (k == 8) return "(" + sub() + " ? " + sub() + " : " + sub() + ")";
    return "noise(" + sub() + ", " + sub() + ", " + sub() + ")";
}

} // namespace fl::formula::testing
