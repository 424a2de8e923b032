// Rigid motions in Cl(0,3,1) (paper §3): screws (twists), rotors, translators and motors g = t r,
// with the blade orientations of the shared conventions.
//
//   screw       s = ωx e2e3 + ωy e3e1 + ωz e1e2 + vx e1e + vy e2e + vz e3e
//   rotor       r = cos(θ/2) + sin(θ/2)(ux e2e3 + uy e3e1 + uz e1e2)   (+θ about u, right hand)
//   translator  t = 1 + ½(tx e1e + ty e2e + tz e3e)
//   motor       g = t r = α0 + α1 e2e3 + α2 e3e1 + α3 e1e2 + β0 e e1e2e3 + β1 e1e + β2 e2e + β3 e3e
//
// g s g* = H s with H = [[R, 0], [T R, R]] (§2), * the Clifford conjugation.
//
// Unit motors (g g* = 1, §3): unit_defect(g) gives the two residuals, inverse(g) = g*,
// renormalize(g) / renormalize_checked(g) project a drifted motor back, and to_homogeneous(g) /
// from_homogeneous(m) convert to and from 4×4 matrices [R t; 0 0 0 1] (the latter validated,
// returning checked<motor<T>>). The exponential map g = e^{z/2} and its inverse are in
// mechanics/exp_log.hpp.
#pragma once

#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <type_traits>

#include "ctga/algebra/operations.hpp"
#include "ctga/algebras.hpp"
#include "ctga/mechanics/checked.hpp"
#include "ctga/mechanics/linear3.hpp"

namespace ctga {

template <class T = double>
using screw = cl031::mv<T, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e">;
template <class T = double>
using rotor = cl031::mv<T, "1", "e2e3", "e3e1", "e1e2">;
template <class T = double>
using translator = cl031::mv<T, "1", "e1e", "e2e", "e3e">;
// The paper's coefficient order: β0 belongs to e e1e2e3 (= −e1e2e3e), as in §3.
template <class T = double>
using motor = cl031::mv<T, "1", "e2e3", "e3e1", "e1e2", "ee1e2e3", "e1e", "e2e", "e3e">;

// The rotation by angle θ about the unit axis u (right-hand rule).
template <class T>
[[nodiscard]] constexpr rotor<T> rotation(const T& ux, const T& uy, const T& uz, const T& theta) noexcept {
    using std::cos;
    using std::sin;
    const T c = cos(theta / T(2)), s = sin(theta / T(2));
    return rotor<T>{c, s * ux, s * uy, s * uz};
}

// The translation by (tx, ty, tz).
template <class T>
[[nodiscard]] constexpr translator<T> translation(const T& tx, const T& ty, const T& tz) noexcept {
    return translator<T>{T(1), tx / T(2), ty / T(2), tz / T(2)};
}

// g = t r: first rotate, then translate.
template <class T>
[[nodiscard]] constexpr motor<T> rigid_motion(const translator<T>& t, const rotor<T>& r) noexcept {
    return t * r;
}

// The adjoint action of a motor on a screw, g s g* (§2–3): for a unit motor, H s. Its blades
// are exactly a screw's (the grade-0 and grade-4 parts cancel for any g), at 72m 58a.
inline constexpr auto adjoint = formula([](auto g, auto s) { return g * s * conj(g); });

// ---- unit motors: residuals, inverse, renormalisation (§3) ---------------------------------
//
// Reading g as a dual quaternion. With ε = e e1e2e3 (ε² = 0, and ε commutes with every even
// element: e commutes with each ei ej, and e1e2e3 is central in Cl(0,3)), ε e2e3 = e1e,
// ε e3e1 = e2e, ε e1e2 = e3e. So g = α + ε β with α = α0 + α1 i + α2 j + α3 k and
// β = β0 + β1 i + β2 j + β3 k two quaternions (i = e2e3, j = e3e1, k = e1e2: i² = j² = k² = −1,
// i j = k). The Clifford conjugation is g* = ᾱ + ε β̄ (bivectors change sign, grades 0 and 4
// do not), hence g g* = |α|² + 2ε(α0β0 + α·β): the two relations of §3. A translator is
// t = 1 + ε t/2 (t the pure quaternion tx i + ty j + tz k), so g = t r has α = r and β = ½ t α.

// The two residuals of g g* = 1 (§3): α·α − 1 and α0β0 + α·β. Both vanish for a rigid motion.
template <class T>
struct motor_defect {
    T alpha_norm;  // α0² + α1² + α2² + α3² − 1
    T alpha_beta;  // α0β0 + α1β1 + α2β2 + α3β3
};

template <class T>
[[nodiscard]] constexpr motor_defect<T> unit_defect(const motor<T>& g) noexcept {
    return {g[0] * g[0] + g[1] * g[1] + g[2] * g[2] + g[3] * g[3] - T(1),
            g[0] * g[4] + g[1] * g[5] + g[2] * g[6] + g[3] * g[7]};
}

// The inverse of a unit motor: g⁻¹ = g* because g g* = 1 (§3). Exact (sign changes only): the
// conjugate ᾱ + ε β̄ of the dual quaternion. For a motor that is not unit this is g*, not g⁻¹.
template <class T>
[[nodiscard]] constexpr motor<T> inverse(const motor<T>& g) noexcept {
    return motor<T>{g[0], -g[1], -g[2], -g[3], g[4], -g[5], -g[6], -g[7]};
}

namespace motion_detail {

// √x, usable in constant expressions (Newton's iteration from above, monotone in exact
// arithmetic, stopped when it no longer decreases) and std::sqrt at run time.
template <class T>
[[nodiscard]] constexpr T sqrt(const T& x) noexcept {
    if (std::is_constant_evaluated()) {
        if (!(x > T(0)) || !is_finite(x)) return x < T(0) ? std::numeric_limits<T>::quiet_NaN() : x;
        T y = x > T(1) ? x : T(1);  // y ≥ √x
        for (;;) {
            const T next = (y + x / y) / T(2);
            if (!(next < y)) return y;
            y = next;
        }
    } else {
        using std::sqrt;
        return sqrt(x);
    }
}

}  // namespace motion_detail

// The nearest rigid motion to a motor g = α + ε β that has drifted off g g* = 1 (rounding,
// integration), or a failure:
//   input_error::non_finite   a component is NaN or ±∞;
//   input_error::not_a_motor  α = 0 (no rotation to keep), or β is so large against α that the
//                             result overflows.
// It divides g by its dual-number norm √(g g*) = |α| + ε (α·β)/|α|:
//   g / √(g g*) = α̂ + ε (β − (α̂·β) α̂)/|α|,   α̂ = α/|α|,
// i.e. "scale by 1/|α|, then remove the component of β along α̂". In what sense it is nearest:
//   - α̂ is the nearest unit quaternion to α (radial projection onto the sphere S³);
//   - with α̂ fixed, β − (α̂·β)α̂ is the orthogonal projection of β onto the hyperplane α̂·β = 0,
//     the nearest β satisfying the second relation of §3;
//   - the result is the motor whose rotation is g's rotor α̂ and whose translation is the one g
//     encodes, t = 2 vec(β ᾱ)/|α|² (g = t r read backwards): only the parts no rigid motion has
//     are discarded (the length of α and the scalar part of β ᾱ). It is unchanged when g is
//     multiplied by a positive number or by a dual scalar 1 + ε μ (β → β + μα).
// It is not the nearest point of R⁸ in the unweighted metric |Δα|² + |Δβ|²: that point mixes
// units (β carries a length) and would rotate the body to repair a translation defect.
// Scaling g by the largest |αi| first keeps |α|² from overflowing or underflowing.
template <class T>
[[nodiscard]] constexpr checked<motor<T>> renormalize_checked(const motor<T>& g) noexcept {
    if (!all_finite(g[0], g[1], g[2], g[3], g[4], g[5], g[6], g[7])) return {motor<T>{}, input_error::non_finite};
    T m = T(0);
    for (int i = 0; i < 4; ++i) {
        const T a = g[i] < T(0) ? -g[i] : g[i];
        if (a > m) m = a;
    }
    if (!(m > T(0))) return {motor<T>{}, input_error::not_a_motor};
    T x[8];
    for (int i = 0; i < 8; ++i) x[i] = g[i] / m;  // the result is invariant under g → λg, λ > 0
    const T n = motion_detail::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);  // in [1, 2]
    for (int i = 0; i < 8; ++i) x[i] /= n;  // α̂ and β/|α|
    const T d = x[0] * x[4] + x[1] * x[5] + x[2] * x[6] + x[3] * x[7];  // α̂·β/|α|
    for (int i = 0; i < 4; ++i) x[4 + i] -= d * x[i];
    if (!all_finite(x[4], x[5], x[6], x[7])) return {motor<T>{}, input_error::not_a_motor};
    return {motor<T>{x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]}, input_error::none};
}

// renormalize_checked for a g known to be a drifted motor. Asserts in debug builds when it is
// not one (see renormalize_checked); in release builds it then returns a motor of NaNs, so
// that the failure shows in every later result instead of passing for a rigid motion.
template <class T>
[[nodiscard]] constexpr motor<T> renormalize(const motor<T>& g) noexcept {
    const checked<motor<T>> r = renormalize_checked(g);
    assert(r && "ctga::renormalize: not a motor (zero or non-finite rotor part); use renormalize_checked");
    if (!r) {
        const T nan = std::numeric_limits<T>::quiet_NaN();
        return motor<T>{nan, nan, nan, nan, nan, nan, nan, nan};
    }
    return r.value;
}

// ---- the linear map of a motor (§2) ------------------------------------------------------

// The linear map of the sandwich by a unit motor g = t r: rotation matrix R of r, translation t.
template <class T = double>
struct motor_map {
    mat3<T> R{};
    vec3<T> t{};
};

// For g = t r (§3): r = α0 + α1 e2e3 + α2 e3e1 + α3 e1e2 is the quaternion (α0, α1, α2, α3) under
// e2e3 ↦ i, e3e1 ↦ j, e1e2 ↦ k, so R is the quaternion's rotation matrix; and g r* = t r r* = t,
// so the translation is twice the e1e, e2e, e3e part of g r*.
// Both are computed homogeneously, dividing by |α|² (R = 1 + (2/|α|²)(…), t = 2 vec(β ᾱ)/|α|²), so
// that a motor off g g* = 1 (an integrator's stage, an unrenormalised step) gives the map of the
// rigid motion it encodes, the same as map_of(renormalize(g)): the dynamics evaluated at a drifted
// motor are then the same function in every representation. 31m 24a and one division.
template <class T>
[[nodiscard]] constexpr motor_map<T> map_of(const motor<T>& g) noexcept {
    const T w = g[0], x = g[1], y = g[2], z = g[3];
    const T two_over_n = T(2) / (w * w + x * x + y * y + z * z);
    const T x2 = x * two_over_n, y2 = y * two_over_n, z2 = z * two_over_n;
    const T wx = w * x2, wy = w * y2, wz = w * z2, xx = x * x2, xy = x * y2, xz = x * z2, yy = y * y2, yz = y * z2,
            zz = z * z2;
    motor_map<T> out;
    out.R = {{{T(1) - (yy + zz), xy - wz, xz + wy}, {xy + wz, T(1) - (xx + zz), yz - wx}, {xz - wy, yz + wx, T(1) - (xx + yy)}}};
    const rotor<T> r{w, x, y, z};
    const auto tau = project<cl031::mv<T, "e1e", "e2e", "e3e">>(g * conj(r));
    out.t = {tau[0] * two_over_n, tau[1] * two_over_n, tau[2] * two_over_n};
    return out;
}

// The map of g⁻¹ = g* from the map of g: Rᵀ and −Rᵀ t (x ↦ R x + t inverted), 9m 6a.
template <class T>
[[nodiscard]] constexpr motor_map<T> inverse(const motor_map<T>& G) noexcept {
    motor_map<T> out;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out.R[i][j] = G.R[j][i];
    for (int i = 0; i < 3; ++i) out.t[i] = -(out.R[i][0] * G.t[0] + out.R[i][1] * G.t[1] + out.R[i][2] * G.t[2]);
    return out;
}

// ---- homogeneous 4×4 matrices -----------------------------------------------------------

// Row-major [R t; 0 0 0 1]: m[row][col], R = the 3×3 block, t = (m[0][3], m[1][3], m[2][3]).
template <class T>
using homogeneous_matrix = std::array<std::array<T, 4>, 4>;

// How far from a rigid motion from_homogeneous accepts a matrix, entrywise (R's entries are at
// most 1 in size, so this is both absolute and relative): |RᵀR − I|ij ≤ tol, |bottom row −
// (0 0 0 1)| ≤ tol. 1e-9 for double and long double: matrices printed with ten significant
// digits, or composed from thousands of products, pass. For float, 1024 ε ≈ 1.2e-4 (1e-9 is
// below float's own rounding of R).
template <class T>
inline constexpr T homogeneous_tolerance = T(1e-9) > T(1024) * std::numeric_limits<T>::epsilon()
                                               ? T(1e-9)
                                               : T(1024) * std::numeric_limits<T>::epsilon();

// The 4×4 matrix [R t; 0 0 0 1] of a unit motor g = t r: its motor_map. For a motor off
// g g* = 1, renormalize first.
template <class T>
[[nodiscard]] constexpr homogeneous_matrix<T> to_homogeneous(const motor<T>& g) noexcept {
    const motor_map<T> G = map_of(g);
    homogeneous_matrix<T> m{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m[i][j] = G.R[i][j];
        m[i][3] = G.t[i];
    }
    m[3][3] = T(1);
    return m;
}

// The motor g = t r of a homogeneous matrix [R t; 0 0 0 1], or why it is not one:
//   input_error::non_finite       an entry is NaN or ±∞;
//   input_error::not_homogeneous  the bottom row is not (0, 0, 0, 1) within tol;
//   input_error::not_a_rotation   R is not orthonormal within tol (|RᵀR − I|ij ≤ tol), or
//                                 det R < 0 (a reflection).
// The rotor by Shepperd's method: of 4w² = 1 + tr R, 4x² = 1 + R00 − R11 − R22,
// 4y² = 1 − R00 + R11 − R22, 4z² = 1 − R00 − R11 + R22, take the root of the largest, which is
// at least 1 (w² + x² + y² + z² = 1, so the largest is ≥ ¼): no cancellation, also near θ = π
// where 1 + tr R → 0. The other three come from the off-diagonal differences and sums
// R21 − R12 = 4wx, R02 − R20 = 4wy, R10 − R01 = 4wz, R01 + R10 = 4xy, R02 + R20 = 4xz,
// R12 + R21 = 4yz, divided by that root.
// The rotor is then normalised (absorbing R's tolerated non-orthogonality) and chosen with
// α0 ≥ 0; −g is the same rigid motion. Then β = ½ t α: β0 = −½ t·α⃗, β⃗ = ½(α0 t + t × α⃗).
template <class T>
[[nodiscard]] constexpr checked<motor<T>> from_homogeneous(const homogeneous_matrix<T>& m,
                                                           const T& tol = homogeneous_tolerance<T>) noexcept {
    for (const auto& row : m)
        for (const T& v : row)
            if (!is_finite(v)) return {motor<T>{}, input_error::non_finite};
    const auto off = [](const T& v) { return v < T(0) ? -v : v; };
    if (off(m[3][0]) > tol || off(m[3][1]) > tol || off(m[3][2]) > tol || off(m[3][3] - T(1)) > tol)
        return {motor<T>{}, input_error::not_homogeneous};
    for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) {
            const T rtr = m[0][i] * m[0][j] + m[1][i] * m[1][j] + m[2][i] * m[2][j];
            if (off(rtr - (i == j ? T(1) : T(0))) > tol) return {motor<T>{}, input_error::not_a_rotation};
        }
    const T det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                  m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    if (!(det > T(0))) return {motor<T>{}, input_error::not_a_rotation};

    const T r00 = m[0][0], r11 = m[1][1], r22 = m[2][2];
    const T tr = r00 + r11 + r22;
    T w, x, y, z;
    if (tr >= r00 && tr >= r11 && tr >= r22) {
        const T h = motion_detail::sqrt(T(1) + tr);  // 2|w|
        w = h / T(2);
        x = (m[2][1] - m[1][2]) / (T(2) * h);
        y = (m[0][2] - m[2][0]) / (T(2) * h);
        z = (m[1][0] - m[0][1]) / (T(2) * h);
    } else if (r00 >= r11 && r00 >= r22) {
        const T h = motion_detail::sqrt(T(1) + r00 - r11 - r22);  // 2|x|
        x = h / T(2);
        w = (m[2][1] - m[1][2]) / (T(2) * h);
        y = (m[0][1] + m[1][0]) / (T(2) * h);
        z = (m[0][2] + m[2][0]) / (T(2) * h);
    } else if (r11 >= r22) {
        const T h = motion_detail::sqrt(T(1) - r00 + r11 - r22);  // 2|y|
        y = h / T(2);
        w = (m[0][2] - m[2][0]) / (T(2) * h);
        x = (m[0][1] + m[1][0]) / (T(2) * h);
        z = (m[1][2] + m[2][1]) / (T(2) * h);
    } else {
        const T h = motion_detail::sqrt(T(1) - r00 - r11 + r22);  // 2|z|
        z = h / T(2);
        w = (m[1][0] - m[0][1]) / (T(2) * h);
        x = (m[0][2] + m[2][0]) / (T(2) * h);
        y = (m[1][2] + m[2][1]) / (T(2) * h);
    }
    T n = motion_detail::sqrt(w * w + x * x + y * y + z * z);
    if (w < T(0)) n = -n;
    w /= n, x /= n, y /= n, z /= n;

    const T tx = m[0][3], ty = m[1][3], tz = m[2][3];
    const T b0 = -(tx * x + ty * y + tz * z) / T(2);
    const T bx = (w * tx + (ty * z - tz * y)) / T(2);
    const T by = (w * ty + (tz * x - tx * z)) / T(2);
    const T bz = (w * tz + (tx * y - ty * x)) / T(2);
    return {motor<T>{w, x, y, z, b0, bx, by, bz}, input_error::none};
}

}  // namespace ctga
