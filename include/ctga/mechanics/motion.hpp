// Rigid motions in Cl(0,3,1) (paper §3): screws (twists), rotors, translators and motors g = t r,
// with the blade orientations of the shared conventions.
//
//   screw       s = ωx e2e3 + ωy e3e1 + ωz e1e2 + vx e1e + vy e2e + vz e3e
//   rotor       r = cos(θ/2) + sin(θ/2)(ux e2e3 + uy e3e1 + uz e1e2)   (+θ about u, right hand)
//   translator  t = 1 + ½(tx e1e + ty e2e + tz e3e)
//   motor       g = t r = α0 + α1 e2e3 + α2 e3e1 + α3 e1e2 + β0 e e1e2e3 + β1 e1e + β2 e2e + β3 e3e
//
// g s g* = H s with H = [[R, 0], [T R, R]] (§2), * the Clifford conjugation.
#pragma once

#include <cmath>

#include "ctga/algebra/operations.hpp"
#include "ctga/algebras.hpp"

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

}  // namespace ctga
