// Motors (paper §3): rigid motions g = t r in Cl(0,3,1), their action on screws and co-screws,
// unit motors, and the exponential map. Everything about a motor is reachable from this header.
//
//   rotor       r = cos(θ/2) + sin(θ/2)(ux e2e3 + uy e3e1 + uz e1e2)   (+θ about u, right hand)
//   translator  t = 1 + ½(tx e1e + ty e2e + tz e3e)
//   motor       g = t r = α0 + α1 e2e3 + α2 e3e1 + α3 e1e2 + β0 e e1e2e3 + β1 e1e + β2 e2e + β3 e3e
//
// g s g* = H s with H = [[R, 0], [T R, R]] (§2), * the Clifford conjugation; on co-screws
// ḡ P ḡ* = H⁻ᵀ P. motor_map holds R and t, built once from g (31m 24a and a division), and
// applies the action at hand-written cost (24m 18a on a screw or a co-screw); the sandwich itself
// is the formula ctga::adjoint, and the tests prove the two agree. The action on inertias is in
// inertia_transform.hpp, the 4×4 homogeneous matrices in convert.hpp.
#pragma once

#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <type_traits>

#include "ctga/mechanics/algebras.hpp"
#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/operations/evaluate.hpp"
#include "ctga/operations/formula.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/inline.hpp"
#include "ctga/support/math.hpp"
#include "ctga/support/unit_direction.hpp"

namespace ctga {

template <class T = double>
using rotor = cl031::mv<T, "1", "e2e3", "e3e1", "e1e2">;
template <class T = double>
using translator = cl031::mv<T, "1", "e1e", "e2e", "e3e">;
// The paper's coefficient order: β0 belongs to e e1e2e3 (= −e1e2e3e), as in §3.
template <class T = double>
using motor = cl031::mv<T, "1", "e2e3", "e3e1", "e1e2", "ee1e2e3", "e1e", "e2e", "e3e">;

// The rotor turning by angle θ about the axis (x, y, z) through the origin, right-handed:
// cos(θ/2) + sin(θ/2)(u_x e2e3 + u_y e3e1 + u_z e1e2), u the axis made unit (any non-zero vector
// gives its direction; a unit axis comes back unchanged up to rounding), so the rotor is always a
// unit rotor. Reported: non_finite (a NaN or an infinity), zero_direction (the zero axis).
template <class T>
[[nodiscard]] constexpr checked<rotor<T>> make_rotor_checked(const T& theta, const T& x, const T& y, const T& z) noexcept {
    if (!is_finite(theta)) return {rotor<T>{}, error_code::non_finite};
    const checked<std::array<T, 3>> u = unit_direction(x, y, z);
    if (!u) return {rotor<T>{}, u.error};
    const auto cs = math::cos_sin(theta / T(2));  // of half the angle
    return {rotor<T>{cs.cos, cs.sin * u.value[0], cs.sin * u.value[1], cs.sin * u.value[2]}, error_code::none};
}

// make_rotor_checked for an axis known to be finite and non-zero (value_or_nan: asserts in debug
// builds, a rotor of NaNs in release builds, never a rotor that looks fine).
template <class T>
[[nodiscard]] constexpr rotor<T> make_rotor(const T& theta, const T& x, const T& y, const T& z) noexcept {
    return value_or_nan(make_rotor_checked(theta, x, y, z));
}

// The translator moving by (tx, ty, tz): 1 + ½(tx e1e + ty e2e + tz e3e).
template <class T>
[[nodiscard]] constexpr translator<T> make_translator(const T& tx, const T& ty, const T& tz) noexcept {
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

// Whether g is a unit motor up to rounding: α·α − 1 within √ε, and α0β0 + α·β within √ε·max(1, |β|)
// (β carries the translation's length). A motor further off was not made by rotors and
// translators (or an integrator's drift) but written by hand wrongly: renormalising it would
// silently replace it by another rigid motion, so the functions that take a pose from a user
// (chains::make_link, integrate) refuse it (not_a_motor) instead.
template <class T>
[[nodiscard]] constexpr bool near_unit(const motor<T>& g) noexcept {
    const motor_defect<T> d = unit_defect(g);
    const T tolerance = math::sqrt(std::numeric_limits<T>::epsilon());
    const T beta = math::sqrt(g[4] * g[4] + g[5] * g[5] + g[6] * g[6] + g[7] * g[7]);
    const auto magnitude = [](const T& x) { return x < T(0) ? -x : x; };
    return all_finite(d.alpha_norm, d.alpha_beta) && magnitude(d.alpha_norm) <= tolerance &&
           magnitude(d.alpha_beta) <= tolerance * (beta > T(1) ? beta : T(1));
}

// The inverse of a unit motor: g⁻¹ = g* because g g* = 1 (§3). Exact (sign changes only): the
// conjugate ᾱ + ε β̄ of the dual quaternion. For a motor that is not unit this is g*, not g⁻¹.
template <class T>
[[nodiscard]] constexpr motor<T> inverse(const motor<T>& g) noexcept {
    return motor<T>{g[0], -g[1], -g[2], -g[3], g[4], -g[5], -g[6], -g[7]};
}

// The nearest rigid motion to a motor g = α + ε β that has drifted off g g* = 1 (rounding,
// integration), or a failure:
//   error_code::non_finite   a component is NaN or ±∞;
//   error_code::not_a_motor  α = 0 (no rotation to keep), or β is so large against α that the
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
namespace renormalize_detail {
// g / m, then α̂ and β/|α| with β's component along α̂ removed (m > 0: g's largest |αi|)
template <class T>
[[nodiscard]] constexpr std::array<T, 8> scaled(const motor<T>& g, const T& m) noexcept {
    std::array<T, 8> x;
    for (std::size_t i = 0; i < 8; ++i) x[i] = g[i] / m;  // the result is invariant under g → λg, λ > 0
    const T n = math::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);  // in [1, 2]
    for (std::size_t i = 0; i < 8; ++i) x[i] /= n;  // α̂ and β/|α|
    const T d = x[0] * x[4] + x[1] * x[5] + x[2] * x[6] + x[3] * x[7];  // α̂·β/|α|
    for (std::size_t i = 0; i < 4; ++i) x[4 + i] -= d * x[i];
    return x;
}
// Packs, lane by lane: the renormalised motor (NaN in a lane that has a NaN or ∞, or α = 0) and
// the lanes' masks: finite, and a rotor part (largest |αi| > 0).
template <class T>
struct lanes_renormalized {
    motor<T> value;
    decltype(T() > T()) finite, rotor;
};
template <lane_wise T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr lanes_renormalized<T> in_lanes(const motor<T>& g) noexcept {
    T m = T(0);
    auto finite = finite_lanes(g[0]);
    for (std::size_t i = 0; i < 8; ++i) finite = finite && finite_lanes(g[i]);
    for (std::size_t i = 0; i < 4; ++i) m = select(abs(g[i]) > m, abs(g[i]), m);
    const auto rotor = m > T(0);
    const T nan(std::numeric_limits<typename T::value_type>::quiet_NaN());
    const auto x = scaled(g, select(finite && rotor, m, nan));
    return {motor<T>{x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]}, finite, rotor};
}
}  // namespace renormalize_detail

template <class T>
[[nodiscard]] constexpr checked<motor<T>, error_of_t<T>> renormalize_checked(const motor<T>& g) noexcept {
    if constexpr (lane_wise<T>) {
        // packs: every lane renormalised; a lane with a NaN or infinity, or a zero rotor part,
        // reports it (non_finite, not_a_motor) and its numbers are NaN
        const auto r = renormalize_detail::in_lanes(g);
        error_of_t<T> e;
        for (std::size_t l = 0; l < T::size; ++l)
            e[l] = !r.finite[l] ? error_code::non_finite : !r.rotor[l] ? error_code::not_a_motor : error_code::none;
        return {r.value, e};
    } else {
        if (!all_finite(g[0], g[1], g[2], g[3], g[4], g[5], g[6], g[7])) return {motor<T>{}, error_code::non_finite};
        T m = T(0);
        for (std::size_t i = 0; i < 4; ++i) {
            const T a = g[i] < T(0) ? -g[i] : g[i];
            if (a > m) m = a;
        }
        if (!(m > T(0))) return {motor<T>{}, error_code::not_a_motor};
        const auto x = renormalize_detail::scaled(g, m);
        if (!all_finite(x[4], x[5], x[6], x[7])) return {motor<T>{}, error_code::not_a_motor};
        return {motor<T>{x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]}, error_code::none};
    }
}

// renormalize_checked for a g known to be a drifted motor. Asserts in debug builds when it is
// not one (see renormalize_checked); in release builds it then returns a motor of NaNs, so
// that the failure shows in every later result instead of passing for a rigid motion.
template <class T>
[[nodiscard]] constexpr motor<T> renormalize(const motor<T>& g) noexcept {
    if constexpr (lane_wise<T>) return renormalize_detail::in_lanes(g).value;  // (a failed lane's numbers are NaN)
    else return value_or_nan(renormalize_checked(g));
}

// ---- the linear map of a motor (§2) ------------------------------------------------------

// The linear map of the sandwich by a unit motor g = t r: rotation matrix R of r, translation t.
// A plain aggregate like mat3: motor_map<T>{} is zero, a default-initialised one (an element
// of an array of maps about to be filled) is not cleared.
template <class T = double>
struct motor_map {
    mat3<T> R;
    vec3<T> t;
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

// The rotor of a rotation matrix (map_of's R inverted, up to the rotor's sign): Shepperd's
// method, from the largest of 1 + tr R and 1 + 2 R_ii − tr R (4 α_k² each), so that the square
// root is never of a small number.
template <class T>
[[nodiscard]] constexpr rotor<T> rotor_of(const mat3<T>& R) noexcept {
    const T trace = R[0][0] + R[1][1] + R[2][2];
    const std::array<T, 4> four{T(1) + trace, T(1) + T(2) * R[0][0] - trace, T(1) + T(2) * R[1][1] - trace, T(1) + T(2) * R[2][2] - trace};
    std::size_t k = 0;
    for (std::size_t i = 1; i < 4; ++i)
        if (four[i] > four[k]) k = i;
    const T a = math::sqrt(four[k]) / T(2), q = T(1) / (T(4) * a);  // α_k, and 1 / (4 α_k)
    const T wx = (R[2][1] - R[1][2]) * q, wy = (R[0][2] - R[2][0]) * q, wz = (R[1][0] - R[0][1]) * q;
    const T xy = (R[1][0] + R[0][1]) * q, xz = (R[0][2] + R[2][0]) * q, yz = (R[2][1] + R[1][2]) * q;
    if (k == 0) return rotor<T>{a, wx, wy, wz};
    if (k == 1) return rotor<T>{wx, a, xy, xz};
    if (k == 2) return rotor<T>{wy, xy, a, yz};
    return rotor<T>{wz, xz, yz, a};
}

// The map of g_A g_B (B's frame placed in A's, A placed in the world): R = R_A R_B,
// t = R_A t_B + t_A, 36m 30a (row i of R_A R_B is R_Bᵀ applied to row i of R_A: with R_B of shape
// S, linear3.hpp, a turn about a coordinate axis, 21m 15a).
template <linear3::shape S = linear3::dense, class T>
[[nodiscard]] constexpr motor_map<T> compose(const motor_map<T>& A, const motor_map<T>& B) noexcept {
    motor_map<T> out;
    for (std::size_t i = 0; i < 3; ++i) out.R[i] = linear3::apply_transposed<S>(B.R, A.R[i]);
    out.t = linear3::add(linear3::apply(A.R, B.t), A.t);
    return out;
}

// The map of g⁻¹ = g* from the map of g: Rᵀ and −Rᵀ t (x ↦ R x + t inverted), 9m 6a.
template <class T>
[[nodiscard]] constexpr motor_map<T> inverse(const motor_map<T>& G) noexcept {
    motor_map<T> out;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) out.R[i][j] = G.R[j][i];
    for (std::size_t i = 0; i < 3; ++i) out.t[i] = -(out.R[i][0] * G.t[0] + out.R[i][1] * G.t[1] + out.R[i][2] * G.t[2]);
    return out;
}

// ---- the action on screws and co-screws (§2) ---------------------------------------------

// g s g* = H s: ω' = R ω, v' = R v + t × ω'. (S: the shape of R when some of its entries are known
// to be 0 or 1, linear3.hpp; a joint aligned with its parent, chains/joints.hpp.)
template <linear3::shape S = linear3::dense, class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr screw<T> transform(const motor_map<T>& G, const screw<T>& s) noexcept {
    const vec3<T> w = linear3::apply<S>(G.R, vec3<T>{s[0], s[1], s[2]});
    const vec3<T> v = linear3::add(linear3::apply<S>(G.R, vec3<T>{s[3], s[4], s[5]}), linear3::cross(G.t, w));
    return screw<T>{w[0], w[1], w[2], v[0], v[1], v[2]};
}

// ḡ P ḡ* = H⁻ᵀ P: p' = R p, l' = R l + t × p'.
template <linear3::shape S = linear3::dense, class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr coscrew<T> transform(const motor_map<T>& G, const coscrew<T>& P) noexcept {
    const vec3<T> p = linear3::apply<S>(G.R, vec3<T>{P[3], P[4], P[5]});
    const vec3<T> l = linear3::add(linear3::apply<S>(G.R, vec3<T>{P[0], P[1], P[2]}), linear3::cross(G.t, p));
    return coscrew<T>{l[0], l[1], l[2], p[0], p[1], p[2]};
}

// The same actions by g⁻¹ = g*, without forming its map (Rᵀ applied directly), 24m 18a each:
// on a screw H⁻¹ s: ω' = Rᵀ ω, v' = Rᵀ (v − t × ω); on a co-screw Hᵀ P: l' = Rᵀ (l − t × p), p' = Rᵀ p.
template <linear3::shape S = linear3::dense, class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr screw<T> transform_inverse(const motor_map<T>& G, const screw<T>& s) noexcept {
    const vec3<T> w{s[0], s[1], s[2]};
    const vec3<T> tw = linear3::cross(G.t, w);
    const vec3<T> w2 = linear3::apply_transposed<S>(G.R, w);
    const vec3<T> v2 = linear3::apply_transposed<S>(G.R, vec3<T>{s[3] - tw[0], s[4] - tw[1], s[5] - tw[2]});
    return screw<T>{w2[0], w2[1], w2[2], v2[0], v2[1], v2[2]};
}
template <linear3::shape S = linear3::dense, class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr coscrew<T> transform_inverse(const motor_map<T>& G, const coscrew<T>& P) noexcept {
    const vec3<T> p{P[3], P[4], P[5]};
    const vec3<T> tp = linear3::cross(G.t, p);
    const vec3<T> l2 = linear3::apply_transposed<S>(G.R, vec3<T>{P[0] - tp[0], P[1] - tp[1], P[2] - tp[2]});
    const vec3<T> p2 = linear3::apply_transposed<S>(G.R, p);
    return coscrew<T>{l2[0], l2[1], l2[2], p2[0], p2[1], p2[2]};
}

// Without a prebuilt map: transform(g, x) builds it once and applies it.
template <class T, class X>
[[nodiscard]] constexpr auto transform(const motor<T>& g, const X& x) noexcept {
    return transform(map_of(g), x);
}

// ---- the exponential map (§3) --------------------------------------------------------------
//
// The exponential map of §3, g = e^{z/2} = 1 + z/2 + (z/2)²/2 + …, from screws to motors, in
// closed form, and its inverse on unit motors.
//
//   ctga::motor<double> g = ctga::exp(z);   // z a ctga::screw<double>
//   ctga::screw<double> z = ctga::log(g);   // exp(log(g)) = ±g, the same rigid motion
//
// Both take ctga types only, so they never compete with std::exp / std::log for numbers, also
// under `using namespace std; using namespace ctga;`. Inside namespace ctga they hide the
// <cmath> names from unqualified lookup: library code calls std::exp / std::log explicitly.
//
// Derivation (dual quaternions, as above: g = α + ε β, ε = e e1e2e3, ε² = 0, central in
// the even subalgebra; i = e2e3, j = e3e1, k = e1e2). A screw is z = 2(a + ε b) with the pure
// quaternions a = ω/2 and b = v/2 (ε i = e1e, …). Since ε² = 0 and ε is central,
//   e^{a + ε b} = e^a + ε D e^a[b]         (the first-order Taylor term, exact here),
// and with φ = |a| = θ/2, e^a = cos φ + sinc φ · a (sinc φ = sin φ / φ), whose derivative along b
// (using ∂φ/∂a = a/φ and sinc′(φ)/φ = (cos φ − sinc φ)/φ²) is
//   β0 = −sinc φ (a·b),   β⃗ = sinc φ · b + c(φ) (a·b) a,   c(φ) = (cos φ − sinc φ)/φ².
// So exp(z) = cos φ + sinc φ · a + ε(−sinc φ (a·b) + sinc φ · b + c(φ)(a·b) a).
// Both sinc and c are entire functions of φ²; near φ = 0 the quotients are 0/0 or cancel, so
// below φ = 1 they are summed as series (12 terms, to φ²⁴: beyond long double precision):
//   sinc φ = Σ (−φ²)ⁿ/(2n+1)!,   c(φ) = Σ_{n≥1} 2n (−1)ⁿ φ^{2n−2}/(2n+1)!.
// For ω = 0 (a pure translation) exp gives 1 + ε b exactly.

namespace motor_detail {

template <class T>
struct sinc_c {
    T sinc;  // sin φ / φ
    T c;     // (cos φ − sin φ/φ)/φ²
};

// sinc φ and c(φ) for φ ≥ 0 given with φ² (exact at φ = 0: 1 and −1/3).
template <class T>
[[nodiscard]] constexpr sinc_c<T> sinc_and_c(const T& phi, const T& phi2) noexcept {
    const auto series = [&] {
        // u_n = (−1)ⁿ φ^{2n−2}/(2n+1)!: sinc = 1 + φ² Σ u_n, c = Σ 2n u_n. At φ < 1 the terms
        // fall below 1/(2n+1)!, 1/25! ≈ 6e-26 at n = 12.
        T u = T(-1) / T(6);
        T su = T(0), cu = T(0);
        for (int n = 1; n <= 12; ++n) {
            su += u;
            cu += T(2 * n) * u;
            u *= -phi2 / T((2 * n + 2) * (2 * n + 3));
        }
        return sinc_c<T>{T(1) + phi2 * su, cu};
    };
    const auto closed = [&] {
        const T s = math::sin(phi) / phi;
        return sinc_c<T>{s, (math::cos(phi) - s) / phi2};  // no cancellation at φ ≥ 1: cos φ − sinc φ ≤ −0.30
    };
    if constexpr (lane_wise<T>) {  // packs: both, each lane taking its own (the closed form's 0/0 at φ = 0 unused)
        const auto small = phi < T(1);
        const sinc_c<T> a = series(), b = closed();
        return {select(small, a.sinc, b.sinc), select(small, a.c, b.c)};
    } else {
        return phi < T(1) ? series() : closed();
    }
}

}  // namespace motor_detail

// The motor g = e^{z/2} of a screw z = (ω, v) (§3): a rotation by θ = |ω| about the screw axis
// combined with the translation along it, in the closed form above. Accurate to a few ulps for
// every θ (series below θ = 2, the closed form above); a pure translation (ω = 0) gives
// 1 + ½(vx e1e + vy e2e + vz e3e) exactly. θ is not reduced: exp(z) for θ and θ + 4π agree.
template <class T>
[[nodiscard]] constexpr motor<T> exp(const screw<T>& z) noexcept {
    const T ax = z[0] / T(2), ay = z[1] / T(2), az = z[2] / T(2);  // a = ω/2
    const T bx = z[3] / T(2), by = z[4] / T(2), bz = z[5] / T(2);  // b = v/2
    const T phi2 = ax * ax + ay * ay + az * az;
    const T phi = math::sqrt(phi2);  // θ/2
    const auto [sinc, c] = motor_detail::sinc_and_c(phi, phi2);
    const T ab = ax * bx + ay * by + az * bz;
    const T cab = c * ab;
    return motor<T>{math::cos(phi),    sinc * ax,         sinc * ay,         sinc * az, -sinc * ab,
                    sinc * bx + cab * ax, sinc * by + cab * ay, sinc * bz + cab * az};
}

// The screw z with exp(z) = g, for a unit motor g (§3), with rotation angle θ = |ω| ∈ [0, π].
//
// g and −g are the same rigid motion (Spin(3) covers SO(3) twice); log works on the one with
// α0 ≥ 0, so exp(log(g)) = g when α0 ≥ 0 and −g otherwise. Then φ = θ/2 = atan2(|α⃗|, α0) ∈
// [0, π/2], accurate at both ends (no acos near α0 = 1, no asin near α0 = 0), and
// a = α⃗ / (|α| sinc φ), sinc φ ≥ 2/π: no division by sin(θ/2), which vanishes at θ = 0.
// b is recovered from β by inverting the derivative above:
//   a·b = cos φ (a·β⃗) − φ sin φ β0       (from β0 = −sinc φ (a·b) and a·β⃗ = cos φ (a·b);
//                                          the weights cos²φ + sin²φ = 1 use both, so neither
//                                          the division by cos φ at θ = π nor by sin φ at
//                                          θ = 0 is needed)
//   b = (β⃗ − c(φ) (a·b) a) / sinc φ = β⃗ / sinc φ − k(φ) (a·b) a,
//   k(φ) = c(φ)/sinc φ = (φ cot φ − 1)/φ²   (the cot form of the SE(3) logarithm, −1/3 at φ = 0,
//                                            −4/π² at θ = π: finite on the whole range).
// A pure translation 1 + ε b gives (0, 2b) exactly. α is divided by |α| (so a motor off by a
// positive factor is handled) but the second relation α0β0 + α·β = 0 is not repaired: for a
// drifted motor, renormalize first.
template <class T>
[[nodiscard]] constexpr screw<T> log(const motor<T>& g) noexcept {
    using std::atan2;
    const T sign = g[0] < T(0) ? T(-1) : T(1);
    const T w = sign * g[0], x = sign * g[1], y = sign * g[2], z = sign * g[3];
    const T s2 = x * x + y * y + z * z;
    const T s = math::sqrt(s2);                 // |α| sin φ
    const T n = math::sqrt(w * w + s2);         // |α|
    const T phi = atan2(s, w);                           // θ/2 ∈ [0, π/2]
    const auto [sinc, c] = motor_detail::sinc_and_c(phi, phi * phi);
    const T k = T(1) / (n * sinc);                      // a = k α⃗ = φ α⃗/|α⃗|
    const T ax = k * x, ay = k * y, az = k * z;
    const T b0 = sign * g[4] / n, bx = sign * g[5] / n, by = sign * g[6] / n, bz = sign * g[7] / n;
    const T ab = (w / n) * (ax * bx + ay * by + az * bz) - phi * (s / n) * b0;
    const T cab = c * ab;
    return screw<T>{T(2) * ax, T(2) * ay, T(2) * az, T(2) * (bx - cab * ax) / sinc, T(2) * (by - cab * ay) / sinc,
                    T(2) * (bz - cab * az) / sinc};
}

}  // namespace ctga
