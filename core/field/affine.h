#pragma once
// Affine maps x' = m x + t: X3D Transform chains, the pieces of an FTransform
// set operation, a shape's placement in the scene (and back, for picking).
// One definition for the kernel and the viewer.
#include "box3.h"

#include <array>
#include <optional>
#include <vector>

namespace fl::field {

// A 4x4 matrix, column-major (OpenGL and Qt's order).
using Matrix4 = std::array<double, 16>;

struct Affine {
    double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    double t[3] = {0, 0, 0};

    Affine operator*(const Affine& o) const;
    static Affine translate(double x, double y, double z);
    static Affine scale(double x, double y, double z);
    // About a unit axis (normalised here); a zero axis or non-finite angle: identity.
    static Affine rotate(double ax, double ay, double az, double angle);
    // An X3D SFRotation (axis x y z, angle); anything but four numbers: identity.
    static Affine rotate(const std::vector<double>& r);
    static Affine fromMatrix(const Matrix4& columnMajor);
    Matrix4 matrix() const; // column-major

    Vec3 point(const Vec3& p) const;  // m p + t
    Vec3 vector(const Vec3& v) const; // m v
    double determinant() const;
    // The cofactor matrix C of the linear part: its inverse is C^T / det and
    // its inverse transpose, which carries normals, C / det.
    std::array<std::array<double, 3>, 3> cofactors() const;
    // None when the map is singular (a zero scale).
    std::optional<Affine> inverse() const;
};

// The axis-aligned box round a box's eight corners, mapped.
Box3 boundsOf(const Box3& box, const Affine& a);

} // namespace fl::field
