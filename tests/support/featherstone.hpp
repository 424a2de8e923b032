// An independent reference for rigid-body dynamics on kinematic trees: Featherstone's spatial
// (6D) algorithms, written plainly with Eigen from R. Featherstone, "Rigid Body Dynamics
// Algorithms", Springer 2008 (RBDA), chapters 2–7. Tests only; it shares no code with ctga and
// is meant to be read, not to be fast (it allocates, it forms 6×6 matrices everywhere).
//
// Conventions (all of RBDA's):
//   * motion vectors  m = (ω, v): angular part first; v is the velocity of the body-fixed point
//                     at the origin of the coordinate frame (Plücker coordinates, RBDA ch. 2);
//   * force vectors   f = (n, f): moment first; n is the moment about the frame's origin;
//   * Plücker transform from frame A to frame B, where B's origin is at r (A coordinates) and
//     E maps A coordinates of a free vector to B coordinates (E = rotation matrix of B in A,
//     transposed):  ^B X_A = rot(E) xlt(r) = [[E, 0], [−E r×, E]]               (RBDA ch. 2, "coordinate transforms")
//     and for forces ^B X_A^* = (^B X_A)^{−T} = [[E, −E r×], [0, E]]              (RBDA ch. 2, "coordinate transforms");
//   * spatial acceleration is the time derivative of the spatial velocity as a vector field
//     (RBDA ch. 2), not the classical acceleration of a point: the classical acceleration of the
//     point at the origin is v̇ + ω × v. In body coordinates the spatial acceleration is the
//     plain time derivative of the six body-coordinate numbers of the spatial velocity.
//
// The model. Bodies are listed in tree order (parent index < own index, −1 = the fixed world).
// Body i's joint frame J_i is fixed in the parent's frame: its axes are the columns of
// `rotation` and its origin is `translation`, both in parent coordinates. The body frame B_i is
// J_i moved by the joint:
//   revolute : rotation by the angle q about `axis` (unit, joint-frame coordinates, right hand),
//   prismatic: translation by q·axis,
//   fixed    : B_i = J_i (no coordinates),
//   floating : q = (x, y, z, qw, qx, qy, qz): B_i's origin (x, y, z) in J_i coordinates and its
//              orientation as a unit Hamilton quaternion qw + qx i + qy j + qz k that rotates
//              B_i coordinates into J_i coordinates. Its 6 velocity coordinates are B_i's spatial
//              velocity relative to J_i in B_i coordinates (ω, v) (S = 1, the RBDL / Pinocchio
//              "local" free-flyer convention), and its acceleration coordinates are their time
//              derivatives. (fk normalises the quaternion before use.)
// The joint's motion subspace S (RBDA Table 4.1) in body coordinates is (axis, 0) for revolute,
// (0, axis) for prismatic, the 6×0 matrix for fixed and the 6×6 identity for floating; the
// velocity-product term c_J = Ṡ q̇ is zero for all four.
//
// Body inertia: mass m, centre of mass c (body coordinates), rotational inertia I_c about c in
// body axes; as a spatial inertia about the body origin (RBDA eq. 2.63):
//   I = [[I_c + m c× c×ᵀ, m c×], [m c×ᵀ, m 1]].
//
// External forces f_ext (optional, empty = none): one spatial force per body, ACTING ON that
// body, in that body's coordinates, moment about the body origin. Then
//   rnea(q, v, a, f_ext) = rnea(q, v, a) − Σ_i J_iᵀ f_i   (J_i = jacobian_body(q, i)),
// i.e. τ is what the joints must supply in addition to the external forces, and aba() solves
// the same equation for the accelerations.
//
// Gravity: model::gravity, a linear acceleration in world coordinates; rnea and aba include it
// by the usual trick of accelerating the base by −g (RBDA ch. 5); fk reports true accelerations.
//
// Functions (q: nq numbers, v / a / τ: nv numbers, in tree order; see model::q_index/v_index):
//   fk(m, q, v, a)               per body: world rotation and origin, ^iX_0, spatial velocity and
//                                spatial acceleration (no gravity) in body coordinates
//   rnea(m, q, v, a, f_ext = {}) τ, with gravity                         (RBDA Table 5.1)
//   crba(m, q)                   H, nv × nv                                (RBDA Table 6.2)
//   aba(m, q, v, τ, f_ext = {})  q̈, with gravity                          (RBDA Table 7.1)
//   jacobian_body(m, q, i)       6 × nv, body i's spatial velocity in body i coordinates = J v
//   jacobian_world(m, q, i)      6 × nv, the same velocity in world Plücker coordinates
//   kinetic_energy(m, q, v), potential_energy(m, q) = −Σ m_i g · c_i
//   q_dot(m, q, v)               nq numbers: the rate of q for the velocity coordinates v
// and the spatial helpers skew, crm, crf, plucker, plucker_inverse, force_transform,
// spatial_inertia, axis_angle, quaternion_rotation, jcalc, tree_transform.
//
// The scalar. The model (`body`, `model`) is always double. The functions that depend on the
// state — skew, crm, crf, plucker, axis_angle, quaternion_rotation, jcalc, compute_positions,
// detail::forward_pass, rnea, crba, inverse_small, aba — are templates on the scalar S of the
// state (default double), e.g. a forward-mode dual number (support/dual_eigen.hpp, used by
// support/featherstone_derivatives.hpp); the model's numbers are converted to S where used.
// Their parameters are non-deduced (std::type_identity_t), so the double calls take Eigen
// expressions as before (fs::rnea(m, q, v, VectorXd::Zero(n))) and another scalar is named:
// fs::rnea<D>(m, q, v, a) with q, v, a of type vecX_t<D>. The double results are those of the
// one-scalar version this file had before, bit for bit (the same operations in the same order;
// cast<double>() of a double matrix is the matrix itself). The rest (fk, the Jacobians, the
// energies, q_dot, plucker_inverse, force_transform, spatial_inertia, tree_transform) is double.
// Frames (poses, velocities, accelerations, Jacobians and their time derivatives in local /
// world / local-world-aligned coordinates), centre of mass, centroidal momentum, mimic joints and
// the lumping of fixed links: support/featherstone_frames.hpp, built on this file.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Dense>

namespace ctga::test::featherstone {

template <class S> using vec3_t = Eigen::Matrix<S, 3, 1>;
template <class S> using mat3_t = Eigen::Matrix<S, 3, 3>;
template <class S> using vec6_t = Eigen::Matrix<S, 6, 1>;
template <class S> using mat6_t = Eigen::Matrix<S, 6, 6>;
// At most 6 columns / rows: a joint has at most 6 degrees of freedom. The fixed maximum sizes
// make Eigen multiply these coefficient by coefficient instead of instantiating its large-matrix
// product kernels, which keeps the compile time of the tests that include this file low.
template <class S> using mat6x_t = Eigen::Matrix<S, 6, Eigen::Dynamic, Eigen::ColMajor, 6, 6>;   // 6 × n_i
template <class S> using matn_t = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, 6, 6>;   // n_i × n_i
template <class S> using vecn_t = Eigen::Matrix<S, Eigen::Dynamic, 1, Eigen::ColMajor, 6, 1>;   // n_i
template <class S> using vecX_t = Eigen::Matrix<S, Eigen::Dynamic, 1>;                 // q, v, a, τ
template <class S> using matX_t = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;    // H
using vec3 = vec3_t<double>;
using mat3 = mat3_t<double>;
using vec6 = vec6_t<double>;
using mat6 = mat6_t<double>;
using mat6x = mat6x_t<double>;
using matn = matn_t<double>;
using vecn = vecn_t<double>;
// a parameter of type nondeduced<T> does not take part in deducing S (see "The scalar" above)
template <class T> using nondeduced = std::type_identity_t<T>;

// ---------------------------------------------------------------------------------------------
// The model.

enum class joint_kind { revolute, prismatic, fixed, floating };

inline int joint_nq(joint_kind k) {
    switch (k) {
    case joint_kind::revolute:
    case joint_kind::prismatic: return 1;
    case joint_kind::fixed: return 0;
    case joint_kind::floating: return 7;
    }
    return 0;
}
inline int joint_nv(joint_kind k) {
    switch (k) {
    case joint_kind::revolute:
    case joint_kind::prismatic: return 1;
    case joint_kind::fixed: return 0;
    case joint_kind::floating: return 6;
    }
    return 0;
}

struct body {
    int parent = -1;                           // parent body, −1 = the world; parent < own index
    joint_kind kind = joint_kind::fixed;
    vec3 axis = vec3::UnitZ();                 // unit, joint-frame coordinates (revolute / prismatic)
    mat3 rotation = mat3::Identity();          // joint frame axes (columns) in parent coordinates
    vec3 translation = vec3::Zero();           // joint frame origin in parent coordinates
    double mass = 1;
    vec3 com = vec3::Zero();                   // centre of mass, body coordinates
    mat3 inertia_c = mat3::Identity();         // rotational inertia about the com, body axes
    double armature = 0;                       // rotor inertia of a 1-dof joint: τ += armature q̈ (H_ii += armature)
};

struct model {
    std::vector<body> bodies;
    vec3 gravity{0, 0, -9.81};                 // world coordinates

    int size() const { return static_cast<int>(bodies.size()); }
    int nq() const {
        int n = 0;
        for (const body& b : bodies) n += joint_nq(b.kind);
        return n;
    }
    int nv() const {
        int n = 0;
        for (const body& b : bodies) n += joint_nv(b.kind);
        return n;
    }
    // where body i's joint coordinates start in q (resp. v, a, τ), in tree order
    int q_index(int i) const {
        int n = 0;
        for (int j = 0; j < i; ++j) n += joint_nq(bodies[static_cast<std::size_t>(j)].kind);
        return n;
    }
    int v_index(int i) const {
        int n = 0;
        for (int j = 0; j < i; ++j) n += joint_nv(bodies[static_cast<std::size_t>(j)].kind);
        return n;
    }
    const body& operator[](int i) const { return bodies[static_cast<std::size_t>(i)]; }
};

// ---------------------------------------------------------------------------------------------
// Spatial algebra (RBDA chapter 2).

// x× as a matrix: skew(x) y = x × y
template <class S = double>
mat3_t<S> skew(const nondeduced<vec3_t<S>>& x) {
    mat3_t<S> m;
    m << 0, -x.z(), x.y(),
         x.z(), 0, -x.x(),
         -x.y(), x.x(), 0;
    return m;
}

// motion cross product  m× = [[ω×, 0], [v×, ω×]]                                  (RBDA ch. 2)
template <class S = double>
mat6_t<S> crm(const nondeduced<vec6_t<S>>& m) {
    mat6_t<S> r = mat6_t<S>::Zero();
    r.template topLeftCorner<3, 3>() = skew<S>(m.template head<3>());
    r.template bottomLeftCorner<3, 3>() = skew<S>(m.template tail<3>());
    r.template bottomRightCorner<3, 3>() = skew<S>(m.template head<3>());
    return r;
}

// force cross product  m×* = −(m×)ᵀ = [[ω×, v×], [0, ω×]]                          (RBDA ch. 2)
template <class S = double>
mat6_t<S> crf(const nondeduced<vec6_t<S>>& m) { return -crm<S>(m).transpose(); }

// ^B X_A for B at r (A coordinates) with E: A coords → B coords:  rot(E) xlt(r)    (RBDA ch. 2, "coordinate transforms")
template <class S = double>
mat6_t<S> plucker(const nondeduced<mat3_t<S>>& E, const nondeduced<vec3_t<S>>& r) {
    mat6_t<S> X = mat6_t<S>::Zero();
    X.template topLeftCorner<3, 3>() = E;
    X.template bottomLeftCorner<3, 3>() = -E * skew<S>(r);
    X.template bottomRightCorner<3, 3>() = E;
    return X;
}

// (^B X_A)^{-1} = ^A X_B = [[Eᵀ, 0], [r× Eᵀ, Eᵀ]], read off the block form of X
inline mat6 plucker_inverse(const mat6& X) {
    const mat3 E = X.topLeftCorner<3, 3>();
    const mat3 Et = E.transpose();
    const mat3 rx = -Et * X.bottomLeftCorner<3, 3>();   // −E r× = lower-left block
    mat6 Y = mat6::Zero();
    Y.topLeftCorner<3, 3>() = Et;
    Y.bottomLeftCorner<3, 3>() = rx * Et;
    Y.bottomRightCorner<3, 3>() = Et;
    return Y;
}

// the force transform X* = X^{−T}                                                   (RBDA ch. 2, "coordinate transforms")
inline mat6 force_transform(const mat6& X) { return plucker_inverse(X).transpose(); }

// spatial inertia about the body origin from (m, c, I_c)                           (RBDA eq. 2.63)
inline mat6 spatial_inertia(double m, const vec3& c, const mat3& Ic) {
    const mat3 C = skew(c);
    mat6 I;
    I.topLeftCorner<3, 3>() = Ic + m * C * C.transpose();
    I.topRightCorner<3, 3>() = m * C;
    I.bottomLeftCorner<3, 3>() = m * C.transpose();
    I.bottomRightCorner<3, 3>() = m * mat3::Identity();
    return I;
}
inline mat6 spatial_inertia(const body& b) { return spatial_inertia(b.mass, b.com, b.inertia_c); }

// rotation by angle θ about the unit axis u (Rodrigues): R = 1 + sin θ u× + (1 − cos θ) u×²
template <class S = double>
mat3_t<S> axis_angle(const vec3& u, const nondeduced<S>& theta) {
    using std::cos;
    using std::sin;
    const mat3_t<S> U = skew(u).template cast<S>();
    return mat3_t<S>::Identity() + sin(theta) * U + (1 - cos(theta)) * U * U;
}

// the rotation matrix of the unit Hamilton quaternion (w, x, y, z) (normalised here), R v = q v q*
template <class S = double>
mat3_t<S> quaternion_rotation(nondeduced<S> w, nondeduced<S> x, nondeduced<S> y, nondeduced<S> z) {
    using std::sqrt;
    const S n = sqrt(w * w + x * x + y * y + z * z);
    w /= n; x /= n; y /= n; z /= n;
    mat3_t<S> R;
    R << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
         2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
         2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
    return R;
}

// ---------------------------------------------------------------------------------------------
// Joints (RBDA ch. 4, Table 4.1) and the tree's positions.

template <class Scalar>
struct joint_state_t {
    mat3_t<Scalar> R;     // body axes in joint-frame coordinates
    vec3_t<Scalar> t;     // body origin in joint-frame coordinates
    mat6_t<Scalar> XJ;    // ^B X_J = rot(Rᵀ) xlt(t)
    mat6x_t<Scalar> S;    // motion subspace, body coordinates (6 × nv_i)
};
using joint_state = joint_state_t<double>;

// jcalc (RBDA ch. 4): q points at the joint's first position coordinate
template <class S>
joint_state_t<S> jcalc(const body& b, const S* q) {
    joint_state_t<S> j;
    j.R = mat3_t<S>::Identity();
    j.t = vec3_t<S>::Zero();
    switch (b.kind) {
    case joint_kind::revolute:
        j.R = axis_angle<S>(b.axis, q[0]);
        j.S = mat6x_t<S>::Zero(6, 1);
        j.S.col(0).template head<3>() = b.axis.template cast<S>();   // the axis is fixed by the rotation about it
        break;
    case joint_kind::prismatic:
        j.t = q[0] * b.axis.template cast<S>();
        j.S = mat6x_t<S>::Zero(6, 1);
        j.S.col(0).template tail<3>() = b.axis.template cast<S>();
        break;
    case joint_kind::fixed:
        j.S = mat6x_t<S>::Zero(6, 0);
        break;
    case joint_kind::floating:
        j.t = vec3_t<S>(q[0], q[1], q[2]);
        j.R = quaternion_rotation<S>(q[3], q[4], q[5], q[6]);
        j.S = mat6x_t<S>::Identity(6, 6);
        break;
    }
    j.XJ = plucker<S>(j.R.transpose(), j.t);
    return j;
}

// the joint frame's placement in the parent: ^J X_λ = rot(rotationᵀ) xlt(translation)  (X_T, RBDA ch. 4)
inline mat6 tree_transform(const body& b) { return plucker(b.rotation.transpose(), b.translation); }

template <class Vector>
void check_sizes(const model& m, const Vector& q, const nondeduced<Vector>* v,
                 const std::vector<vec6>* f_ext = nullptr) {
    for (int i = 0; i < m.size(); ++i)
        if (m[i].parent < -1 || m[i].parent >= i)
            throw std::invalid_argument("featherstone: body " + std::to_string(i) +
                                        ": parent must be in [-1, i)");
    if (q.size() != m.nq()) throw std::invalid_argument("featherstone: q has the wrong size");
    if (v && v->size() != m.nv()) throw std::invalid_argument("featherstone: a v-sized vector has the wrong size");
    if (f_ext && !f_ext->empty() && static_cast<int>(f_ext->size()) != m.size())
        throw std::invalid_argument("featherstone: f_ext must be empty or have one force per body");
}

// Everything that depends on q only.
template <class Scalar>
struct positions_t {
    std::vector<mat6_t<Scalar>> Xup;     // ^i X_λ(i) = X_J X_T (λ = −1: ^i X_0)
    std::vector<mat6_t<Scalar>> X0;      // ^i X_0 (world → body i), as a product of the Xup
    std::vector<mat6x_t<Scalar>> S;      // motion subspaces, body coordinates
    std::vector<mat3_t<Scalar>> R;       // body axes in world coordinates, composed from the 3×3 placements
    std::vector<vec3_t<Scalar>> p;       // body origin in world coordinates
};
using positions = positions_t<double>;

template <class S = double>
positions_t<S> compute_positions(const model& m, const nondeduced<vecX_t<S>>& q) {
    check_sizes(m, q, nullptr);
    const auto n = static_cast<std::size_t>(m.size());
    positions_t<S> P;
    P.Xup.resize(n); P.X0.resize(n); P.S.resize(n); P.R.resize(n); P.p.resize(n);
    for (int i = 0; i < m.size(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        const body& b = m[i];
        const joint_state_t<S> j = jcalc(b, q.data() + m.q_index(i));
        const auto rotation = b.rotation.template cast<S>();         // (S = double: b.rotation itself)
        const auto translation = b.translation.template cast<S>();
        P.S[k] = j.S;
        P.Xup[k] = j.XJ * tree_transform(b).template cast<S>();
        // world placement by composing rotations and origins directly (not via the 6×6 X)
        const mat3_t<S> Rp = b.parent < 0 ? mat3_t<S>::Identity() : P.R[static_cast<std::size_t>(b.parent)];
        const vec3_t<S> pp = b.parent < 0 ? vec3_t<S>::Zero() : P.p[static_cast<std::size_t>(b.parent)];
        P.R[k] = Rp * rotation * j.R;
        P.p[k] = pp + Rp * (translation + rotation * j.t);
        P.X0[k] = b.parent < 0 ? P.Xup[k] : mat6_t<S>(P.Xup[k] * P.X0[static_cast<std::size_t>(b.parent)]);
    }
    return P;
}

// ---------------------------------------------------------------------------------------------
// Forward kinematics: positions, velocities and accelerations (the forward pass of RBDA
// Table 5.1 with a0 = 0).

struct body_kinematics {
    mat3 rotation;       // body axes in world coordinates (world coords = rotation · body coords + origin)
    vec3 origin;         // body origin in world coordinates
    mat6 X_world;        // ^i X_0: world Plücker coordinates → body coordinates
    vec6 velocity;       // spatial velocity, body coordinates
    vec6 acceleration;   // spatial acceleration (no gravity), body coordinates
};

struct kinematics {
    std::vector<body_kinematics> bodies;
    const body_kinematics& operator[](int i) const { return bodies[static_cast<std::size_t>(i)]; }
};

namespace detail {

// The forward pass of RNEA / ABA (RBDA Table 5.1):
//   v_i = ^iX_λ v_λ + S_i q̇_i,   a_i = ^iX_λ a_λ + S_i q̈_i + c_J + v_i × S_i q̇_i,
// with v_world = 0 and a_world = a0 (world coordinates).
template <class S>
void forward_pass(const model& m, const positions_t<S>& P, const nondeduced<vecX_t<S>>& v,
                  const nondeduced<vecX_t<S>>& a, const nondeduced<vec6_t<S>>& a0,
                  std::vector<vec6_t<S>>& vel, std::vector<vec6_t<S>>& acc) {
    using vec6s = vec6_t<S>;
    const auto n = static_cast<std::size_t>(m.size());
    vel.assign(n, vec6s::Zero());
    acc.assign(n, vec6s::Zero());
    for (int i = 0; i < m.size(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        const int nvi = joint_nv(m[i].kind);
        const vec6s vJ = P.S[k] * v.segment(m.v_index(i), nvi);
        const vec6s vp = m[i].parent < 0 ? vec6s::Zero() : vel[static_cast<std::size_t>(m[i].parent)];
        const vec6s ap = m[i].parent < 0 ? a0 : acc[static_cast<std::size_t>(m[i].parent)];
        vel[k] = P.Xup[k] * vp + vJ;
        acc[k] = P.Xup[k] * ap + P.S[k] * a.segment(m.v_index(i), nvi) + crm<S>(vel[k]) * vJ;   // c_J = 0
    }
}

// −a_g: the fictitious base acceleration that accounts for gravity (RBDA ch. 5)
template <class S = double>
vec6_t<S> gravity_base(const model& m) {
    vec6_t<S> a0 = vec6_t<S>::Zero();
    a0.template tail<3>() = -m.gravity.template cast<S>();
    return a0;
}

}  // namespace detail

inline kinematics fk(const model& m, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                     const Eigen::VectorXd& a) {
    check_sizes(m, q, &v);
    if (a.size() != m.nv()) throw std::invalid_argument("featherstone: a has the wrong size");
    const positions P = compute_positions(m, q);
    std::vector<vec6> vel, acc;
    detail::forward_pass(m, P, v, a, vec6::Zero(), vel, acc);
    kinematics K;
    K.bodies.resize(static_cast<std::size_t>(m.size()));
    for (std::size_t k = 0; k < K.bodies.size(); ++k)
        K.bodies[k] = body_kinematics{P.R[k], P.p[k], P.X0[k], vel[k], acc[k]};
    return K;
}

// ---------------------------------------------------------------------------------------------
// Inverse dynamics: the recursive Newton–Euler algorithm (RBDA Table 5.1).

template <class S = double>
vecX_t<S> rnea(const model& m, const nondeduced<vecX_t<S>>& q, const nondeduced<vecX_t<S>>& v,
               const nondeduced<vecX_t<S>>& a, const std::vector<vec6>& f_ext = {}) {
    check_sizes(m, q, &v, &f_ext);
    if (a.size() != m.nv()) throw std::invalid_argument("featherstone: a has the wrong size");
    const positions_t<S> P = compute_positions<S>(m, q);
    std::vector<vec6_t<S>> vel, acc;
    detail::forward_pass(m, P, v, a, detail::gravity_base<S>(m), vel, acc);
    const auto n = static_cast<std::size_t>(m.size());
    std::vector<vec6_t<S>> f(n);
    // f_i = I_i a_i + v_i ×* I_i v_i − f_i^x                                        (RBDA Table 5.1)
    for (std::size_t k = 0; k < n; ++k) {
        const mat6_t<S> I = spatial_inertia(m.bodies[k]).template cast<S>();
        f[k] = I * acc[k] + crf<S>(vel[k]) * (I * vel[k]);
        if (!f_ext.empty()) f[k] -= f_ext[k].template cast<S>();
    }
    vecX_t<S> tau(m.nv());
    for (int i = m.size() - 1; i >= 0; --i) {
        const auto k = static_cast<std::size_t>(i);
        tau.segment(m.v_index(i), joint_nv(m[i].kind)) = P.S[k].transpose() * f[k];   // Table 5.1
        if (joint_nv(m[i].kind) == 1) tau(m.v_index(i)) += S(m[i].armature) * a(m.v_index(i));   // the rotor
        if (m[i].parent >= 0)                                                        // Table 5.1
            f[static_cast<std::size_t>(m[i].parent)] += P.Xup[k].transpose() * f[k];     // ^λX_i^* = (^iX_λ)ᵀ
    }
    return tau;
}

// ---------------------------------------------------------------------------------------------
// The joint-space inertia matrix: the composite-rigid-body algorithm (RBDA Table 6.2).

template <class S = double>
matX_t<S> crba(const model& m, const nondeduced<vecX_t<S>>& q) {
    const positions_t<S> P = compute_positions<S>(m, q);
    const auto n = static_cast<std::size_t>(m.size());
    std::vector<mat6_t<S>> Ic(n);
    for (std::size_t k = 0; k < n; ++k) Ic[k] = spatial_inertia(m.bodies[k]).template cast<S>();
    matX_t<S> H = matX_t<S>::Zero(m.nv(), m.nv());
    for (int i = m.size() - 1; i >= 0; --i) {
        const auto k = static_cast<std::size_t>(i);
        const int lambda = m[i].parent;
        if (lambda >= 0)   // I^c_λ += ^λX_i^* I^c_i ^iX_λ                                (Table 6.2)
            Ic[static_cast<std::size_t>(lambda)] += P.Xup[k].transpose() * Ic[k] * P.Xup[k];
        const int ni = joint_nv(m[i].kind);
        if (ni == 0) continue;
        const int vi = m.v_index(i);
        mat6x_t<S> F = Ic[k] * P.S[k];                                   // F = I^c_i S_i
        H.block(vi, vi, ni, ni) = P.S[k].transpose() * F;           // H_ii = S_iᵀ F
        if (ni == 1) H(vi, vi) += S(m[i].armature);                  // + the rotor's armature
        int j = i;
        while (m[j].parent >= 0) {
            F = P.Xup[static_cast<std::size_t>(j)].transpose() * F;   // F = ^λX_j^* F
            j = m[j].parent;
            const int nj = joint_nv(m[j].kind);
            if (nj == 0) continue;
            const int vj = m.v_index(j);
            H.block(vi, vj, ni, nj) = F.transpose() * P.S[static_cast<std::size_t>(j)];   // H_ij = Fᵀ S_j
            H.block(vj, vi, nj, ni) = H.block(vi, vj, ni, nj).transpose();
        }
    }
    return H;
}

// ---------------------------------------------------------------------------------------------
// Forward dynamics: the articulated-body algorithm (RBDA Table 7.1).

// the inverse of an n × n matrix, n ≤ 6 (ABA's D_i, symmetric positive definite): Gauss–Jordan
// elimination with partial pivoting, written out (Eigen's LU would cost seconds of compile time
// in every test that includes this file)
template <class S = double>
matn_t<S> inverse_small(const nondeduced<matn_t<S>>& D) {
    using std::abs;
    const Eigen::Index n = D.rows();
    matn_t<S> A = D;
    matn_t<S> B = matn_t<S>::Identity(n, n);
    for (Eigen::Index col = 0; col < n; ++col) {
        Eigen::Index pivot = col;
        for (Eigen::Index r = col + 1; r < n; ++r)
            if (abs(A(r, col)) > abs(A(pivot, col))) pivot = r;
        if (A(pivot, col) == 0) throw std::runtime_error("featherstone: singular joint-space inertia D_i");
        A.row(col).swap(A.row(pivot));
        B.row(col).swap(B.row(pivot));
        const S d = A(col, col);
        A.row(col) /= d;
        B.row(col) /= d;
        for (Eigen::Index r = 0; r < n; ++r) {
            if (r == col) continue;
            const S f = A(r, col);
            A.row(r) -= f * A.row(col);
            B.row(r) -= f * B.row(col);
        }
    }
    return B;
}

template <class S = double>
vecX_t<S> aba(const model& m, const nondeduced<vecX_t<S>>& q, const nondeduced<vecX_t<S>>& v,
              const nondeduced<vecX_t<S>>& tau, const std::vector<vec6>& f_ext = {}) {
    using vec6s = vec6_t<S>;
    using mat6s = mat6_t<S>;
    check_sizes(m, q, &v, &f_ext);
    if (tau.size() != m.nv()) throw std::invalid_argument("featherstone: tau has the wrong size");
    const positions_t<S> P = compute_positions<S>(m, q);
    const auto n = static_cast<std::size_t>(m.size());
    std::vector<vec6s> vel(n), c(n), pA(n), u(n);
    std::vector<mat6s> IA(n);
    std::vector<mat6x_t<S>> U(n);
    std::vector<matn_t<S>> Dinv(n);
    std::vector<vecn_t<S>> uu(n);

    // pass 1 (outwards): velocities, velocity-product accelerations, isolated-body quantities
    for (int i = 0; i < m.size(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        const vec6s vJ = P.S[k] * v.segment(m.v_index(i), joint_nv(m[i].kind));
        const vec6s vp = m[i].parent < 0 ? vec6s::Zero() : vel[static_cast<std::size_t>(m[i].parent)];
        vel[k] = P.Xup[k] * vp + vJ;
        c[k] = crm<S>(vel[k]) * vJ;                                 // c_i = c_J + v_i × v_J  (c_J = 0)
        IA[k] = spatial_inertia(m.bodies[k]).template cast<S>();    // I^A_i = I_i
        pA[k] = crf<S>(vel[k]) * (IA[k] * vel[k]);                  // p^A_i = v_i ×* I_i v_i − f^x_i
        if (!f_ext.empty()) pA[k] -= f_ext[k].template cast<S>();
    }
    // pass 2 (inwards): articulated-body inertias and bias forces
    for (int i = m.size() - 1; i >= 0; --i) {
        const auto k = static_cast<std::size_t>(i);
        const int ni = joint_nv(m[i].kind);
        // the articulated inertia and bias force that body i's subtree passes to its parent
        // through the joint; for a fixed joint (no dofs) I^a_i = I^A_i, p^a_i = p^A_i + I^A_i c_i
        mat6s Ia = IA[k];
        vec6s pa = pA[k];
        if (ni > 0) {
            U[k] = IA[k] * P.S[k];                                  // U_i = I^A_i S_i
            matn_t<S> D = P.S[k].transpose() * U[k];                // D_i = S_iᵀ U_i
            if (ni == 1) D(0, 0) += S(m[i].armature);                 // + the rotor's armature
            Dinv[k] = inverse_small<S>(D);
            uu[k] = tau.segment(m.v_index(i), ni) - P.S[k].transpose() * pA[k];   // u_i = τ_i − S_iᵀ p^A_i
            Ia -= U[k] * Dinv[k] * U[k].transpose();                // I^a_i = I^A_i − U D⁻¹ Uᵀ
            pa += U[k] * Dinv[k] * uu[k];
        }
        pa += Ia * c[k];                                            // p^a_i = p^A_i + I^a_i c_i + U D⁻¹ u
        if (m[i].parent >= 0) {
            const auto l = static_cast<std::size_t>(m[i].parent);
            IA[l] += P.Xup[k].transpose() * Ia * P.Xup[k];          // I^A_λ += ^λX_i^* I^a_i ^iX_λ
            pA[l] += P.Xup[k].transpose() * pa;                     // p^A_λ += ^λX_i^* p^a_i
        }
    }
    // pass 3 (outwards): accelerations
    vecX_t<S> qdd = vecX_t<S>::Zero(m.nv());
    std::vector<vec6s> acc(n);
    const vec6s a0 = detail::gravity_base<S>(m);
    for (int i = 0; i < m.size(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        const int ni = joint_nv(m[i].kind);
        const vec6s ap = m[i].parent < 0 ? a0 : acc[static_cast<std::size_t>(m[i].parent)];
        const vec6s a_prime = P.Xup[k] * ap + c[k];                 // a'_i = ^iX_λ a_λ + c_i
        acc[k] = a_prime;
        if (ni > 0) {
            const vecn_t<S> qddi = Dinv[k] * (uu[k] - U[k].transpose() * a_prime);   // Table 7.1
            qdd.segment(m.v_index(i), ni) = qddi;
            acc[k] += P.S[k] * qddi;                                // a_i = a'_i + S_i q̈_i
        }
    }
    return qdd;
}

// ---------------------------------------------------------------------------------------------
// Jacobians, energies, the position-derivative map.

// J with v_i (body i's spatial velocity, body i coordinates) = J v: the columns of body j's
// joint, for j on the path from body i to the root, are ^iX_j S_j (RBDA ch. 4)
inline Eigen::MatrixXd jacobian_body(const model& m, const Eigen::VectorXd& q, int i) {
    if (i < 0 || i >= m.size()) throw std::invalid_argument("featherstone: no such body");
    const positions P = compute_positions(m, q);
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(6, m.nv());
    mat6 X = mat6::Identity();   // ^iX_j
    for (int j = i; j >= 0; j = m[j].parent) {
        const auto k = static_cast<std::size_t>(j);
        const int nj = joint_nv(m[j].kind);
        if (nj > 0) J.block(0, m.v_index(j), 6, nj) = X * P.S[k];
        X = X * P.Xup[k];
    }
    return J;
}

// the same velocity in world Plücker coordinates (about the world origin): ^0X_i J_body
inline Eigen::MatrixXd jacobian_world(const model& m, const Eigen::VectorXd& q, int i) {
    const positions P = compute_positions(m, q);
    // (lazyProduct: the plain coefficient-wise product, see mat6x)
    return plucker_inverse(P.X0[static_cast<std::size_t>(i)]).lazyProduct(jacobian_body(m, q, i));
}

// T = ½ Σ v_iᵀ I_i v_i
inline double kinetic_energy(const model& m, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
    const kinematics K = fk(m, q, v, Eigen::VectorXd::Zero(m.nv()));
    double T = 0;
    for (int i = 0; i < m.size(); ++i) {
        T += 0.5 * K[i].velocity.dot(spatial_inertia(m[i]) * K[i].velocity);
        if (joint_nv(m[i].kind) == 1) T += 0.5 * m[i].armature * v(m.v_index(i)) * v(m.v_index(i));   // the rotor
    }
    return T;
}

// V = −Σ m_i g · c_i, c_i = body i's centre of mass in world coordinates
inline double potential_energy(const model& m, const Eigen::VectorXd& q) {
    const positions P = compute_positions(m, q);
    double V = 0;
    for (int i = 0; i < m.size(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        V -= m[i].mass * m.gravity.dot(P.p[k] + P.R[k] * m[i].com);
    }
    return V;
}

// q̇ from v (nq numbers): revolute / prismatic q̇ = v; floating: the origin's rate is R v_lin
// (R = the body's orientation in the joint frame), the quaternion's rate is ½ q ⊗ (0, ω).
inline Eigen::VectorXd q_dot(const model& m, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
    check_sizes(m, q, &v);
    Eigen::VectorXd qd(m.nq());
    for (int i = 0; i < m.size(); ++i) {
        const int iq = m.q_index(i), iv = m.v_index(i);
        switch (m[i].kind) {
        case joint_kind::revolute:
        case joint_kind::prismatic: qd[iq] = v[iv]; break;
        case joint_kind::fixed: break;
        case joint_kind::floating: {
            const double w = q[iq + 3];
            const vec3 e(q[iq + 4], q[iq + 5], q[iq + 6]);
            const vec3 om = v.segment<3>(iv);
            const vec3 lin = v.segment<3>(iv + 3);
            qd.segment<3>(iq) = quaternion_rotation(w, e.x(), e.y(), e.z()) * lin;
            qd[iq + 3] = -0.5 * e.dot(om);
            qd.segment<3>(iq + 4) = 0.5 * (w * om + e.cross(om));
            break;
        }
        }
    }
    return qd;
}

}  // namespace ctga::test::featherstone
