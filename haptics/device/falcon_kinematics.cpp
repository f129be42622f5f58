#include "device/falcon_kinematics.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fl::haptics::falcon {

using field::Vec3;

namespace {

// Stamper's geometry of the Falcon, in metres (libnifalcon FalconGeometry).
constexpr double kThigh = 0.060;       // a: hip to knee
constexpr double kShin = 0.1025;       // b: parallelogram side
constexpr double kEffectorU = 0.01443; // c: shin joint to effector centre, u
constexpr double kShinJoint = 0.01125; // d: shin to effector joint
constexpr double kKneeJoint = 0.01125; // e: knee to shin joint
constexpr double kEffectorV = -0.025;  // f: shin joint to effector centre, v
constexpr double kHipU = 0.0400;       // r: origin to hip, u
constexpr double kHipV = -0.02309;     // s: origin to hip, v
// The legs sit 120° apart, the whole arm turned 15° from the desk plane.
constexpr double kTilt = std::numbers::pi / 12;
constexpr std::array<double, 3> kLegAngle{
    std::numbers::pi / 2 + kTilt, -std::numbers::pi / 6 + kTilt, -5 * std::numbers::pi / 6 + kTilt};

// Encoders: 320 slots in quadrature (1280 counts a turn) on a 14.25 mm
// shaft that rolls on a 110 mm arc; count 0 is about 35° of thigh angle.
constexpr double kDegreesPerCount = 360.0 * 0.01425 / (4 * 320 * 0.110);
constexpr double kAngleAtZero = 35.0;

constexpr double kMotorCountsPerNewtonMetre = 10000;
constexpr double kMotorLimit = 32767;

// A leg's own frame: the effector point seen from leg i's hip.
Vec3 legFrame(const Vec3& p, int leg) {
    const double cp = std::cos(kLegAngle[leg]);
    const double sp = std::sin(kLegAngle[leg]);
    return {cp * p[0] + sp * p[1] - kHipU, -sp * p[0] + cp * p[1] - kHipV, p[2]};
}

struct LegPose {
    double theta1; // thigh
    double cos3;   // cos θ3 of the parallelogram
    double sin3;   // sin θ3 ≥ 0
    double reach;  // L = d + e + b sin θ3
};

std::optional<LegPose> legPose(const Vec3& P) {
    const double cos3 = (P[1] + kEffectorV) / kShin;
    if (!(std::abs(cos3) <= 1)) return std::nullopt;
    const double sin3 = std::sqrt(1 - cos3 * cos3);
    const double reach = kShinJoint + kKneeJoint + kShin * sin3;
    // The knee lies at distance a from the hip and `reach` from Q.
    const double qu = P[0] + kEffectorU;
    const double qw = P[2];
    const double q = std::hypot(qu, qw);
    if (!(q > 0)) return std::nullopt;
    const double cosKnee = (kThigh * kThigh + q * q - reach * reach) / (2 * kThigh * q);
    if (!(std::abs(cosKnee) <= 1)) return std::nullopt;
    // Of the two knees, the Falcon's is the one turned towards −θ.
    return LegPose{std::atan2(qw, qu) - std::acos(cosKnee), cos3, sin3, reach};
}

double maxAbs(const Vec3& v) {
    return std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
}

} // namespace

double encoderToAngle(double counts) {
    return (counts * kDegreesPerCount + kAngleAtZero) * (std::numbers::pi / 180);
}

double angleToEncoder(double angle) {
    return (angle * (180 / std::numbers::pi) - kAngleAtZero) / kDegreesPerCount;
}

std::optional<Vec3> thighAngles(const Vec3& position) {
    if (!field::isFinite(position)) return std::nullopt;
    Vec3 angles{};
    for (int leg = 0; leg < 3; ++leg) {
        const auto pose = legPose(legFrame(position, leg));
        if (!pose) return std::nullopt;
        angles[leg] = pose->theta1;
    }
    return angles;
}

std::optional<Mat3> angleJacobian(const Vec3& position) {
    if (!field::isFinite(position)) return std::nullopt;
    Mat3 J{};
    for (int leg = 0; leg < 3; ++leg) {
        const Vec3 P = legFrame(position, leg);
        const auto pose = legPose(P);
        if (!pose || !(pose->sin3 > 1e-9)) return std::nullopt;
        // Implicit differentiation of the leg's closure
        //   g = (P_u + c − a cos θ1)² + (P_w − a sin θ1)² − L(P_v)² = 0.
        const double c1 = std::cos(pose->theta1);
        const double s1 = std::sin(pose->theta1);
        const double du = 2 * (P[0] + kEffectorU - kThigh * c1);
        const double dw = 2 * (P[2] - kThigh * s1);
        const double dv = 2 * pose->reach * pose->cos3 / pose->sin3; // −2L·dL/dP_v
        const double dTheta = 2 * kThigh * ((P[0] + kEffectorU) * s1 - P[2] * c1);
        if (!(std::abs(dTheta) > 1e-12)) return std::nullopt;
        const double gu = -du / dTheta;
        const double gv = -dv / dTheta;
        const double gw = -dw / dTheta;
        // Chain through the leg frame's rotation.
        const double cp = std::cos(kLegAngle[leg]);
        const double sp = std::sin(kLegAngle[leg]);
        J[leg] = {gu * cp - gv * sp, gu * sp + gv * cp, gw};
    }
    return J;
}

Vec3 multiply(const Mat3& m, const Vec3& v) {
    return {field::dot(m[0], v), field::dot(m[1], v), field::dot(m[2], v)};
}

Mat3 transpose(const Mat3& m) {
    return {
        {{m[0][0], m[1][0], m[2][0]}, {m[0][1], m[1][1], m[2][1]}, {m[0][2], m[1][2], m[2][2]}}};
}

std::optional<Mat3> inverse(const Mat3& m) {
    // Rows of the inverse's transpose are cross products of the rows.
    const Vec3 c0 = field::cross(m[1], m[2]);
    const Vec3 c1 = field::cross(m[2], m[0]);
    const Vec3 c2 = field::cross(m[0], m[1]);
    const double det = field::dot(m[0], c0);
    const double scale = maxAbs(m[0]) * maxAbs(m[1]) * maxAbs(m[2]);
    if (!(std::abs(det) > 1e-12 * scale) || !std::isfinite(det)) return std::nullopt;
    return transpose(
        {field::scaled(c0, 1 / det), field::scaled(c1, 1 / det), field::scaled(c2, 1 / det)});
}

std::optional<Vec3> effectorPosition(const Vec3& angles, const Vec3& guess) {
    if (!field::isFinite(angles)) return std::nullopt;
    constexpr double kTolerance = 1e-9; // rad
    constexpr int kMaxSteps = 50;
    Vec3 x = guess;
    std::optional<Vec3> at = thighAngles(x);
    if (!at) {
        x = kWorkspaceCentre;
        at = thighAngles(x);
    }
    if (!at) return std::nullopt;
    Vec3 residual = field::minus(angles, *at);
    for (int step = 0; step < kMaxSteps; ++step) {
        if (maxAbs(residual) < kTolerance) return x;
        const auto J = angleJacobian(x);
        if (!J) return std::nullopt;
        const auto Jinv = inverse(*J);
        if (!Jinv) return std::nullopt;
        const Vec3 dx = multiply(*Jinv, residual);
        // Backtrack along the Newton step until the residual shrinks: far
        // from the answer, or near the reach's edge, a full step can leave
        // what the legs can reach.
        bool improved = false;
        for (double lambda = 1; lambda >= 1.0 / 1024; lambda /= 2) {
            const Vec3 next = field::along(x, dx, lambda);
            const auto nextAngles = thighAngles(next);
            if (!nextAngles) continue;
            const Vec3 nextResidual = field::minus(angles, *nextAngles);
            if (maxAbs(nextResidual) < maxAbs(residual)) {
                x = next;
                residual = nextResidual;
                improved = true;
                break;
            }
        }
        if (!improved) return std::nullopt;
    }
    return maxAbs(residual) < kTolerance ? std::optional<Vec3>(x) : std::nullopt;
}

std::optional<Vec3> jointTorques(const Vec3& position, const Vec3& force) {
    if (!field::isFinite(force)) return std::nullopt;
    const auto J = angleJacobian(position);
    if (!J) return std::nullopt;
    const auto Jinv = inverse(*J);
    if (!Jinv) return std::nullopt;
    // Virtual work: τ · δθ = F · δp with δθ = J δp, so τ = J⁻ᵀ F.
    return multiply(transpose(*Jinv), force);
}

std::array<std::int16_t, 3> motorValues(const Vec3& torques) {
    if (!field::isFinite(torques)) return {0, 0, 0};
    // The motors turn the legs the other way from θ for a positive drive.
    Vec3 drive = field::scaled(torques, -kMotorCountsPerNewtonMetre);
    const double largest = maxAbs(drive);
    if (largest > kMotorLimit) drive = field::scaled(drive, kMotorLimit / largest);
    std::array<std::int16_t, 3> values{};
    for (int i = 0; i < 3; ++i)
        values[i] =
            static_cast<std::int16_t>(std::lround(std::clamp(drive[i], -kMotorLimit, kMotorLimit)));
    return values;
}

} // namespace fl::haptics::falcon
