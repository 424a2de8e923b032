// One rigid body's motion in the 6×6 matrix formalism of §2, with Eigen: a model for the
// integrators of include/ctga/integrators/ (the motion_model concept of model.hpp) written
// without ctga's algebra.
//
//   motor_type = Eigen::Matrix<T, 8, 1>   the dual quaternion α + ε β in ctga::motor's order
//                                         (α0, α1, α2, α3, β0, β1, β2, β3), i = e2e3, j = e3e1,
//                                         k = e1e2 (i j = k), ε = e e1e2e3
//   screw_type = Eigen::Matrix<T, 6, 1>   (ω, v) in ctga::screw's order and signs (to_vector6),
//                                         i.e. the dual quaternion ω + ε v
//   wrench     = Eigen::Matrix<T, 6, 1>   (τ, F) = (l, p) order, as ctga::coscrew
//
//   N = [[I_c − m Ĉ², m Ĉ], [−m Ĉ, m 1]],   M = N⁻¹ = [[J, −J Ĉ], [Ĉ J, 1/m − Ĉ J Ĉ]],  J = I_c⁻¹
//   (built here from the mass properties, independently of ctga's inertia_of / mobility_of)
//   ṡ = M (W − s ×* (N s)),   s ×* P = (ω × l + v × p, ω × p)  (Featherstone's crf(s) P)
//   fixed frame: N' = H⁻ᵀ N H⁻¹, M' = H M Hᵀ, H = [[R, 0], [T R, R]] the adjoint of g
//   (R the rotation of α, t = 2 vec(β ᾱ), T x = t × x; H⁻¹ = [[Rᵀ, 0], [−Rᵀ T, Rᵀ]])
//   motor_rate ½ s g (fixed) or ½ g s (body), compose: the dual-quaternion product,
//   exp(z) = e^{z/2} in the closed form of mechanics/motor.hpp, bracket (ω1 × ω2, ω1 × v2 − ω2 × v1)
//   = crm(s1) s2, renormalize: the division by the dual norm of mechanics/motor.hpp.
//
// Off the unit motors (see dense_model.hpp): H is read from g with the formula of a unit
// quaternion, R = 1 + 2 α0 α̂ + 2 α̂² (α̂ the cross-product matrix of (α1, α2, α3)), and Rᵀ
// taken for R⁻¹; `evaluate_at_unit_pose` (default true, as ctga's homogeneous map_of)
// evaluates the dynamics, the wrench included, at renormalize(g) instead.
//
// Conversions to and from ctga's types (for comparing trajectories component by component):
//   matrix_of(motor<T>), matrix_of(screw<T>), matrix_of(coscrew<T>), to_ctga(Matrix<T,8,1>)
//   -> motor<T>, to_ctga(Matrix<T,6,1>) -> screw<T>.
#pragma once

#include "support/dual_quaternion.hpp"

#include <cmath>
#include <cstddef>
#include <limits>

#include <Eigen/Dense>

#include <ctga/integrators/model.hpp>
#include <ctga/mechanics/inertia.hpp>
#include <ctga/mechanics/inertia_matrix.hpp>
#include <ctga/mechanics/mass_properties.hpp>
#include <ctga/mechanics/motor.hpp>

namespace ctga::test {

template <class T>
using vector8 = Eigen::Matrix<T, 8, 1>;
template <class T>
using vector6 = Eigen::Matrix<T, 6, 1>;
template <class T>
using matrix6 = Eigen::Matrix<T, 6, 6>;

namespace matrix_model_detail {

template <class T>
using v3 = Eigen::Matrix<T, 3, 1>;
template <class T>
using m3 = Eigen::Matrix<T, 3, 3>;
template <class T>
using quat = Eigen::Matrix<T, 4, 1>;  // (w, x, y, z)

template <class T>
m3<T> hat(const v3<T>& x) {
    m3<T> m;
    m << T(0), -x(2), x(1), x(2), T(0), -x(0), -x(1), x(0), T(0);
    return m;
}

// The Hamilton product (i j = k).
template <class T>
quat<T> qmul(const quat<T>& a, const quat<T>& b) {
    quat<T> out;
    out(0) = a(0) * b(0) - a(1) * b(1) - a(2) * b(2) - a(3) * b(3);
    out(1) = a(0) * b(1) + a(1) * b(0) + a(2) * b(3) - a(3) * b(2);
    out(2) = a(0) * b(2) - a(1) * b(3) + a(2) * b(0) + a(3) * b(1);
    out(3) = a(0) * b(3) + a(1) * b(2) - a(2) * b(1) + a(3) * b(0);
    return out;
}
template <class T>
quat<T> pure(const v3<T>& v) {
    return quat<T>(T(0), v(0), v(1), v(2));
}
template <class T>
quat<T> conj(const quat<T>& q) {
    return quat<T>(q(0), -q(1), -q(2), -q(3));
}

// (α1 + ε β1)(α2 + ε β2) = α1 α2 + ε(α1 β2 + β1 α2).
template <class T>
vector8<T> dq_mul(const quat<T>& a1, const quat<T>& b1, const quat<T>& a2, const quat<T>& b2) {
    vector8<T> out;
    out << qmul(a1, a2), qmul(a1, b2) + qmul(b1, a2);
    return out;
}

// The sandwich g s g* = H s of a unit motor: H = [[R, 0], [T R, R]], and H⁻¹.
template <class T>
struct adjoint_matrices {
    matrix6<T> H, H_inverse;
};
template <class T>
adjoint_matrices<T> adjoint_of(const vector8<T>& g) {
    const T w = g(0);
    const v3<T> x(g(1), g(2), g(3));
    const m3<T> X = hat(x);
    const m3<T> R = m3<T>::Identity() + T(2) * w * X + T(2) * X * X;
    const quat<T> alpha = g.template head<4>(), beta = g.template tail<4>();
    const quat<T> ba = qmul(beta, conj(alpha));
    const v3<T> t(T(2) * ba(1), T(2) * ba(2), T(2) * ba(3));
    const m3<T> TR = hat(t) * R;
    adjoint_matrices<T> out;
    out.H.setZero();
    out.H.template topLeftCorner<3, 3>() = R;
    out.H.template bottomRightCorner<3, 3>() = R;
    out.H.template bottomLeftCorner<3, 3>() = TR;
    out.H_inverse.setZero();
    out.H_inverse.template topLeftCorner<3, 3>() = R.transpose();
    out.H_inverse.template bottomRightCorner<3, 3>() = R.transpose();
    out.H_inverse.template bottomLeftCorner<3, 3>() = TR.transpose();  // −Rᵀ T = (T R)ᵀ, as Tᵀ = −T
    return out;
}

// Featherstone's crf(s) P = (ω × l + v × p, ω × p).
template <class T>
vector6<T> force_cross(const vector6<T>& s, const vector6<T>& P) {
    const v3<T> w = s.template head<3>(), v = s.template tail<3>();
    const v3<T> l = P.template head<3>(), p = P.template tail<3>();
    vector6<T> out;
    out << w.cross(l) + v.cross(p), w.cross(p);
    return out;
}
// Featherstone's crm(a) b = (ωa × ωb, ωa × vb + va × ωb).
template <class T>
vector6<T> motion_cross(const vector6<T>& a, const vector6<T>& b) {
    const v3<T> wa = a.template head<3>(), va = a.template tail<3>();
    const v3<T> wb = b.template head<3>(), vb = b.template tail<3>();
    vector6<T> out;
    out << wa.cross(wb), wa.cross(vb) + va.cross(wb);
    return out;
}


}  // namespace matrix_model_detail

// ---- conversions to and from ctga's types ----------------------------------------------------

template <class T>
vector8<T> matrix_of(const ctga::motor<T>& g) {
    vector8<T> out;
    for (int i = 0; i < 8; ++i) out(i) = g[static_cast<std::size_t>(i)];
    return out;
}
template <class T>
vector6<T> matrix_of(const ctga::screw<T>& s) {
    vector6<T> out;
    for (int i = 0; i < 6; ++i) out(i) = s[static_cast<std::size_t>(i)];
    return out;
}
template <class T>
vector6<T> matrix_of(const ctga::coscrew<T>& P) {
    vector6<T> out;
    for (int i = 0; i < 6; ++i) out(i) = P[static_cast<std::size_t>(i)];
    return out;
}
template <class T>
ctga::motor<T> to_ctga(const vector8<T>& g) {
    return ctga::motor<T>{g(0), g(1), g(2), g(3), g(4), g(5), g(6), g(7)};
}
template <class T>
ctga::screw<T> to_ctga(const vector6<T>& s) {
    return ctga::screw<T>{s(0), s(1), s(2), s(3), s(4), s(5)};
}

// No applied wrench: a free body.
struct matrix_no_wrench {
    template <class T>
    vector6<T> operator()(const vector8<T>&, const vector6<T>&) const {
        return vector6<T>::Zero();
    }
};

// The 6×6 inertia and mobility of mass properties given in the body frame.
template <class T>
matrix6<T> inertia_matrix6(const ctga::mass_properties<T>& b) {
    using namespace matrix_model_detail;
    m3<T> Ic;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Ic(i, j) = b.inertia_c[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    const m3<T> C = hat(v3<T>(b.com[0], b.com[1], b.com[2]));
    matrix6<T> N;
    N << Ic - b.mass * C * C, b.mass * C, -b.mass * C, b.mass * m3<T>::Identity();
    return N;
}
template <class T>
matrix6<T> mobility_matrix6(const ctga::mass_properties<T>& b) {
    using namespace matrix_model_detail;
    m3<T> Ic;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Ic(i, j) = b.inertia_c[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    const m3<T> J = Ic.inverse();
    const m3<T> C = hat(v3<T>(b.com[0], b.com[1], b.com[2]));
    matrix6<T> M;
    M << J, -J * C, C * J, m3<T>::Identity() / b.mass - C * J * C;
    return M;
}

// ---- the model ---------------------------------------------------------------------------------

template <class T = double, ctga::frame Frame = ctga::frame::body, class Wrench = matrix_no_wrench>
struct matrix_motion {
    using scalar_type = T;
    using motor_type = vector8<T>;
    using screw_type = vector6<T>;
    static constexpr ctga::frame velocity_frame = Frame;

    ctga::mass_properties<T> mass;       // in the body frame
    matrix6<T> N;                        // the inertia, body frame
    matrix6<T> M;                        // the mobility N⁻¹, body frame
    Wrench applied{};                    // W(g, s) in the model's frame, (τ, F)
    bool evaluate_at_unit_pose = true;  // evaluate the dynamics at renormalize(g), as ctga does

    explicit matrix_motion(const ctga::mass_properties<T>& body, Wrench wrench = {}, bool at_unit_pose = true)
        : mass(body),
          N(inertia_matrix6(body)),
          M(mobility_matrix6(body)),
          applied(wrench),
          evaluate_at_unit_pose(at_unit_pose) {}

    [[nodiscard]] screw_type acceleration(const motor_type& pose, const screw_type& s) const {
        using matrix_model_detail::force_cross;
        const motor_type g = evaluate_at_unit_pose ? renormalize(pose) : pose;
        const vector6<T> W = applied(g, s);
        if constexpr (Frame == ctga::frame::fixed) {
            const auto A = matrix_model_detail::adjoint_of<T>(g);
            const matrix6<T> Nf = A.H_inverse.transpose() * N * A.H_inverse;
            const matrix6<T> Mf = A.H * M * A.H.transpose();
            return Mf * (W - force_cross<T>(s, Nf * s));
        } else {
            return M * (W - force_cross<T>(s, N * s));
        }
    }
    // ½ s g = ½(ω α + ε(ω β + v α)) or ½ g s = ½(α ω + ε(α v + β ω)).
    [[nodiscard]] motor_type motor_rate(const motor_type& g, const screw_type& s) const {
        using namespace matrix_model_detail;
        const quat<T> a = g.template head<4>(), b = g.template tail<4>();
        const quat<T> w = pure<T>(s.template head<3>()), v = pure<T>(s.template tail<3>());
        if constexpr (Frame == ctga::frame::body) return (T(1) / T(2)) * dq_mul<T>(a, b, w, v);
        else return (T(1) / T(2)) * dq_mul<T>(w, v, a, b);
    }
    // e^{z/2} (exp_log.hpp's closed form, support/dual_quaternion.hpp)
    [[nodiscard]] motor_type exp(const screw_type& z) const {
        const auto g = dual_quaternion::exp(std::array<T, 6>{z(0), z(1), z(2), z(3), z(4), z(5)});
        return Eigen::Map<const motor_type>(g.data());
    }
    [[nodiscard]] motor_type compose(const motor_type& a, const motor_type& b) const {
        return matrix_model_detail::dq_mul<T>(a.template head<4>(), a.template tail<4>(), b.template head<4>(),
                                              b.template tail<4>());
    }
    [[nodiscard]] screw_type bracket(const screw_type& a, const screw_type& b) const {
        return matrix_model_detail::motion_cross<T>(a, b);
    }
    // g / √(g g*) (motion.hpp, support/dual_quaternion.hpp); NaNs for α = 0 or a non-finite g
    [[nodiscard]] motor_type renormalize(const motor_type& g) const {
        std::array<T, 8> x{};
        for (int i = 0; i < 8; ++i) x[static_cast<std::size_t>(i)] = g(i);
        x = dual_quaternion::renormalized(x);
        return Eigen::Map<const motor_type>(x.data());
    }
    [[nodiscard]] bool unit(const motor_type& g) const {
        std::array<T, 8> x{};
        for (int i = 0; i < 8; ++i) x[static_cast<std::size_t>(i)] = g(i);
        return dual_quaternion::near_unit(x);
    }
    [[nodiscard]] bool finite(const motor_type& g, const screw_type& s) const { return g.allFinite() && s.allFinite(); }
    [[nodiscard]] T magnitude(const screw_type& z) const { return z.cwiseAbs().maxCoeff(); }
};

}  // namespace ctga::test
