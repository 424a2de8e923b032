// One rigid body's motion in the naive dense reference (include/ctga/reference/dense.hpp): a
// model for the integrators of include/ctga/integrators/ (the motion_model concept of model.hpp)
// whose arithmetic never touches ctga's compile-time engine.
//
//   motor_type = screw_type = ctga::dense::multivector<ctga::cl031, T>   (all 16 components)
//
// The dynamics are the paper's formulas, evaluated literally in the dense 256-component
// Cl(0,6,2) (§5–6):
//
//   P = A ∨ (N ∧ s),   ṡ = E ∨ (M ∧ (W − ½(s̄P − Ps̄)))
//
// with the screw lifted onto the e-half blade by blade (generator k of Cl(0,3,1) is generator
// k + 4 of Cl(0,6,2), in the same order, so a blade's mask shifts by 4 and its orientation is
// unchanged), N and M the dense copies of ctga's inertia_of / mobility_of (made once, at
// construction: ctga only supplies the 24 + 36 numbers, blade by blade), and in the fixed frame
// the inertia and the mobility moved with the body by the dense sandwich
//
//   N' = (g ḡ) N (g ḡ)*,   M' = (g ḡ) M (g ḡ)*      (g lifted, ḡ its bar: the a-half copy).
//
// The rest is written on the dense components with plain arithmetic: motor_rate ½ s g / ½ g s
// and compose g h (dense geometric products of Cl(0,3,1)), bracket ½(ab − ba) (its grade-2 part:
// the grade-0 and grade-4 parts of ab − ba of two screws vanish exactly in exact arithmetic,
// and only rounding noise of summation order is dropped), exp(z) = e^{z/2} in the closed form of
// exp_log.hpp, renormalize the division by the dual norm of motion.hpp (same steps in the same
// order, hence the same rounding).
//
// Off the unit motors. The fixed-frame dynamics depend on the pose, and explicit Euler and the
// stages of RK4 evaluate them at motors with g g* ≠ 1. The paper's sandwich is then not a rigid
// motion (for g = λ r it scales N' and M' by λ⁴, ṡ by about λ⁸), and every representation
// extends the dynamics off g g* = 1 in its own way (a unit-quaternion formula for R is not homogeneous in g). The trajectories of those methods then differ by
// far more than rounding, though each is a valid discretisation. `evaluate_at_unit_pose`
// (default true, the choice ctga makes: its map_of is homogeneous and equals
// map_of(renormalize(g))) evaluates the dynamics, the wrench included, at renormalize(g): the
// same function of g in every representation. false gives the paper's sandwich with g as given.
//
// The wrench is a callable W(g, s) -> ctga::dense::multivector<ctga::cl062, T>, a co-screw in the
// model's frame (blades a1a, a2a, a3a, a2a3, a3a1, a1a2); the default is a free body.
//
// Conversions to and from ctga's types (for comparing trajectories component by component):
//   dense_of(motor<T>), dense_of(screw<T>), motor_of_dense(x), screw_of_dense(x),
//   coscrew_to_dense(coscrew<T>).
// The dense products are slow (each visits all 256 × 256 blade pairs): about 6 per body-frame
// acceleration, 11 per fixed-frame one.
#pragma once

#include "support/dual_quaternion.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string_view>

#include <ctga/mechanics/algebras.hpp>
#include <ctga/integrators/model.hpp>
#include <ctga/mechanics/inertia.hpp>
#include <ctga/mechanics/mass_properties.hpp>
#include <ctga/reference/dense.hpp>

namespace ctga::test {

template <class T>
using dense31 = ctga::dense::multivector<ctga::cl031, T>;  // motors and screws
template <class T>
using dense62 = ctga::dense::multivector<ctga::cl062, T>;  // momenta, wrenches, inertias

namespace dense_model_detail {

// A blade written as in ctga's types: its canonical mask and the orientation of the written order.
struct signed_blade {
    ctga::blade_mask mask;
    int sign;
};
constexpr signed_blade blade31(std::string_view name) {
    const auto b = ctga::cl031::parse_blade(name);
    return {b.mask, b.sign};
}
// ctga::motor's coefficient order (α0, α1, α2, α3, β0, β1, β2, β3) and ctga::screw's (ω, v).
inline constexpr std::array<signed_blade, 8> motor_blades{blade31("1"),       blade31("e2e3"), blade31("e3e1"),
                                                          blade31("e1e2"),    blade31("ee1e2e3"), blade31("e1e"),
                                                          blade31("e2e"),     blade31("e3e")};
inline constexpr std::array<signed_blade, 6> screw_blades{blade31("e2e3"), blade31("e3e1"), blade31("e1e2"),
                                                          blade31("e1e"),  blade31("e2e"),  blade31("e3e")};
inline constexpr std::array<std::string_view, 6> coscrew_names{"a1a", "a2a", "a3a", "a2a3", "a3a1", "a1a2"};

// Generator k of Cl(0,3,1) is generator k + 4 of Cl(0,6,2).
inline constexpr int e_offset = 4;

template <class T>
T component(const dense31<T>& x, const signed_blade& b) {
    return b.sign > 0 ? x[b.mask] : -x[b.mask];
}
template <class T>
void set_component(dense31<T>& x, const signed_blade& b, const T& v) {
    x[b.mask] = b.sign > 0 ? v : -v;
}

// The (α, β) or (ω, v) coefficients of a dense element, in ctga's order.
template <class T>
std::array<T, 8> motor_coefficients(const dense31<T>& g) {
    std::array<T, 8> out{};
    for (std::size_t i = 0; i < 8; ++i) out[i] = component(g, motor_blades[i]);
    return out;
}
template <class T>
std::array<T, 6> screw_coefficients(const dense31<T>& s) {
    std::array<T, 6> out{};
    for (std::size_t i = 0; i < 6; ++i) out[i] = component(s, screw_blades[i]);
    return out;
}
template <class T>
dense31<T> motor_from(const std::array<T, 8>& c) {
    dense31<T> out;
    for (std::size_t i = 0; i < 8; ++i) set_component(out, motor_blades[i], c[i]);
    return out;
}
template <class T>
dense31<T> screw_from(const std::array<T, 6>& c) {
    dense31<T> out;
    for (std::size_t i = 0; i < 6; ++i) set_component(out, screw_blades[i], c[i]);
    return out;
}

// x placed on the e-half of Cl(0,6,2), and back (the a-blades of y must vanish).
template <class T>
dense62<T> lift(const dense31<T>& x) {
    dense62<T> out;
    for (std::size_t m = 0; m < ctga::cl031::blade_count; ++m)
        out[static_cast<ctga::blade_mask>(m << e_offset)] = x[static_cast<ctga::blade_mask>(m)];
    return out;
}
// The screw part of an element of the e-half: the six screw blades only.
template <class T>
dense31<T> lower_screw(const dense62<T>& y) {
    dense31<T> out;
    for (const signed_blade& b : screw_blades) out[b.mask] = y[static_cast<ctga::blade_mask>(b.mask << e_offset)];
    return out;
}
template <class T>
dense31<T> screw_part(const dense31<T>& x) {
    dense31<T> out;
    for (const signed_blade& b : screw_blades) out[b.mask] = x[b.mask];
    return out;
}

template <class T>
const dense62<T>& A() {
    static const dense62<T> a = dense62<T>::blade("a1a2a3a");
    return a;
}
template <class T>
const dense62<T>& E() {
    static const dense62<T> e = dense62<T>::blade("e1e2e3e");
    return e;
}

// ½(x y − y x) in Cl(0,6,2).
template <class T>
dense62<T> half_commutator(const dense62<T>& x, const dense62<T>& y) {
    return (T(1) / T(2)) * (ctga::dense::gp(x, y) - ctga::dense::gp(y, x));
}
// h x h*.
template <class T>
dense62<T> sandwich(const dense62<T>& h, const dense62<T>& x) {
    return ctga::dense::gp(ctga::dense::gp(h, x), ctga::dense::conjugate(h));
}

// ṡ = E ∨ (M ∧ (W − ½(s̄P − Ps̄))), P = A ∨ (N ∧ s), with s already lifted.
template <class T>
dense31<T> acceleration(const dense62<T>& N, const dense62<T>& M, const dense62<T>& s, const dense62<T>& W) {
    namespace d = ctga::dense;
    const dense62<T> P = d::shuffle(A<T>(), d::wedge(N, s));
    const dense62<T> rhs = W - half_commutator(d::bar(s), P);
    return lower_screw(d::shuffle(E<T>(), d::wedge(M, rhs)));
}

}  // namespace dense_model_detail

// ---- conversions to and from ctga's types ----------------------------------------------------

template <class T>
dense31<T> dense_of(const ctga::motor<T>& g) {
    std::array<T, 8> c{};
    for (std::size_t i = 0; i < 8; ++i) c[i] = g[i];
    return dense_model_detail::motor_from(c);
}
template <class T>
dense31<T> dense_of(const ctga::screw<T>& s) {
    std::array<T, 6> c{};
    for (std::size_t i = 0; i < 6; ++i) c[i] = s[i];
    return dense_model_detail::screw_from(c);
}
template <class T>
ctga::motor<T> motor_of_dense(const dense31<T>& g) {
    const auto c = dense_model_detail::motor_coefficients(g);
    return ctga::motor<T>{c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]};
}
template <class T>
ctga::screw<T> screw_of_dense(const dense31<T>& s) {
    const auto c = dense_model_detail::screw_coefficients(s);
    return ctga::screw<T>{c[0], c[1], c[2], c[3], c[4], c[5]};
}
// A co-screw (l, p) as a dense element of Cl(0,6,2) (a wrench for the dense model).
template <class T>
dense62<T> coscrew_to_dense(const ctga::coscrew<T>& P) {
    dense62<T> out;
    for (std::size_t i = 0; i < 6; ++i) out = out + dense62<T>::blade(dense_model_detail::coscrew_names[i], P[i]);
    return out;
}

// No applied wrench: a free body.
struct dense_no_wrench {
    template <class T>
    dense62<T> operator()(const dense31<T>&, const dense31<T>&) const {
        return dense62<T>{};
    }
};

// ---- the model ---------------------------------------------------------------------------------

template <class T = double, ctga::frame Frame = ctga::frame::body, class Wrench = dense_no_wrench>
struct dense_motion {
    using scalar_type = T;
    using motor_type = dense31<T>;
    using screw_type = dense31<T>;
    static constexpr ctga::frame velocity_frame = Frame;

    ctga::mass_properties<T> mass;  // in the body frame
    dense62<T> N;                   // the inertia, body frame, all 256 components
    dense62<T> M;                   // the mobility N⁻¹, body frame
    Wrench applied{};               // W(g, s) in the model's frame
    bool evaluate_at_unit_pose = true;  // evaluate the dynamics at renormalize(g), as ctga does

    explicit dense_motion(const ctga::mass_properties<T>& body, Wrench wrench = {}, bool at_unit_pose = true)
        : mass(body),
          N(ctga::dense::to_dense(ctga::inertia_of(body))),
          M(ctga::dense::to_dense(ctga::mobility_of(body))),
          applied(wrench),
          evaluate_at_unit_pose(at_unit_pose) {}

    // N' = (g ḡ) N (g ḡ)* and M' = (g ḡ) M (g ḡ)*: the body's inertia and mobility in the fixed frame.
    [[nodiscard]] std::array<dense62<T>, 2> moved_inertia(const motor_type& g) const {
        const dense62<T> gl = dense_model_detail::lift(g);
        const dense62<T> h = ctga::dense::gp(gl, ctga::dense::bar(gl));
        return {dense_model_detail::sandwich(h, N), dense_model_detail::sandwich(h, M)};
    }

    [[nodiscard]] screw_type acceleration(const motor_type& pose, const screw_type& s) const {
        const motor_type g = evaluate_at_unit_pose ? renormalize(pose) : pose;
        const dense62<T> W = applied(g, s);
        const dense62<T> x = dense_model_detail::lift(s);
        if constexpr (Frame == ctga::frame::fixed) {
            const auto moved = moved_inertia(g);
            return dense_model_detail::acceleration(moved[0], moved[1], x, W);
        } else {
            return dense_model_detail::acceleration(N, M, x, W);
        }
    }
    [[nodiscard]] motor_type motor_rate(const motor_type& g, const screw_type& s) const {
        if constexpr (Frame == ctga::frame::body) return (T(1) / T(2)) * ctga::dense::gp(g, s);
        else return (T(1) / T(2)) * ctga::dense::gp(s, g);
    }
    // e^{z/2} (exp_log.hpp's closed form, support/dual_quaternion.hpp)
    [[nodiscard]] motor_type exp(const screw_type& z) const {
        return dense_model_detail::motor_from(dual_quaternion::exp(dense_model_detail::screw_coefficients(z)));
    }
    [[nodiscard]] motor_type compose(const motor_type& a, const motor_type& b) const { return ctga::dense::gp(a, b); }
    [[nodiscard]] screw_type bracket(const screw_type& a, const screw_type& b) const {
        return dense_model_detail::screw_part(
            dense31<T>((T(1) / T(2)) * (ctga::dense::gp(a, b) - ctga::dense::gp(b, a))));
    }
    // g / √(g g*) (motion.hpp, support/dual_quaternion.hpp); NaNs for α = 0 or a non-finite g
    [[nodiscard]] motor_type renormalize(const motor_type& g) const {
        return dense_model_detail::motor_from(dual_quaternion::renormalized(dense_model_detail::motor_coefficients(g)));
    }
    [[nodiscard]] bool unit(const motor_type& g) const {
        return dual_quaternion::near_unit(dense_model_detail::motor_coefficients(g));
    }
    [[nodiscard]] bool finite(const motor_type& g, const screw_type& s) const {
        for (const T& v : g.components())
            if (!std::isfinite(v)) return false;
        for (const T& v : s.components())
            if (!std::isfinite(v)) return false;
        return true;
    }
    [[nodiscard]] T magnitude(const screw_type& z) const { return ctga::dense::max_abs(z); }
};

}  // namespace ctga::test
