// The kinematic trees of the chain benchmarks, each given once as plain numbers (description)
// and built from them for both implementations: ctga::chains (the tree a type) and the
// hand-written spatial code (bench/spatial_chains.hpp, the tree run-time data).
//
//   arm7       7 revolute joints about z, y, z, y, z, y, z, frames 0.3 m apart (a 7-dof arm)
//   chain30    30 revolute joints cycling z, y, x, frames 0.1 m apart
//   tree       a floating base with four legs of three revolute joints (hip x, thigh y, knee y)
//   quadruped  the same shape with a real robot's numbers (Solo 12, feet merged)
//   humanoid   a floating pelvis, two legs of six joints, torso, head, two arms of seven and
//              hands: 39 bodies, 44 dofs
// arm7 has a named frame "tool" on its last body, tree a "foot" at the end of its front left leg
// (frame_placement: turned and offset, for the frame Jacobians).
//   chain<N>   N revolute joints cycling z, y, x (the scaling benchmarks, 1 … 64 bodies)
//
// Masses, centres of mass and inertia tensors are drawn once from a fixed seed: full tensors,
// centres of mass off the joint axes, so no product is structurally zero by accident of the data.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <random>
#include <stdexcept>
#include <utility>

#include <ctga/ctga.hpp>

#include "chain_trees.hpp"
#include "spatial_chains.hpp"

namespace bench::chains {

namespace ch = ctga::chains;
namespace sp = spatial::chains;

struct body_description {
    int parent;
    sp::joint_kind kind;
    std::array<double, 3> t;                   // joint frame in the parent's: translation (rotation: identity)
    double mass;
    std::array<double, 3> com;
    std::array<std::array<double, 3>, 3> Ic;  // about the centre of mass
};

template <std::size_t N>
using description = std::array<body_description, N>;

// Mass properties from principal second moments m g² (triangle inequality holds), turned about a
// random axis.
inline void random_inertia(std::mt19937_64& rng, body_description& b) {
    std::uniform_real_distribution<double> u(-1, 1);
    b.mass = 1.5 + u(rng);
    const double g[3] = {0.05 + 0.03 * u(rng), 0.06 + 0.03 * u(rng), 0.04 + 0.02 * u(rng)};
    const double s[3] = {b.mass * g[0] * g[0], b.mass * g[1] * g[1], b.mass * g[2] * g[2]};
    const double d[3] = {s[1] + s[2], s[0] + s[2], s[0] + s[1]};
    double ax[3] = {u(rng), u(rng), 1};
    const double n = std::sqrt(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
    for (double& x : ax) x /= n;
    const double th = 3 * u(rng), c = std::cos(th), s1 = std::sin(th), v = 1 - c;
    const double R[3][3] = {{c + v * ax[0] * ax[0], v * ax[0] * ax[1] - s1 * ax[2], v * ax[0] * ax[2] + s1 * ax[1]},
                            {v * ax[1] * ax[0] + s1 * ax[2], c + v * ax[1] * ax[1], v * ax[1] * ax[2] - s1 * ax[0]},
                            {v * ax[2] * ax[0] - s1 * ax[1], v * ax[2] * ax[1] + s1 * ax[0], c + v * ax[2] * ax[2]}};
    for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) {
            double x = 0;
            for (int k = 0; k < 3; ++k) x += R[i][k] * d[k] * R[j][k];
            b.Ic[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = b.Ic[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)] = x;
        }
    b.com = {0.02 * u(rng), 0.02 * u(rng), 0.1 + 0.02 * u(rng)};
}

// A serial chain of N revolute joints cycling through the axes of `cycle`, frames `step` apart.
template <std::size_t N>
description<N> serial(const std::array<sp::joint_kind, 3>& cycle, std::size_t cycle_length, double step, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    description<N> d{};
    for (std::size_t i = 0; i < N; ++i) {
        d[i].parent = static_cast<int>(i) - 1;
        d[i].kind = cycle[i % cycle_length];
        d[i].t = {0, 0, i == 0 ? 0.0 : step};
        random_inertia(rng, d[i]);
    }
    return d;
}

// ---- the benchmarked trees -----------------------------------------------------------------------

inline description<7> arm7() {
    return serial<7>({sp::joint_kind::revolute_z, sp::joint_kind::revolute_y, sp::joint_kind::revolute_z}, 2, 0.3, 7);
}

template <std::size_t N>
description<N> chain() {
    return serial<N>({sp::joint_kind::revolute_z, sp::joint_kind::revolute_y, sp::joint_kind::revolute_x}, 3, 0.1, 30 + N);
}

inline description<13> legged() {
    std::mt19937_64 rng(13);
    description<13> d{};
    d[0] = {-1, sp::joint_kind::floating, {0, 0, 0}, 0, {}, {}};
    random_inertia(rng, d[0]);
    d[0].mass = 10;
    const double hip[4][2] = {{0.3, 0.15}, {0.3, -0.15}, {-0.3, 0.15}, {-0.3, -0.15}};
    for (int leg = 0; leg < 4; ++leg)
        for (int j = 0; j < 3; ++j) {
            body_description& b = d[static_cast<std::size_t>(1 + 3 * leg + j)];
            b.parent = j == 0 ? 0 : 3 * leg + j;
            b.kind = j == 0 ? sp::joint_kind::revolute_x : sp::joint_kind::revolute_y;
            b.t = j == 0 ? std::array<double, 3>{hip[leg][0], hip[leg][1], 0} : std::array<double, 3>{0, 0, j == 1 ? -0.05 : -0.25};
            random_inertia(rng, b);
        }
    return d;
}

inline description<39> humanoid() {
    using k = sp::joint_kind;
    std::mt19937_64 rng(39);
    description<39> d{};
    const auto put = [&](std::size_t i, int parent, k kind, std::array<double, 3> t) {
        d[i].parent = parent;
        d[i].kind = kind;
        d[i].t = t;
        random_inertia(rng, d[i]);
    };
    put(0, -1, k::floating, {0, 0, 0});
    d[0].mass = 8;
    for (int side = 0; side < 2; ++side) {
        const double y = side == 0 ? 1 : -1;
        const std::size_t leg = side == 0 ? 1 : 7, arm = side == 0 ? 17 : 28, hand = arm + 7;
        const int l = static_cast<int>(leg), a = static_cast<int>(arm);
        put(leg, 0, k::revolute_z, {0, 0.1 * y, -0.1});
        put(leg + 1, l, k::revolute_x, {0, 0, -0.05});
        put(leg + 2, l + 1, k::revolute_y, {0, 0, -0.05});
        put(leg + 3, l + 2, k::revolute_y, {0, 0, -0.4});
        put(leg + 4, l + 3, k::revolute_y, {0, 0, -0.4});
        put(leg + 5, l + 4, k::revolute_x, {0, 0, -0.05});
        put(arm, 14, k::revolute_y, {0, 0.2 * y, 0.25});
        put(arm + 1, a, k::revolute_x, {0, 0.05 * y, 0});
        put(arm + 2, a + 1, k::revolute_z, {0, 0, -0.1});
        put(arm + 3, a + 2, k::revolute_y, {0, 0, -0.2});
        put(arm + 4, a + 3, k::revolute_z, {0, 0, -0.1});
        put(arm + 5, a + 4, k::revolute_y, {0, 0, -0.15});
        put(arm + 6, a + 5, k::revolute_x, {0, 0, -0.05});
        put(hand, a + 6, k::revolute_z, {0.02, 0.02 * y, -0.05});
        put(hand + 1, static_cast<int>(hand), k::revolute_y, {0, 0, -0.03});
        put(hand + 2, a + 6, k::revolute_y, {-0.02, 0, -0.08});
        put(hand + 3, static_cast<int>(hand) + 2, k::revolute_y, {0, 0, -0.04});
    }
    put(13, 0, k::revolute_z, {0, 0, 0.1});
    put(14, 13, k::revolute_y, {0, 0, 0.1});
    put(15, 14, k::revolute_z, {0, 0, 0.35});
    put(16, 15, k::revolute_y, {0, 0, 0.05});
    return d;
}

// A rigid body fixed to b (a fixed joint merged, as the URDF loader merges fixed links): mass m,
// centre c and second moments Ic about c, in b's frame; b's centre and Ic move to the sum's
// (parallel axes: Ic + m (|d|² 1 − d dᵀ), d from the new centre).
inline void attach(body_description& b, double m, const std::array<double, 3>& c, const std::array<std::array<double, 3>, 3>& Ic) {
    const double M = b.mass + m;
    std::array<double, 3> com{};
    for (std::size_t i = 0; i < 3; ++i) com[i] = (b.mass * b.com[i] + m * c[i]) / M;
    const auto shifted = [&](double mass, const std::array<double, 3>& at, const std::array<std::array<double, 3>, 3>& I) {
        const std::array<double, 3> d{at[0] - com[0], at[1] - com[1], at[2] - com[2]};
        const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        std::array<std::array<double, 3>, 3> out = I;
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = 0; j < 3; ++j) out[i][j] += mass * ((i == j ? dd : 0.0) - d[i] * d[j]);
        return out;
    };
    const auto a = shifted(b.mass, b.com, b.Ic), e = shifted(m, c, Ic);
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) b.Ic[i][j] = a[i][j] + e[i][j];
    b.mass = M;
    b.com = com;
}

// A real quadruped, merged: Solo 12 (solo12.urdf of a public collection of robot descriptions,
// BSD 3-Clause, Copyright (C) 2018-2020 LAAS-CNRS, University of Edinburgh, INRIA), the legged
// tree's shape with the URDF's numbers: joint origins (no rotations), axes x, y, y, and each
// link's inertial, the feet (fixed joints at (0, ±0.008, −0.16)) merged into the lower legs.
inline description<13> solo12() {
    description<13> d{};
    d[0] = {-1, sp::joint_kind::floating, {0, 0, 0}, 1.16115091, {0, 0, 0}, {{{0.00578574, 0, 0}, {0, 0.01938108, 0}, {0, 0, 0.02476124}}}};
    for (int leg = 0; leg < 4; ++leg) {
        const double x = leg < 2 ? 1.0 : -1.0, y = leg % 2 == 0 ? 1.0 : -1.0;  // FL, FR, HL, HR
        const std::size_t b = static_cast<std::size_t>(1 + 3 * leg);
        d[b] = {0, sp::joint_kind::revolute_x, {0.1946 * x, 0.0875 * y, 0}, 0.14853845, {-0.078707 * x, 0.01 * y, 0},
                {{{0.00003024, 0.00004671 * y, 0}, {0.00004671 * y, 0.00041193, 0}, {0, 0, 0.00041107}}}};
        d[b + 1] = {static_cast<int>(b), sp::joint_kind::revolute_y, {0, 0.014 * y, 0}, 0.14853845, {0.00001377 * y, 0.01935853 * y, -0.078707},
                    {{{0.00041107, 0, 0}, {0, 0.00041193, 0.00004671 * y}, {0, 0.00004671 * y, 0.00003024}}}};
        d[b + 2] = {static_cast<int>(b + 1), sp::joint_kind::revolute_y, {0, 0.03745 * y, -0.16}, 0.03070001, {0, 0.00787644 * y, -0.08928215},
                    {{{0.00012024, 0, 0}, {0, 0.00012029, 0.00000305 * y}, {0, 0.00000305 * y, 0.00000216}}}};
        attach(d[b + 2], 0.00693606, {0, 0.008 * y, -0.16 + 0.00035767}, {{{0.00000057, 0, 0}, {0, 0.00000084, 0}, {0, 0, 0.00000053}}});
    }
    return d;
}

// ---- building both implementations' models -----------------------------------------------------

// Frame 0's placement in its body (both trees' frames): 0.25 m along the body's −z, turned 0.7 rad
// about (1, 2, 2)/3.
inline constexpr std::array<double, 3> frame_offset{0.02, -0.01, -0.25};
inline constexpr std::array<double, 4> frame_rotation{0.7, 1.0 / 3, 2.0 / 3, 2.0 / 3};  // angle, unit axis

template <class J>
constexpr sp::joint_kind kind_of() {
    if constexpr (std::is_same_v<J, ch::revolute_x> || std::is_same_v<J, ch::aligned<ch::revolute_x>>) return sp::joint_kind::revolute_x;
    else if constexpr (std::is_same_v<J, ch::revolute_y> || std::is_same_v<J, ch::aligned<ch::revolute_y>>) return sp::joint_kind::revolute_y;
    else if constexpr (std::is_same_v<J, ch::revolute_z> || std::is_same_v<J, ch::aligned<ch::revolute_z>>) return sp::joint_kind::revolute_z;
    else if constexpr (std::is_same_v<J, ch::floating> || std::is_same_v<J, ch::aligned<ch::floating>>) return sp::joint_kind::floating;
    else return sp::joint_kind::fixed;
}

template <class Tree, std::size_t N>
ch::model<Tree> ctga_model(const description<N>& d) {
    static_assert(Tree::size == N);
    ch::model<Tree> m;
    m.gravity = {0, 0, -9.81};
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ([&] {
            using J = typename Tree::template joint_at<I>;
            const body_description& b = d[I];
            if (Tree::parent[I] != b.parent || kind_of<J>() != b.kind) throw std::logic_error("chain_models: tree type and description differ");
            const auto link = ch::make_link<J>(ctga::motor<double>(ctga::make_translator(b.t[0], b.t[1], b.t[2])),
                                               ctga::make_mass_properties(b.mass, ctga::vec3<double>{b.com[0], b.com[1], b.com[2]}, b.Ic));
            if (!link) throw std::logic_error(ctga::describe(link.error));
            m.template link<I>() = *link;
        }(), ...);
    }(std::make_index_sequence<N>{});
    if constexpr (Tree::frame_count > 0)
        m.frames[0] = *ch::make_frame(ctga::rigid_motion(ctga::make_translator(frame_offset[0], frame_offset[1], frame_offset[2]),
                                                         ctga::make_rotor(frame_rotation[0], frame_rotation[1], frame_rotation[2],
                                                                          frame_rotation[3])));
    return m;
}

// The same placement for the spatial code.
inline spatial::se3 spatial_frame() {
    const double th = frame_rotation[0], x = frame_rotation[1], y = frame_rotation[2], z = frame_rotation[3];
    const double c = std::cos(th), s = std::sin(th), v = 1 - c;
    return {{{c + v * x * x, v * x * y - s * z, v * x * z + s * y},
             {v * y * x + s * z, c + v * y * y, v * y * z - s * x},
             {v * z * x - s * y, v * z * y + s * x, c + v * z * z}},
            {frame_offset[0], frame_offset[1], frame_offset[2]}};
}

template <std::size_t N>
sp::model<N> spatial_model(const description<N>& d) {
    sp::model<N> m{};
    for (std::size_t i = 0; i < N; ++i) {
        const body_description& b = d[i];
        m.bodies[i] = {b.parent,
                       b.kind,
                       {0, 0, 1},
                       {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                       {b.t[0], b.t[1], b.t[2]},
                       {b.mass, {b.com[0], b.com[1], b.com[2]}, {b.Ic[0][0], b.Ic[0][1], b.Ic[1][1], b.Ic[0][2], b.Ic[1][2], b.Ic[2][2]}}};
    }
    m.n = N;
    m.gravity = {0, 0, -9.81};
    sp::finalize(m);
    return m;
}

// One state in both layouts: ctga's floating q is a motor (8 numbers), the spatial code's is
// (x, y, z, qw, qx, qy, qz).
template <class Tree>
struct state {
    ch::configuration<Tree> q{};
    std::array<double, Tree::nq> q_spatial{};  // (the first nq − size_of_floating_difference used)
    ch::joint_vector<Tree> qd{}, qdd{}, tau{};
};

template <class Tree>
std::array<state<Tree>, 64> random_states(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::array<state<Tree>, 64> out{};
    for (state<Tree>& s : out) {
        std::size_t qs = 0;
        for (std::size_t i = 0; i < Tree::size; ++i) {
            const std::size_t o = Tree::q_offset[i];
            if (Tree::nq_of[i] == 8) {
                double ax[3] = {u(rng), u(rng), 1};
                const double n = std::sqrt(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
                const double th = 2 * u(rng), x = u(rng), y = u(rng), z = 0.5 + 0.2 * u(rng);
                const ctga::motor<double> g =
                    ctga::rigid_motion(ctga::make_translator(x, y, z), ctga::make_rotor(th, ax[0] / n, ax[1] / n, ax[2] / n));
                for (std::size_t k = 0; k < 8; ++k) s.q[o + k] = g[k];
                const double w = std::cos(th / 2), sh = std::sin(th / 2);
                const double qs7[7] = {x, y, z, w, sh * ax[0] / n, sh * ax[1] / n, sh * ax[2] / n};
                for (double c : qs7) s.q_spatial[qs++] = c;
            } else if (Tree::nq_of[i] == 1) {
                s.q[o] = s.q_spatial[qs++] = 2 * u(rng);
            }
        }
        for (std::size_t k = 0; k < Tree::nv; ++k) s.qd[k] = u(rng), s.qdd[k] = 3 * u(rng), s.tau[k] = 5 * u(rng);
    }
    return out;
}

}  // namespace bench::chains
