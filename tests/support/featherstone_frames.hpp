// Frames, centre of mass, centroidal momentum, mimic joints and the lumping of fixed links for
// the Featherstone reference (tests/support/featherstone.hpp; read its header comment first:
// the model, the joints, the motion / force vector conventions and the Plücker transforms are
// all its). Tests only, plain Eigen, written from RBDA (R. Featherstone, "Rigid Body Dynamics
// Algorithms", 2008), D. Orin & A. Goswami, "Centroidal momentum matrix of a humanoid robot"
// (2008/2013) and Pinocchio's documented frame conventions; it shares no code with ctga.
//
// Frames. A frame is fixed in one body (`parent`, −1 = the world): its axes are the columns of
// `rotation` and its origin is `translation`, both in the parent body's coordinates (for the
// world: in world coordinates). Its Plücker transform from the body is
//   ^F X_B = plucker(rotationᵀ, translation).
//
// The three coordinate systems for a frame's motion (Pinocchio's ReferenceFrame):
//   local               : Plücker coordinates of the frame itself: (ω, v) in frame axes, v the
//                         velocity of the body-fixed point at the frame origin;
//   world               : Plücker coordinates of the world frame: (ω, v) in world axes, v the
//                         velocity of the body-fixed point that is momentarily at the world origin;
//   local_world_aligned : the local numbers rotated into world axes, i.e. (ω, ṗ) in world axes
//                         with ṗ the velocity of the frame origin (the Plücker coordinates of a
//                         frame with world axes placed, at this instant, at the frame origin).
// Spatial accelerations (the time derivative of the spatial velocity field, RBDA ch. 2; never
// gravity) are given in the same three coordinate systems: local = the time derivative of the
// local velocity numbers (the frame moves with the body), world = the time derivative of the
// world velocity numbers, local_world_aligned = the local spatial acceleration rotated into world
// axes (this is NOT the time derivative of the local_world_aligned velocity numbers; see
// frame_jacobian_dot). The classical acceleration of the frame origin is p̈ (a 3-vector), in
// frame axes (local) or world axes (world, local_world_aligned); in local coordinates it is
// v̇ + ω × v of the local spatial acceleration (v̇) and velocity (ω, v).
//
// Functions (q: nq, v / a: nv numbers, as in featherstone.hpp):
//   frame_pose(m, q, f)                          world rotation (columns = frame axes) and origin
//   frame_velocity(m, q, v, f, ref)              6-vector (ω, v)
//   frame_acceleration(m, q, v, a, f, ref)       6-vector, spatial acceleration, no gravity
//   frame_classical_acceleration(m, q, v, a, f, ref)   3-vector p̈ of the frame origin
//   frame_jacobian(m, q, f, ref)                 6 × nv, frame_velocity(q, v, f, ref) = J v
//   frame_jacobian_dot(m, q, v, f, ref)          6 × nv, dJ/dt along q̇ = q_dot(q, v)
//   total_mass, center_of_mass, center_of_mass_velocity, center_of_mass_jacobian,
//   subtree_centers_of_mass                      (world coordinates)
//   centroidal_momentum(m, q, v), centroidal_momentum_matrix(m, q)   (n, f) about the com
//   mimic_coupling; mimic_nq, mimic_nv, expand_q, reduce_q, mimic_matrix (G), rnea_mimic,
//   crba_mimic, aba_mimic, jacobian_mimic        (reduced coordinates)
//   merge_fixed(m, frames)                       bodies on fixed joints lumped into their parents
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "support/featherstone.hpp"

namespace ctga::test::featherstone {

// ---------------------------------------------------------------------------------------------
// Frames.

struct frame {
    int parent = -1;                    // the body the frame is fixed in, −1 = the world
    mat3 rotation = mat3::Identity();   // frame axes (columns) in parent-body coordinates
    vec3 translation = vec3::Zero();    // frame origin in parent-body coordinates
};

enum class reference { local, world, local_world_aligned };

// a placement in world coordinates: world coords of a point = rotation · frame coords + origin
struct pose {
    mat3 rotation = mat3::Identity();   // frame axes (columns) in world coordinates
    vec3 origin = vec3::Zero();         // frame origin in world coordinates
};

namespace detail {

inline void check_frame(const model& m, const frame& f) {
    if (f.parent < -1 || f.parent >= m.size())
        throw std::invalid_argument("featherstone: frame parent must be in [-1, size)");
}

// rot(R) = diag(R, R): a pure rotation as a Plücker transform (R = axes of the old frame in the
// new one's coordinates; the origin stays)
inline mat6 rotate6(const mat3& R) {
    mat6 X = mat6::Zero();
    X.topLeftCorner<3, 3>() = R;
    X.bottomRightCorner<3, 3>() = R;
    return X;
}

// ^F X_B, the frame's fixed transform from its parent body (or from the world)
inline mat6 frame_from_parent(const frame& f) { return plucker(f.rotation.transpose(), f.translation); }

// ^F X_0 (world Plücker coordinates → frame coordinates)
inline mat6 frame_from_world(const positions& P, const frame& f) {
    const mat6 XFB = frame_from_parent(f);
    return f.parent < 0 ? XFB : mat6(XFB * P.X0[static_cast<std::size_t>(f.parent)]);
}

inline pose frame_pose(const positions& P, const frame& f) {
    if (f.parent < 0) return pose{f.rotation, f.translation};
    const auto b = static_cast<std::size_t>(f.parent);
    return pose{P.R[b] * f.rotation, P.p[b] + P.R[b] * f.translation};
}

// body spatial velocities and accelerations (no gravity), body coordinates
inline void body_motion(const model& m, const positions& P, const Eigen::VectorXd& v,
                        const Eigen::VectorXd& a, std::vector<vec6>& vel, std::vector<vec6>& acc) {
    if (v.size() != m.nv()) throw std::invalid_argument("featherstone: v has the wrong size");
    if (a.size() != m.nv()) throw std::invalid_argument("featherstone: a has the wrong size");
    forward_pass(m, P, v, a, vec6::Zero(), vel, acc);
}

// a local motion 6-vector (frame coordinates) in the coordinate system `ref`
inline vec6 from_local(const positions& P, const frame& f, const vec6& x_local, reference ref) {
    switch (ref) {
    case reference::local: return x_local;
    case reference::world: return plucker_inverse(frame_from_world(P, f)) * x_local;   // ^0X_F
    case reference::local_world_aligned: return rotate6(frame_pose(P, f).rotation) * x_local;
    }
    return x_local;
}

// 6 × nv Jacobian of the body's spatial velocity in world Plücker coordinates (the columns of
// joint j, for j on the path from `body` to the root, are ^0X_j S_j) and, if `vel_world` is
// given (every body's spatial velocity in world coordinates), its time derivative, whose
// columns are (^0X_j v_j) ×_motion (^0X_j S_j): S_j is constant in body j's coordinates
// (c_J = 0 for all four joint kinds) and d/dt ^0X_j = (v_j^world ×) ^0X_j.
inline void jacobian_world_and_dot(const model& m, const positions& P, int body,
                                   const std::vector<vec6>* vel_world, Eigen::MatrixXd& J,
                                   Eigen::MatrixXd* Jdot) {
    J = Eigen::MatrixXd::Zero(6, m.nv());
    if (Jdot) *Jdot = Eigen::MatrixXd::Zero(6, m.nv());
    for (int j = body; j >= 0; j = m[j].parent) {
        const auto k = static_cast<std::size_t>(j);
        const int nj = joint_nv(m[j].kind);
        if (nj == 0) continue;
        const mat6x Sw = plucker_inverse(P.X0[k]) * P.S[k];
        J.block(0, m.v_index(j), 6, nj) = Sw;
        if (Jdot) Jdot->block(0, m.v_index(j), 6, nj) = crm((*vel_world)[k]) * Sw;
    }
}

}  // namespace detail

// The frame's world placement.
inline pose frame_pose(const model& m, const Eigen::VectorXd& q, const frame& f) {
    detail::check_frame(m, f);
    return detail::frame_pose(compute_positions(m, q), f);
}

// The frame's spatial velocity (ω, v) in `ref` (see the header comment). A world frame: zero.
inline vec6 frame_velocity(const model& m, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                           const frame& f, reference ref) {
    detail::check_frame(m, f);
    const positions P = compute_positions(m, q);
    std::vector<vec6> vel, acc;
    detail::body_motion(m, P, v, Eigen::VectorXd::Zero(m.nv()), vel, acc);
    if (f.parent < 0) return vec6::Zero();
    const vec6 local = detail::frame_from_parent(f) * vel[static_cast<std::size_t>(f.parent)];
    return detail::from_local(P, f, local, ref);
}

// The frame's spatial acceleration in `ref`, gravity not included: local = ^FX_B a_B (the time
// derivative of the local velocity numbers), world = ^0X_F of that (the time derivative of the
// world velocity numbers), local_world_aligned = diag(R_F, R_F) · local.
inline vec6 frame_acceleration(const model& m, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                               const Eigen::VectorXd& a, const frame& f, reference ref) {
    detail::check_frame(m, f);
    const positions P = compute_positions(m, q);
    std::vector<vec6> vel, acc;
    detail::body_motion(m, P, v, a, vel, acc);
    if (f.parent < 0) return vec6::Zero();
    const vec6 local = detail::frame_from_parent(f) * acc[static_cast<std::size_t>(f.parent)];
    return detail::from_local(P, f, local, ref);
}

// p̈, the classical acceleration of the frame origin (no gravity): in frame axes for local, in
// world axes for world and local_world_aligned. From the local spatial velocity (ω, v) and
// acceleration (ω̇, v̇): p̈ (frame axes) = v̇ + ω × v.
inline vec3 frame_classical_acceleration(const model& m, const Eigen::VectorXd& q,
                                         const Eigen::VectorXd& v, const Eigen::VectorXd& a,
                                         const frame& f, reference ref) {
    detail::check_frame(m, f);
    const positions P = compute_positions(m, q);
    std::vector<vec6> vel, acc;
    detail::body_motion(m, P, v, a, vel, acc);
    if (f.parent < 0) return vec3::Zero();
    const auto b = static_cast<std::size_t>(f.parent);
    const mat6 XFB = detail::frame_from_parent(f);
    const vec6 vl = XFB * vel[b], al = XFB * acc[b];
    const vec3 local = al.tail<3>() + vl.head<3>().cross(vl.tail<3>());
    if (ref == reference::local) return local;
    return detail::frame_pose(P, f).rotation * local;
}

// J (6 × nv) with frame_velocity(m, q, v, f, ref) = J v for every v: world = ^0X_B J_B-world
// columns ^0X_j S_j; local = ^FX_0 J_world; local_world_aligned = diag(R_F, R_F) J_local.
// A world frame: zero.
inline Eigen::MatrixXd frame_jacobian(const model& m, const Eigen::VectorXd& q, const frame& f,
                                      reference ref) {
    detail::check_frame(m, f);
    const positions P = compute_positions(m, q);
    if (f.parent < 0) return Eigen::MatrixXd::Zero(6, m.nv());
    Eigen::MatrixXd Jw;
    detail::jacobian_world_and_dot(m, P, f.parent, nullptr, Jw, nullptr);
    const mat6 XF0 = detail::frame_from_world(P, f);
    switch (ref) {
    case reference::world: return Jw;
    case reference::local: return XF0.lazyProduct(Jw);
    case reference::local_world_aligned:
        return mat6(detail::rotate6(detail::frame_pose(P, f).rotation) * XF0).lazyProduct(Jw);
    }
    return Jw;
}

// J̇ (6 × nv) = d/dt frame_jacobian(m, q(t), f, ref) along the motion with q̇ = q_dot(q, v),
// computed analytically:
//   world : column of joint j (an ancestor of the frame's body, or the body) = v_j^w × ^0X_j S_j,
//           v_j^w = body j's spatial velocity in world coordinates;
//   local : J_l = ^FX_0 J_w and d/dt ^FX_0 = −(v_F ×) ^FX_0 (v_F = the local frame velocity), so
//           J̇_l = ^FX_0 J̇_w − v_F × J_l;
//   local_world_aligned : J_lwa = A J_w with A = plucker(1, p_F) (world axes, origin p_F, the
//           frame origin), Ȧ = [[0, 0], [−ṗ_F ×, 0]], so J̇_lwa = A J̇_w + Ȧ J_w.
// Identities (a = the acceleration coordinates, v̇):
//   local, world : frame_acceleration(q, v, a, f, ref) = J a + J̇ v;
//   local_world_aligned : J a + J̇ v = d/dt (the local_world_aligned velocity numbers (ω, ṗ))
//           = (ω̇, p̈) in world axes = (the angular part of frame_acceleration(…, lwa),
//             frame_classical_acceleration(…, world)),
//           which differs from frame_acceleration(…, local_world_aligned) = (ω̇, p̈ − ω × ṗ) by
//           (0, ω × ṗ). (Differentiating Pinocchio's LOCAL_WORLD_ALIGNED Jacobian gives this
//           matrix; the derivation above, not Pinocchio's code, is what this reference states.)
inline Eigen::MatrixXd frame_jacobian_dot(const model& m, const Eigen::VectorXd& q,
                                          const Eigen::VectorXd& v, const frame& f, reference ref) {
    detail::check_frame(m, f);
    const positions P = compute_positions(m, q);
    std::vector<vec6> vel, acc;
    detail::body_motion(m, P, v, Eigen::VectorXd::Zero(m.nv()), vel, acc);
    if (f.parent < 0) return Eigen::MatrixXd::Zero(6, m.nv());
    std::vector<vec6> vel_world(vel.size());
    for (std::size_t k = 0; k < vel.size(); ++k) vel_world[k] = plucker_inverse(P.X0[k]) * vel[k];
    Eigen::MatrixXd Jw, Jdw;
    detail::jacobian_world_and_dot(m, P, f.parent, &vel_world, Jw, &Jdw);
    const vec6& vb = vel_world[static_cast<std::size_t>(f.parent)];
    switch (ref) {
    case reference::world: return Jdw;
    case reference::local: {
        const mat6 XF0 = detail::frame_from_world(P, f);
        const vec6 vF = XF0 * vb;
        const Eigen::MatrixXd Jl = XF0.lazyProduct(Jw);
        return Eigen::MatrixXd(XF0.lazyProduct(Jdw)) - crm(vF).lazyProduct(Jl);
    }
    case reference::local_world_aligned: {
        const mat6 A = plucker(mat3::Identity(), detail::frame_pose(P, f).origin);
        const vec3 pdot = (A * vb).tail<3>();   // velocity of the body point at the frame origin
        mat6 Adot = mat6::Zero();
        Adot.bottomLeftCorner<3, 3>() = -skew(pdot);
        return Eigen::MatrixXd(A.lazyProduct(Jdw)) + Adot.lazyProduct(Jw);
    }
    }
    return Jdw;
}

// ---------------------------------------------------------------------------------------------
// Centre of mass (world coordinates).

inline double total_mass(const model& m) {
    double M = 0;
    for (const body& b : m.bodies) M += b.mass;
    return M;
}

// c = Σ m_i c_i / M, c_i = body i's com in world coordinates; throws if M = 0
inline vec3 center_of_mass(const model& m, const Eigen::VectorXd& q) {
    const double M = total_mass(m);
    if (!(M > 0)) throw std::invalid_argument("featherstone: center_of_mass of a massless model");
    const positions P = compute_positions(m, q);
    vec3 c = vec3::Zero();
    for (int i = 0; i < m.size(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        c += m[i].mass * (P.p[k] + P.R[k] * m[i].com);
    }
    return c / M;
}

// J_c (3 × nv, world axes): ċ = J_c v. Body i's com moves with R_i (v_i + ω_i × c_i) (body
// coordinates (ω_i, v_i) = J_body,i v), i.e. R_i (J_lin − c_i× J_ang).
inline Eigen::MatrixXd center_of_mass_jacobian(const model& m, const Eigen::VectorXd& q) {
    const double M = total_mass(m);
    if (!(M > 0)) throw std::invalid_argument("featherstone: center_of_mass_jacobian of a massless model");
    const positions P = compute_positions(m, q);
    Eigen::MatrixXd Jc = Eigen::MatrixXd::Zero(3, m.nv());
    for (int i = 0; i < m.size(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        const Eigen::MatrixXd Jb = jacobian_body(m, q, i);
        const Eigen::MatrixXd point = Jb.bottomRows(3) - skew(m[i].com).lazyProduct(Jb.topRows(3));
        Jc += (m[i].mass / M) * Eigen::MatrixXd(P.R[k].lazyProduct(point));
    }
    return Jc;
}

// ċ = Σ m_i ċ_i / M, world axes
inline vec3 center_of_mass_velocity(const model& m, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
    const double M = total_mass(m);
    if (!(M > 0)) throw std::invalid_argument("featherstone: center_of_mass_velocity of a massless model");
    const positions P = compute_positions(m, q);
    std::vector<vec6> vel, acc;
    detail::body_motion(m, P, v, Eigen::VectorXd::Zero(m.nv()), vel, acc);
    vec3 cd = vec3::Zero();
    for (int i = 0; i < m.size(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        const vec3 vc = vel[k].tail<3>() + vel[k].head<3>().cross(m[i].com);   // body axes
        cd += m[i].mass * (P.R[k] * vc);
    }
    return cd / M;
}

struct subtree_mass {
    double mass = 0;            // body i and all its descendants
    vec3 com = vec3::Zero();    // their centre of mass, world coordinates (the body origin if mass = 0)
};

// per body (tree order): the mass and world com of the body and all its descendants
inline std::vector<subtree_mass> subtree_centers_of_mass(const model& m, const Eigen::VectorXd& q) {
    const positions P = compute_positions(m, q);
    const auto n = static_cast<std::size_t>(m.size());
    std::vector<double> mass(n, 0);
    std::vector<vec3> moment(n, vec3::Zero());   // Σ m c
    for (int i = m.size() - 1; i >= 0; --i) {
        const auto k = static_cast<std::size_t>(i);
        mass[k] += m[i].mass;
        moment[k] += m[i].mass * (P.p[k] + P.R[k] * m[i].com);
        if (m[i].parent >= 0) {
            mass[static_cast<std::size_t>(m[i].parent)] += mass[k];
            moment[static_cast<std::size_t>(m[i].parent)] += moment[k];
        }
    }
    std::vector<subtree_mass> out(n);
    for (std::size_t k = 0; k < n; ++k)
        out[k] = subtree_mass{mass[k], mass[k] > 0 ? vec3(moment[k] / mass[k]) : P.p[k]};
    return out;
}

// ---------------------------------------------------------------------------------------------
// Centroidal momentum (Orin & Goswami): the total spatial momentum about the centre of mass c,
// world axes, as a force vector (n, f) = (angular momentum about c, linear momentum).
// h_0 = Σ ^0X*_i I_i v_i = Σ (^iX_0)ᵀ I_i v_i (about the world origin), then h_G = ^GX*_0 h_0
// with G = (world axes, origin c): ^GX*_0 = [[1, −c×], [0, 1]] (n_G = n_0 − c × f).

inline mat6 centroidal_force_transform(const vec3& c) { return force_transform(plucker(mat3::Identity(), c)); }

inline vec6 centroidal_momentum(const model& m, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
    const positions P = compute_positions(m, q);
    std::vector<vec6> vel, acc;
    detail::body_motion(m, P, v, Eigen::VectorXd::Zero(m.nv()), vel, acc);
    vec6 h0 = vec6::Zero();
    for (int i = 0; i < m.size(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        h0 += P.X0[k].transpose() * (spatial_inertia(m[i]) * vel[k]);
    }
    return centroidal_force_transform(center_of_mass(m, q)) * h0;
}

// A_G (6 × nv): centroidal_momentum(q, v) = A_G v; A_G = ^GX*_0 Σ (^iX_0)ᵀ I_i J_body,i
inline Eigen::MatrixXd centroidal_momentum_matrix(const model& m, const Eigen::VectorXd& q) {
    const positions P = compute_positions(m, q);
    Eigen::MatrixXd A0 = Eigen::MatrixXd::Zero(6, m.nv());
    for (int i = 0; i < m.size(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        const mat6 XI = P.X0[k].transpose() * spatial_inertia(m[i]);
        A0 += Eigen::MatrixXd(XI.lazyProduct(jacobian_body(m, q, i)));
    }
    return centroidal_force_transform(center_of_mass(m, q)).lazyProduct(A0);
}

// ---------------------------------------------------------------------------------------------
// Mimic joints. Each coupling makes body `follower`'s joint (revolute or prismatic, 1 dof)
// follow body `leader`'s joint (revolute or prismatic, 1 dof, not itself a follower):
//   q_follower = ratio · q_leader + offset   (so v_follower = ratio · v_leader, likewise a).
// A body is a follower at most once. Reduced coordinates: the coordinates of every joint that is
// not a follower, in tree order (q_r: mimic_nq numbers, v_r / a_r / τ_r: mimic_nv numbers).
// With G (nv × mimic_nv) = ∂v/∂v_r (identity rows for the independent joints, `ratio` in the
// leader's column on the follower's row):
//   rnea_mimic = Gᵀ rnea(expand_q(q_r), G v_r, G a_r, f_ext)  (generalised forces of the
//                independent coordinates: the follower's joint force is passed on through G)
//   crba_mimic = Gᵀ H G
//   aba_mimic  = (Gᵀ H G)⁻¹ (τ_r − Gᵀ rnea(expand_q(q_r), G v_r, 0, f_ext))
//   jacobian_mimic = frame_jacobian(expand_q(q_r)) G
// (Ġ = 0: ratios are constants, so G a_r is the full acceleration.)

struct mimic_coupling {
    int follower = -1;   // body whose joint follows
    int leader = -1;     // body whose joint it follows
    double ratio = 1;
    double offset = 0;
};

namespace detail {

inline bool one_dof(joint_kind k) { return k == joint_kind::revolute || k == joint_kind::prismatic; }

// per body: is its joint a follower? (validates the couplings)
inline std::vector<bool> followers(const model& m, const std::vector<mimic_coupling>& c) {
    std::vector<bool> is(static_cast<std::size_t>(m.size()), false);
    for (const mimic_coupling& x : c) {
        if (x.follower < 0 || x.follower >= m.size() || x.leader < 0 || x.leader >= m.size() ||
            x.follower == x.leader)
            throw std::invalid_argument("featherstone: mimic coupling: bad body indices");
        if (!one_dof(m[x.follower].kind) || !one_dof(m[x.leader].kind))
            throw std::invalid_argument("featherstone: mimic coupling: joints must be revolute or prismatic");
        if (is[static_cast<std::size_t>(x.follower)])
            throw std::invalid_argument("featherstone: mimic coupling: a body follows twice");
        is[static_cast<std::size_t>(x.follower)] = true;
    }
    for (const mimic_coupling& x : c)
        if (is[static_cast<std::size_t>(x.leader)])
            throw std::invalid_argument("featherstone: mimic coupling: a leader must be independent");
    return is;
}

// where each independent body's coordinates start in q_r (resp. v_r); −1 for followers
inline std::vector<int> reduced_index(const model& m, const std::vector<bool>& is_follower, bool velocity) {
    std::vector<int> idx(static_cast<std::size_t>(m.size()), -1);
    int n = 0;
    for (int i = 0; i < m.size(); ++i) {
        if (is_follower[static_cast<std::size_t>(i)]) continue;
        idx[static_cast<std::size_t>(i)] = n;
        n += velocity ? joint_nv(m[i].kind) : joint_nq(m[i].kind);
    }
    return idx;
}

// Cholesky solve of H x = b (H symmetric positive definite), written out
inline Eigen::VectorXd solve_spd(const Eigen::MatrixXd& H, const Eigen::VectorXd& b) {
    const Eigen::Index n = H.rows();
    Eigen::MatrixXd L = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index j = 0; j < n; ++j) {
        double d = H(j, j);
        for (Eigen::Index k = 0; k < j; ++k) d -= L(j, k) * L(j, k);
        if (!(d > 0)) throw std::runtime_error("featherstone: matrix not positive definite");
        L(j, j) = std::sqrt(d);
        for (Eigen::Index i = j + 1; i < n; ++i) {
            double x = H(i, j);
            for (Eigen::Index k = 0; k < j; ++k) x -= L(i, k) * L(j, k);
            L(i, j) = x / L(j, j);
        }
    }
    Eigen::VectorXd y(n), x(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        double s = b[i];
        for (Eigen::Index k = 0; k < i; ++k) s -= L(i, k) * y[k];
        y[i] = s / L(i, i);
    }
    for (Eigen::Index i = n - 1; i >= 0; --i) {
        double s = y[i];
        for (Eigen::Index k = i + 1; k < n; ++k) s -= L(k, i) * x[k];
        x[i] = s / L(i, i);
    }
    return x;
}

}  // namespace detail

inline int mimic_nq(const model& m, const std::vector<mimic_coupling>& c) {
    return m.nq() - static_cast<int>(c.size());
}
inline int mimic_nv(const model& m, const std::vector<mimic_coupling>& c) {
    return m.nv() - static_cast<int>(c.size());
}

// the full q (nq) from the reduced q_r: independent joints copied, followers r q_leader + o
inline Eigen::VectorXd expand_q(const model& m, const std::vector<mimic_coupling>& c,
                                const Eigen::VectorXd& q_r) {
    const std::vector<bool> is = detail::followers(m, c);
    if (q_r.size() != mimic_nq(m, c)) throw std::invalid_argument("featherstone: q_r has the wrong size");
    const std::vector<int> rq = detail::reduced_index(m, is, false);
    Eigen::VectorXd q(m.nq());
    for (int i = 0; i < m.size(); ++i)
        if (!is[static_cast<std::size_t>(i)])
            q.segment(m.q_index(i), joint_nq(m[i].kind)) = q_r.segment(rq[static_cast<std::size_t>(i)], joint_nq(m[i].kind));
    for (const mimic_coupling& x : c)
        q[m.q_index(x.follower)] = x.ratio * q[m.q_index(x.leader)] + x.offset;
    return q;
}

// q_r from a full q: the independent joints' coordinates (the followers' are dropped, unchecked)
inline Eigen::VectorXd reduce_q(const model& m, const std::vector<mimic_coupling>& c,
                                const Eigen::VectorXd& q) {
    const std::vector<bool> is = detail::followers(m, c);
    if (q.size() != m.nq()) throw std::invalid_argument("featherstone: q has the wrong size");
    const std::vector<int> rq = detail::reduced_index(m, is, false);
    Eigen::VectorXd q_r(mimic_nq(m, c));
    for (int i = 0; i < m.size(); ++i)
        if (!is[static_cast<std::size_t>(i)])
            q_r.segment(rq[static_cast<std::size_t>(i)], joint_nq(m[i].kind)) = q.segment(m.q_index(i), joint_nq(m[i].kind));
    return q_r;
}

// G (nv × mimic_nv): v = G v_r
inline Eigen::MatrixXd mimic_matrix(const model& m, const std::vector<mimic_coupling>& c) {
    const std::vector<bool> is = detail::followers(m, c);
    const std::vector<int> rv = detail::reduced_index(m, is, true);
    Eigen::MatrixXd G = Eigen::MatrixXd::Zero(m.nv(), mimic_nv(m, c));
    for (int i = 0; i < m.size(); ++i) {
        if (is[static_cast<std::size_t>(i)]) continue;
        const int n = joint_nv(m[i].kind);
        G.block(m.v_index(i), rv[static_cast<std::size_t>(i)], n, n).setIdentity();
    }
    for (const mimic_coupling& x : c)
        G(m.v_index(x.follower), rv[static_cast<std::size_t>(x.leader)]) = x.ratio;
    return G;
}

inline Eigen::VectorXd rnea_mimic(const model& m, const std::vector<mimic_coupling>& c,
                                  const Eigen::VectorXd& q_r, const Eigen::VectorXd& v_r,
                                  const Eigen::VectorXd& a_r, const std::vector<vec6>& f_ext = {}) {
    const Eigen::MatrixXd G = mimic_matrix(m, c);
    if (v_r.size() != G.cols() || a_r.size() != G.cols())
        throw std::invalid_argument("featherstone: v_r / a_r have the wrong size");
    const Eigen::VectorXd v = G.lazyProduct(v_r), a = G.lazyProduct(a_r);
    return G.transpose().lazyProduct(rnea(m, expand_q(m, c, q_r), v, a, f_ext));
}

inline Eigen::MatrixXd crba_mimic(const model& m, const std::vector<mimic_coupling>& c,
                                  const Eigen::VectorXd& q_r) {
    const Eigen::MatrixXd G = mimic_matrix(m, c);
    const Eigen::MatrixXd GtH = G.transpose().lazyProduct(crba(m, expand_q(m, c, q_r)));
    return GtH.lazyProduct(G);
}

inline Eigen::VectorXd aba_mimic(const model& m, const std::vector<mimic_coupling>& c,
                                 const Eigen::VectorXd& q_r, const Eigen::VectorXd& v_r,
                                 const Eigen::VectorXd& tau_r, const std::vector<vec6>& f_ext = {}) {
    const Eigen::MatrixXd G = mimic_matrix(m, c);
    if (v_r.size() != G.cols() || tau_r.size() != G.cols())
        throw std::invalid_argument("featherstone: v_r / tau_r have the wrong size");
    const Eigen::VectorXd bias = rnea_mimic(m, c, q_r, v_r, Eigen::VectorXd::Zero(G.cols()), f_ext);
    return detail::solve_spd(crba_mimic(m, c, q_r), tau_r - bias);
}

// frame_jacobian(expand_q(q_r), f, ref) G: frame_velocity(expand_q(q_r), G v_r, f, ref) = J v_r
inline Eigen::MatrixXd jacobian_mimic(const model& m, const std::vector<mimic_coupling>& c,
                                      const Eigen::VectorXd& q_r, const frame& f, reference ref) {
    const Eigen::MatrixXd G = mimic_matrix(m, c);
    return frame_jacobian(m, expand_q(m, c, q_r), f, ref).lazyProduct(G);
}

// ---------------------------------------------------------------------------------------------
// Lumping fixed links. merge_fixed(m, frames) returns a model in which every body on a fixed
// joint is merged into its parent (transitively: into its nearest ancestor on a non-fixed joint,
// or into the world):
//   * its spatial inertia is added to that ancestor's, in the ancestor's coordinates, with the
//     composite-inertia step of RBDA Table 6.2: I_a += X_cᵀ I_c X_c, X_c = ^cX_a; the sum is
//     turned back into (mass, com, inertia_c). A body merged into the world is dropped (the
//     world does not move: joint-space dynamics are unchanged, but total_mass and the centre of
//     mass of the merged model no longer count it);
//   * its children are re-parented to that ancestor, their joint frames composed with the fixed
//     placement (joint axes stay in their joint frames, so they are unchanged);
//   * the given frames are re-expressed on the surviving ancestor (or the world).
// Fixed joints have no coordinates, so q, v, a and τ are the same numbers for both models.

struct merged_model {
    model merged;
    std::vector<int> body_map;     // old body → new body, −1 = merged into the world
    std::vector<pose> placement;   // old body's frame in the new body's coordinates (world's if −1)
    std::vector<frame> frames;     // the given frames, on the new bodies
};

// (mass, com, inertia_c) from a spatial inertia about the body origin (RBDA eq. 2.63 read back)
inline body inertia_parameters(body b, const mat6& I) {
    b.mass = I(3, 3);
    const mat3 mC = I.topRightCorner<3, 3>();   // m c×
    b.com = b.mass > 0 ? vec3(vec3(mC(2, 1), mC(0, 2), mC(1, 0)) / b.mass) : vec3::Zero();
    const mat3 C = skew(b.com);
    const mat3 Ic = I.topLeftCorner<3, 3>() - b.mass * C * C.transpose();
    b.inertia_c = 0.5 * (Ic + Ic.transpose());
    return b;
}

inline merged_model merge_fixed(const model& m, const std::vector<frame>& frames = {}) {
    for (int i = 0; i < m.size(); ++i)
        if (m[i].parent < -1 || m[i].parent >= i)
            throw std::invalid_argument("featherstone: merge_fixed: parent must be in [-1, i)");
    for (const frame& f : frames) detail::check_frame(m, f);
    const auto n = static_cast<std::size_t>(m.size());
    merged_model out;
    out.merged.gravity = m.gravity;
    out.body_map.assign(n, -1);
    out.placement.assign(n, pose{});
    std::vector<mat6> inertia;   // per new body, about its origin, its coordinates
    for (int i = 0; i < m.size(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        const body& b = m[i];
        // the joint frame J_i in the coordinates of the surviving ancestor (or the world)
        const int a = b.parent < 0 ? -1 : out.body_map[static_cast<std::size_t>(b.parent)];
        const pose pp = b.parent < 0 ? pose{} : out.placement[static_cast<std::size_t>(b.parent)];
        const mat3 RJ = pp.rotation * b.rotation;
        const vec3 tJ = pp.origin + pp.rotation * b.translation;
        if (b.kind == joint_kind::fixed) {   // B_i = J_i
            out.body_map[k] = a;
            out.placement[k] = pose{RJ, tJ};
            if (a >= 0) {
                const mat6 Xc = plucker(RJ.transpose(), tJ);   // ^cX_a
                inertia[static_cast<std::size_t>(a)] += Xc.transpose() * spatial_inertia(b) * Xc;
            }
        } else {
            body nb = b;
            nb.parent = a;
            nb.rotation = RJ;
            nb.translation = tJ;
            out.body_map[k] = out.merged.size();
            out.placement[k] = pose{};
            out.merged.bodies.push_back(nb);
            inertia.push_back(spatial_inertia(b));
        }
    }
    for (std::size_t k = 0; k < inertia.size(); ++k)
        out.merged.bodies[k] = inertia_parameters(out.merged.bodies[k], inertia[k]);
    for (const frame& f : frames) {
        if (f.parent < 0) {
            out.frames.push_back(f);
            continue;
        }
        const pose& pl = out.placement[static_cast<std::size_t>(f.parent)];
        out.frames.push_back(frame{out.body_map[static_cast<std::size_t>(f.parent)], pl.rotation * f.rotation,
                                   pl.origin + pl.rotation * f.translation});
    }
    return out;
}

}  // namespace ctga::test::featherstone
