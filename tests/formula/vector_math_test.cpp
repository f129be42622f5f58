// SLEEF behind vmath: each variant's arrays equal its own scalar routine bit
// for bit (what lets batch == scalar), and both stay within SLEEF's bound of
// the C library's correctly rounded-or-nearly results.
#include "formula/vector_math.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>
#include <vector>

namespace fl::formula::vmath {
namespace {

double ulpDistance(double a, double b) {
    if (std::isnan(a) && std::isnan(b)) return 0;
    if (a == b) return 0;
    if (!std::isfinite(a) || !std::isfinite(b)) return INFINITY;
    return std::abs(a - b) / std::abs(std::nextafter(b, INFINITY) - b);
}

std::vector<const Implementation*> variants() {
    std::vector<const Implementation*> v{&sse2Implementation()};
    if (avx2Implementation()) v.push_back(avx2Implementation());
    if (avx512Implementation()) v.push_back(avx512Implementation());
    return v;
}

bool sameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b) ||
           (std::isnan(a) && std::isnan(b));
}

TEST(VectorMath, ArraysEqualTheirScalarTwinsBitForBit) {
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> wide(-50, 50);
    const std::size_t n = 1003; // not a multiple of the lane count: tails too
    std::vector<double> a(n), b(n), out(n);
    for (std::size_t i = 0; i < n; ++i) {
        a[i] = wide(rng);
        b[i] = wide(rng);
    }
    a[0] = 0.0, a[1] = -0.0, a[2] = INFINITY, a[3] = NAN, a[4] = 1e300, a[5] = 1e-300;
    for (const Implementation* impl : variants()) {
        for (int f = 0; f < static_cast<int>(Unary::Count); ++f) {
            impl->unaryArray[f](a.data(), out.data(), n);
            for (std::size_t i = 0; i < n; ++i) {
                double s = impl->unary[f](a[i]);
                ASSERT_TRUE(sameBits(s, out[i])) << impl->name << " unary " << f << " at " << a[i];
            }
        }
        for (int f = 0; f < static_cast<int>(Binary::Count); ++f) {
            impl->binaryArray[f](a.data(), 0, nullptr, 2.5, out.data(), n);
            for (std::size_t i = 0; i < n; ++i) {
                double s = impl->binary[f](a[i], 2.5);
                ASSERT_TRUE(sameBits(s, out[i])) << impl->name << " binary " << f;
            }
            impl->binaryArray[f](nullptr, 1.5, b.data(), 0, out.data(), n);
            for (std::size_t i = 0; i < n; ++i) {
                double s = impl->binary[f](1.5, b[i]);
                ASSERT_TRUE(sameBits(s, out[i]));
            }
        }
    }
}

// sin, cos and tan go as whole vectors where every lane lies inside one of
// SLEEF's argument reductions (|x| < 15, or 15 to 1e14); a vector that mixes
// them has its lanes sorted by range into vectors of their own. Vectors made
// to sit in each range, on and across its edges, beside huge, infinite and
// NaN lanes, must all give the scalar twin's bits, in place too.
TEST(VectorMath, TrigonometryInEveryReductionRangeEqualsItsScalarTwin) {
    std::mt19937_64 rng(10);
    const double below15 = std::nextafter(15.0, 0.0), below1e14 = std::nextafter(1e14, 0.0);
    const double edges[] = {0,    1e-3,      11.9, 12,      12.1, 14.9, below15, 15,
                            15.1, 15.9,      16,   16.1,    100,  1e6,  1e12,    1.01e12,
                            1e13, below1e14, 1e14, 1.01e14, 1e17, 1e300};
    std::uniform_int_distribution<int> pick(0, int(std::size(edges)) - 1);
    std::uniform_real_distribution<double> jitter(0.999, 1.001), logMagnitude(-3, 20);
    const std::size_t n = 40000;
    std::vector<double> a(n), out(n);
    std::uniform_real_distribution<double> fast(-11.99, 11.99), logMedium(std::log10(16.0), 12),
        pastFast(15.0, 16.5);
    for (std::size_t i = 0; i < n; i += 8) {
        // a run of eight (one AVX-512 vector, two AVX2 ones, four SSE2 ones):
        // every lane in the fast range, every lane in the medium one, or mixed
        const int kind = int(i / 8 % 7);
        for (std::size_t k = 0; k < 8; ++k) {
            double v = kind == 0   ? edges[pick(rng)] * jitter(rng)
                       : kind == 1 ? std::pow(10.0, logMagnitude(rng))
                       : kind == 2 ? 16.0 + 1e3 * jitter(rng) * double(k)
                       : kind == 3 ? fast(rng)
                       : kind == 4 ? std::pow(10.0, logMedium(rng))
                       : kind == 5 ? edges[std::size_t(i / 8 + k) % std::size(edges)]
                       // lanes of every range in one vector, most near the fast one's edge
                       : rng() % 2 ? fast(rng) * 15.0 / 11.99
                       : rng() % 2 ? pastFast(rng)
                                   : std::pow(10.0, logMagnitude(rng));
            if (rng() % 2) v = -v;
            if (kind != 3 && kind != 4 && rng() % 97 == 0) v = rng() % 2 ? NAN : INFINITY;
            a[i + k] = v;
        }
    }
    for (const Implementation* impl : variants()) {
        for (const Unary f : {Unary::Sin, Unary::Cos, Unary::Tan}) {
            impl->unaryArray[static_cast<int>(f)](a.data(), out.data(), n);
            for (std::size_t i = 0; i < n; ++i) {
                const double s = impl->unary[static_cast<int>(f)](a[i]);
                ASSERT_TRUE(sameBits(s, out[i]))
                    << impl->name << " unary " << int(f) << " at " << a[i] << " (lane " << i << ")";
            }
            // in place (the batch evaluator may write a step over its operand)
            std::vector<double> inPlace = a;
            impl->unaryArray[static_cast<int>(f)](inPlace.data(), inPlace.data(), n);
            for (std::size_t i = 0; i < n; ++i)
                ASSERT_TRUE(sameBits(inPlace[i], out[i])) << impl->name << " in place, lane " << i;
        }
        // sincos: the same reductions, two results
        std::vector<double> sines(n), cosines(n);
        impl->sinCosArray(a.data(), sines.data(), cosines.data(), n);
        for (std::size_t i = 0; i < n; ++i) {
            const SinCos s = impl->sinCos(a[i]);
            ASSERT_TRUE(sameBits(s.sin, sines[i]) && sameBits(s.cos, cosines[i]))
                << impl->name << " sincos at " << a[i] << " (lane " << i << ")";
        }
        for (const bool sineInPlace : {true, false}) {
            std::vector<double> inPlace = a, other(n);
            impl->sinCosArray(inPlace.data(), sineInPlace ? inPlace.data() : other.data(),
                              sineInPlace ? other.data() : inPlace.data(), n);
            for (std::size_t i = 0; i < n; ++i)
                ASSERT_TRUE(sameBits(inPlace[i], sineInPlace ? sines[i] : cosines[i]) &&
                            sameBits(other[i], sineInPlace ? cosines[i] : sines[i]))
                    << impl->name << " sincos in place, lane " << i;
        }
    }
}

// A CPU with AVX-512 must give the bits a CPU with only AVX2 gives: the
// 512-bit arrays keep the AVX2 variant's scalar routines as their twin.
TEST(VectorMath, Avx512GivesTheAvx2VariantsBits) {
    if (!avx512Implementation()) GTEST_SKIP() << "this CPU has no AVX-512F";
    const Implementation& wide = *avx512Implementation();
    const Implementation& avx2 = *avx2Implementation();
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> logMagnitude(-8, 14);
    const std::size_t n = 4099;
    std::vector<double> a(n), b(n), outWide(n), outAvx2(n);
    for (std::size_t i = 0; i < n; ++i) {
        a[i] = std::pow(10.0, logMagnitude(rng)) * (rng() % 2 ? 1 : -1);
        b[i] = std::pow(10.0, logMagnitude(rng) / 4) * (rng() % 2 ? 1 : -1);
    }
    // SLEEF's 512-bit log and pow take exponent and mantissa apart by
    // instructions of their own: subnormals, zeros, infinities, NaN and
    // results that overflow or underflow too.
    const double specials[] = {
        0.0,   -0.0,   5e-324, -5e-324, 1e-310, 2.2250738585072014e-308, INFINITY, -INFINITY, NAN,
        710.0, -745.5, 1e308,  -1e308,  1.0};
    for (std::size_t i = 0; i < std::size(specials); ++i) {
        a[i] = specials[i];
        b[std::size(specials) - 1 - i] = specials[i];
        a[n - 1 - i] = specials[i] * 0.5;
    }
    for (int f = 0; f < static_cast<int>(Unary::Count); ++f) {
        wide.unaryArray[f](a.data(), outWide.data(), n);
        avx2.unaryArray[f](a.data(), outAvx2.data(), n);
        for (std::size_t i = 0; i < n; ++i) {
            ASSERT_TRUE(sameBits(outWide[i], outAvx2[i])) << "unary " << f << " at " << a[i];
            ASSERT_TRUE(sameBits(wide.unary[f](a[i]), avx2.unary[f](a[i])));
        }
    }
    std::vector<double> cosWide(n), cosAvx2(n);
    wide.sinCosArray(a.data(), outWide.data(), cosWide.data(), n);
    avx2.sinCosArray(a.data(), outAvx2.data(), cosAvx2.data(), n);
    for (std::size_t i = 0; i < n; ++i)
        ASSERT_TRUE(sameBits(outWide[i], outAvx2[i]) && sameBits(cosWide[i], cosAvx2[i]))
            << "sincos at " << a[i];
    for (int f = 0; f < static_cast<int>(Binary::Count); ++f) {
        wide.binaryArray[f](a.data(), 0, b.data(), 0, outWide.data(), n);
        avx2.binaryArray[f](a.data(), 0, b.data(), 0, outAvx2.data(), n);
        for (std::size_t i = 0; i < n; ++i)
            ASSERT_TRUE(sameBits(outWide[i], outAvx2[i]))
                << "binary " << f << " at " << a[i] << ", " << b[i];
    }
}

TEST(VectorMath, WithinTwoUlpsOfTheCLibrary) {
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> unit(-1, 1), wide(-20, 20), pos(1e-3, 50);
    double (*ref[])(double) = {std::sin,  std::cos,  std::tan,  std::asin, std::acos,
                               std::atan, std::exp,  std::log,  std::log2, std::log10,
                               std::sinh, std::cosh, std::tanh, std::cbrt};
    for (const Implementation* impl : variants()) {
        for (int f = 0; f < static_cast<int>(Unary::Count); ++f) {
            for (int k = 0; k < 2000; ++k) {
                Unary u = static_cast<Unary>(f);
                double x = (u == Unary::Asin || u == Unary::Acos)                       ? unit(rng)
                           : (u == Unary::Log || u == Unary::Log2 || u == Unary::Log10) ? pos(rng)
                                                                                        : wide(rng);
                ASSERT_LE(ulpDistance(impl->unary[f](x), ref[f](x)), 2.0)
                    << impl->name << " " << f << " " << x;
            }
        }
        for (int k = 0; k < 2000; ++k) {
            const double x = wide(rng);
            const SinCos s = impl->sinCos(x);
            ASSERT_LE(ulpDistance(s.sin, std::sin(x)), 2.0) << impl->name << " sincos " << x;
            ASSERT_LE(ulpDistance(s.cos, std::cos(x)), 2.0) << impl->name << " sincos " << x;
        }
        for (int k = 0; k < 2000; ++k) {
            double y = wide(rng), x = wide(rng), p = pos(rng);
            ASSERT_LE(ulpDistance(impl->binary[int(Binary::Atan2)](y, x), std::atan2(y, x)), 2.0);
            ASSERT_LE(ulpDistance(impl->binary[int(Binary::Pow)](p, y), std::pow(p, y)), 2.0);
        }
    }
}

TEST(VectorMath, SpecialValuesFollowC99) {
    const Implementation& m = implementation();
    auto U = [&](Unary f, double x) { return m.unary[int(f)](x); };
    EXPECT_EQ(U(Unary::Log, 0.0), -INFINITY);
    EXPECT_TRUE(std::isnan(U(Unary::Log, -1.0)));
    EXPECT_TRUE(std::isnan(U(Unary::Sin, INFINITY)));
    EXPECT_TRUE(std::signbit(U(Unary::Sin, -0.0)));
    EXPECT_TRUE(std::signbit(m.sinCos(-0.0).sin));
    EXPECT_EQ(m.sinCos(-0.0).cos, 1.0);
    EXPECT_TRUE(std::isnan(m.sinCos(INFINITY).sin) && std::isnan(m.sinCos(-INFINITY).cos));
    EXPECT_TRUE(std::isnan(m.sinCos(NAN).sin) && std::isnan(m.sinCos(NAN).cos));
    EXPECT_EQ(U(Unary::Exp, 1000.0), INFINITY);
    EXPECT_EQ(U(Unary::Exp, -1000.0), 0.0);
    EXPECT_EQ(U(Unary::Cbrt, -8.0), -2.0);
    EXPECT_EQ(m.binary[int(Binary::Pow)](NAN, 0.0), 1.0);
    EXPECT_EQ(m.binary[int(Binary::Pow)](1.0, NAN), 1.0);
    EXPECT_EQ(m.binary[int(Binary::Pow)](-2.0, 3.0), -8.0);
    EXPECT_TRUE(std::isnan(m.binary[int(Binary::Pow)](-8.0, 1.0 / 3.0)));
}

} // namespace
} // namespace fl::formula::vmath
