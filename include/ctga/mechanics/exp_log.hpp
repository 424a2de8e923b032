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
// Derivation (dual quaternions, see motion.hpp: g = α + ε β, ε = e e1e2e3, ε² = 0, central in
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
#pragma once

#include <cmath>

#include "ctga/mechanics/motion.hpp"

namespace ctga {

namespace motion_detail {

template <class T>
struct sinc_c {
    T sinc;  // sin φ / φ
    T c;     // (cos φ − sin φ/φ)/φ²
};

// sinc φ and c(φ) for φ ≥ 0 given with φ² (exact at φ = 0: 1 and −1/3).
template <class T>
[[nodiscard]] constexpr sinc_c<T> sinc_and_c(const T& phi, const T& phi2) noexcept {
    if (phi < T(1)) {
        // u_n = (−1)ⁿ φ^{2n−2}/(2n+1)!: sinc = 1 + φ² Σ u_n, c = Σ 2n u_n. At φ < 1 the terms
        // fall below 1/(2n+1)!, 1/25! ≈ 6e-26 at n = 12.
        T u = T(-1) / T(6);
        T su = T(0), cu = T(0);
        for (int n = 1; n <= 12; ++n) {
            su += u;
            cu += T(2 * n) * u;
            u *= -phi2 / T((2 * n + 2) * (2 * n + 3));
        }
        return {T(1) + phi2 * su, cu};
    }
    using std::cos;
    using std::sin;
    const T s = sin(phi) / phi;
    return {s, (cos(phi) - s) / phi2};  // no cancellation at φ ≥ 1: cos φ − sinc φ ≤ −0.30
}

}  // namespace motion_detail

// The motor g = e^{z/2} of a screw z = (ω, v) (§3): a rotation by θ = |ω| about the screw axis
// combined with the translation along it, in the closed form above. Accurate to a few ulps for
// every θ (series below θ = 2, the closed form above); a pure translation (ω = 0) gives
// 1 + ½(vx e1e + vy e2e + vz e3e) exactly. θ is not reduced: exp(z) for θ and θ + 4π agree.
template <class T>
[[nodiscard]] constexpr motor<T> exp(const screw<T>& z) noexcept {
    using std::cos;
    const T ax = z[0] / T(2), ay = z[1] / T(2), az = z[2] / T(2);  // a = ω/2
    const T bx = z[3] / T(2), by = z[4] / T(2), bz = z[5] / T(2);  // b = v/2
    const T phi2 = ax * ax + ay * ay + az * az;
    const T phi = motion_detail::sqrt(phi2);  // θ/2
    const auto [sinc, c] = motion_detail::sinc_and_c(phi, phi2);
    const T ab = ax * bx + ay * by + az * bz;
    const T cab = c * ab;
    return motor<T>{cos(phi),          sinc * ax,         sinc * ay,         sinc * az, -sinc * ab,
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
    const T s = motion_detail::sqrt(s2);                 // |α| sin φ
    const T n = motion_detail::sqrt(w * w + s2);         // |α|
    const T phi = atan2(s, w);                           // θ/2 ∈ [0, π/2]
    const auto [sinc, c] = motion_detail::sinc_and_c(phi, phi * phi);
    const T k = T(1) / (n * sinc);                      // a = k α⃗ = φ α⃗/|α⃗|
    const T ax = k * x, ay = k * y, az = k * z;
    const T b0 = sign * g[4] / n, bx = sign * g[5] / n, by = sign * g[6] / n, bz = sign * g[7] / n;
    const T ab = (w / n) * (ax * bx + ay * by + az * bz) - phi * (s / n) * b0;
    const T cab = c * ab;
    return screw<T>{T(2) * ax, T(2) * ay, T(2) * az, T(2) * (bx - cab * ax) / sinc, T(2) * (by - cab * ay) / sinc,
                    T(2) * (bz - cab * az) / sinc};
}

}  // namespace ctga
