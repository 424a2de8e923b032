// The centre of mass of a kinematic tree (and of each body's subtree), its velocity and its
// Jacobian, from the bodies' world poses and velocities (forward_kinematics.hpp).
//
// Body i's inertia holds m_i and its first moment h_i = m_i c_i in its frame (body_inertia.hpp),
// so its mass-weighted centre in the world is m_i c_i,w = R_i h_i + m_i t_i (no division per
// body), and its linear momentum m_i ċ_i,w = R_i (m_i v_i + ω_i × h_i) (the momentum's linear
// part p = m v − h × ω, §5, in world axes). A subtree's centre is the sum over its bodies over the
// sum of their masses.
//
// The Jacobian: joint j moves the whole subtree of body j rigidly with its world column (ω, v)
// (frame_jacobian.hpp), so the centre of mass of that subtree, c_j, moves at v + ω × c_j, and the
// whole robot's at (M_j / M)(v + ω × c_j): one column per joint from the subtree centres.
#pragma once

#include <array>
#include <cstddef>

#include "ctga/chains/arguments.hpp"
#include "ctga/chains/frame_jacobian.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/mechanics/body_inertia.hpp"
#include "ctga/mechanics/linear3.hpp"

namespace ctga::chains {

// A mass and its centre, world coordinates.
template <class T = double>
struct mass_center {
    T mass{};
    vec3<T> position{};
};
template <class T = double>
struct center_of_mass_state {
    T mass{};
    vec3<T> position{};  // world
    vec3<T> velocity{};  // world (zero when k carries no velocities)
};

namespace com_detail {
template <class T>
constexpr vec3<T> scaled(const vec3<T>& x, const T& s) noexcept {
    return {x[0] * s, x[1] * s, x[2] * s};
}
// Σ over each body's subtree of m_i c_i,w and m_i: the first moments and masses, world.
template <class Tree, class T>
constexpr void subtree_moments(const model<Tree, T>& m, const kinematics<Tree, T>& k, std::array<vec3<T>, Tree::size>& h,
                               std::array<T, Tree::size>& mass) noexcept {
    algorithm_detail::forward<Tree::size>([&](auto body) {
        constexpr std::size_t i = decltype(body)::value;
        const body_inertia<T>& N = m.template link<i>().inertia;
        mass[i] = N.mass();
        h[i] = linear3::add(linear3::apply(k.pose[i].R, N.first_moment()), scaled(k.pose[i].t, mass[i]));
    });
    for (std::size_t i = Tree::size; i-- > 0;)
        if (Tree::parent[i] >= 0) {
            const auto p = static_cast<std::size_t>(Tree::parent[i]);
            h[p] = linear3::add(h[p], h[i]);
            mass[p] += mass[i];
        }
}
}  // namespace com_detail

struct center_of_mass_t {
    // The whole robot's mass, centre of mass and its velocity (k: forward_kinematics(m, q[, q̇])).
    // A robot without mass has no centre: its position and velocity are NaN.
    template <class Tree, class T>
    [[nodiscard]] constexpr center_of_mass_state<T> operator()(const model<Tree, T>& m, const kinematics<Tree, T>& k) const noexcept {
        center_of_mass_state<T> out;
        vec3<T> h{}, p{};
        algorithm_detail::forward<Tree::size>([&](auto body) {
            constexpr std::size_t i = decltype(body)::value;
            const body_inertia<T>& N = m.template link<i>().inertia;
            const motor_map<T>& W = k.pose[i];
            out.mass += N.mass();
            h = linear3::add(h, linear3::add(linear3::apply(W.R, N.first_moment()), com_detail::scaled(W.t, N.mass())));
            // linear momentum m v − h × ω in body axes, then world axes
            const vec3<T> w = frame_detail::angular(k.v[i]), v = frame_detail::linear(k.v[i]);
            const vec3<T> pb = linear3::add(com_detail::scaled(v, N.mass()), linear3::cross(w, N.first_moment()));
            p = linear3::add(p, linear3::apply(W.R, pb));
        });
        const T inv = T(1) / out.mass;
        out.position = com_detail::scaled(h, inv);
        out.velocity = com_detail::scaled(p, inv);
        return out;
    }
};
inline constexpr algorithm<center_of_mass_t, "center_of_mass"> center_of_mass{};

struct subtree_centers_of_mass_t {
    // For each body, the mass and centre of mass of it and everything it carries (k: poses).
    template <class Tree, class T>
    [[nodiscard]] constexpr std::array<mass_center<T>, Tree::size> operator()(const model<Tree, T>& m,
                                                                              const kinematics<Tree, T>& k) const noexcept {
        std::array<vec3<T>, Tree::size> h;
        std::array<T, Tree::size> mass;
        com_detail::subtree_moments(m, k, h, mass);
        std::array<mass_center<T>, Tree::size> out;
        for (std::size_t i = 0; i < Tree::size; ++i) out[i] = {mass[i], com_detail::scaled(h[i], T(1) / mass[i])};
        return out;
    }
};
inline constexpr algorithm<subtree_centers_of_mass_t, "subtree_centers_of_mass"> subtree_centers_of_mass{};

template <class Tree, class T = double>
using center_of_mass_jacobian_matrix = std::array<vec3<T>, Tree::nv>;  // column k: ċ per unit q̇_k, world

struct center_of_mass_jacobian_t {
    // J_c with ċ = J_c q̇ (world axes); k: forward_kinematics(m, q).
    template <class Tree, class T>
    [[nodiscard]] constexpr center_of_mass_jacobian_matrix<Tree, T> operator()(const model<Tree, T>& m,
                                                                               const kinematics<Tree, T>& k) const noexcept {
        std::array<vec3<T>, Tree::size> h;
        std::array<T, Tree::size> mass;
        com_detail::subtree_moments(m, k, h, mass);
        T total{};  // the roots' subtrees together
        for (std::size_t i = 0; i < Tree::size; ++i)
            if (Tree::parent[i] < 0) total += mass[i];
        const T inv_total = T(1) / total;
        // column of joint j: (ω, v) world, (M_j v + ω × h_j) / M, h_j = M_j c_j
        jacobian_matrix<Tree, T> J{};  // the columns as screws (ω, ċ): put_column's weights for mimic joints
        algorithm_detail::forward<Tree::size>([&](auto body) {
            constexpr std::size_t j = decltype(body)::value;
            using Jt = typename Tree::template joint_at<j>;
            if constexpr (moves<Jt>)
                [&]<std::size_t... K>(std::index_sequence<K...>) {
                    (frame_detail::put_column<j, K>(m, J, column(k.pose[j], Jt::template subspace<K, T>(m.template link<j>().joint),
                                                                   h[j], mass[j], inv_total)),
                     ...);
                }(std::make_index_sequence<is_mimic<Jt> ? 1 : Jt::nv>{});
        });
        center_of_mass_jacobian_matrix<Tree, T> out;
        for (std::size_t c = 0; c < Tree::nv; ++c) out[c] = frame_detail::linear(J[c]);
        return out;
    }
    // … from q.
    template <class Tree, class T>
    [[nodiscard]] constexpr center_of_mass_jacobian_matrix<Tree, T> operator()(const model<Tree, T>& m,
                                                                               const configuration<Tree, T>& q) const noexcept {
        return (*this)(m, forward_kinematics(m, q));
    }

private:
    template <class T, class S>
    static constexpr screw<T> column(const motor_map<T>& G, const S& s, const vec3<T>& h, const T& mass, const T& inv_total) noexcept {
        const screw<T> c = frame_detail::moved_out(G, s);
        const vec3<T> w = frame_detail::angular(c);
        const vec3<T> x = com_detail::scaled(linear3::add(com_detail::scaled(frame_detail::linear(c), mass), linear3::cross(w, h)), inv_total);
        return screw<T>{T(0), T(0), T(0), x[0], x[1], x[2]};
    }
};
inline constexpr algorithm<center_of_mass_jacobian_t, "center_of_mass_jacobian"> center_of_mass_jacobian{};

}  // namespace ctga::chains
