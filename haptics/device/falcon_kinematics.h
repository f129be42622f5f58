#pragma once
// Kinematics of the Novint Falcon, a parallel arm with three legs of a
// thigh and a parallelogram shin (Stamper's model, as libnifalcon uses it;
// the equations below are our own derivation from that geometry).
//
// Leg i is turned by phi_i about the z axis. In the leg's frame (u, v, w),
// with the effector point P = Rz(-phi_i)·p − (r, s, 0):
//     P_u = a cos θ1 + L cos θ2 − c
//     P_v = b cos θ3 − f
//     P_w = a sin θ1 + L sin θ2,          L = d + e + b sin θ3
// θ1 is the thigh angle the motor turns and the encoder measures. The
// inverse (position → θ1) is closed-form: θ3 from P_v, then the knee at
// distance a from the hip and L from (P_u + c, P_w), the branch the Falcon
// is built in. The forward map (encoders → position) is Newton's method on
// the inverse, with its Jacobian found by implicit differentiation.
//
// Frames: the kinematic frame has its origin at the centre of the hips' base
// with z along the device's axis, growing away from the motors, as
// libnifalcon reports positions. The device frame the servo loop sees has
// the same axes moved to the workspace centre, kWorkspaceCentre. (Which way
// x and z point for a user facing the device should be checked on a real
// Falcon; the servo loop's device-to-scene transform is where to turn them.)
#include "field/vec3.h"

#include <array>
#include <cstdint>
#include <optional>

namespace fl::haptics::falcon {

using Mat3 = std::array<field::Vec3, 3>; // rows

// The workspace centre in the kinematic frame: the point about which the
// largest ball (radius ≈ 0.055 m) is reachable; the limits table promises
// 0.04 m around it.
inline constexpr field::Vec3 kWorkspaceCentre{0, 0, 0.1225};

// The thigh angle (radians) for an encoder count: 320 slots read in
// quadrature on a 14.25 mm shaft driving a 110 mm arc; count 0 at 35°.
double encoderToAngle(double counts);
double angleToEncoder(double angle);

// θ1 of each leg for an effector point (kinematic frame, metres); none
// outside what the legs can reach.
std::optional<field::Vec3> thighAngles(const field::Vec3& position);

// dθ1_i/dp_j at a point (row i: leg i); none where a leg is singular.
// Checked against finite differences in the tests. (libnifalcon's own
// Jacobian agrees in x and y; its z column has sin θ2·sin θ2 where the
// derivative has sin θ2·sin θ3, so its forces along z are off.)
std::optional<Mat3> angleJacobian(const field::Vec3& position);

// The effector point whose thigh angles are `angles`, by Newton steps from
// `guess` (the last known position; kWorkspaceCentre when there is none).
// Converges to within 1e-9 rad in a few steps; none if it cannot.
std::optional<field::Vec3> effectorPosition(const field::Vec3& angles,
                                            const field::Vec3& guess = kWorkspaceCentre);

// The torques about the three hip axes (N·m) that make the effector push
// with `force` (N) at `position`: τ = J⁻ᵀ F, the virtual-work dual of
// θ̇ = J ṗ. None where the arm is singular.
std::optional<field::Vec3> jointTorques(const field::Vec3& position, const field::Vec3& force);

// Motor drive values for joint torques: libnifalcon's measured gain of
// 10000 counts per N·m with the motors' sign; scaled down together when one
// would pass the int16 range, so the force keeps its direction.
std::array<std::int16_t, 3> motorValues(const field::Vec3& torques);

// 3×3 helpers, exposed for the tests.
field::Vec3 multiply(const Mat3& m, const field::Vec3& v);
std::optional<Mat3> inverse(const Mat3& m);
Mat3 transpose(const Mat3& m);

} // namespace fl::haptics::falcon
