// Random kinematic trees, states and forces for the Featherstone reference
// (tests/support/featherstone.hpp) and the tests that compare against it.
//
// Only the raw 64-bit output of the engine is used (uniforms from its top 53 bits, normals by
// Box–Muller), so a seed gives the same models with every standard library.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "support/featherstone.hpp"

namespace ctga::test::featherstone {

struct random_tree_options {
    int min_bodies = 1;
    int max_bodies = 30;
    // which joint kinds may appear (a model may also end up using only some of them)
    bool revolute = true;
    bool prismatic = true;
    bool fixed = true;
    // probability that body 0 gets a floating joint (to the world)
    double floating_base_probability = 0.3;
    // allow floating joints on other bodies too (a 6-dof joint to its parent)
    bool floating_children = false;
    // probability that a body's parent is the previous body (long chains) rather than any
    // earlier body or the world
    double chain_probability = 0.5;
    // probability that a body other than body 0 is attached to the world (a forest)
    double world_parent_probability = 0.05;
    // half-width of the random joint-frame translations, centre-of-mass offsets
    double placement_scale = 0.5;
    double com_scale = 0.3;
    // masses are uniform in [mass_min, mass_max]
    double mass_min = 0.5;
    double mass_max = 2.0;
    // the principal radii of gyration g_x, g_y, g_z are uniform in [gyration_min, gyration_max]
    double gyration_min = 0.05;
    double gyration_max = 0.3;
};

// uniform in [0, 1) from the top 53 bits
inline double uniform01(std::mt19937_64& rng) {
    return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}
inline double uniform(std::mt19937_64& rng, double lo, double hi) { return lo + (hi - lo) * uniform01(rng); }
inline int uniform_int(std::mt19937_64& rng, int lo, int hi) {   // [lo, hi]
    const auto span = static_cast<std::uint64_t>(hi - lo + 1);
    return lo + static_cast<int>(rng() % span);
}
inline double normal(std::mt19937_64& rng) {   // Box–Muller
    const double u1 = 1.0 - uniform01(rng);      // (0, 1]
    const double u2 = uniform01(rng);
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}
inline vec3 uniform_vec3(std::mt19937_64& rng, double half_width) {
    return vec3(uniform(rng, -half_width, half_width), uniform(rng, -half_width, half_width),
                uniform(rng, -half_width, half_width));
}
inline vec3 random_unit_vec3(std::mt19937_64& rng) {
    for (;;) {
        const vec3 x(normal(rng), normal(rng), normal(rng));
        const double n = x.norm();
        if (n > 1e-3) return x / n;
    }
}
// uniformly distributed unit quaternion (w, x, y, z) with w ≥ 0
inline Eigen::Vector4d random_quaternion(std::mt19937_64& rng) {
    for (;;) {
        Eigen::Vector4d x(normal(rng), normal(rng), normal(rng), normal(rng));
        const double n = x.norm();
        if (n > 1e-3) {
            x /= n;
            return x[0] < 0 ? Eigen::Vector4d(-x) : x;
        }
    }
}
inline mat3 random_rotation(std::mt19937_64& rng) {
    const Eigen::Vector4d u = random_quaternion(rng);
    return quaternion_rotation(u[0], u[1], u[2], u[3]);
}

// A physically valid rotational inertia about the com: from positive second moments
// s = (Σ m x², Σ m y², Σ m z²) = m (g_x², g_y², g_z²) in principal axes, I_p = diag(s_y + s_z,
// s_x + s_z, s_x + s_y) (so the triangle inequality holds), turned: I = R I_p Rᵀ.
inline mat3 random_inertia_c(std::mt19937_64& rng, double mass, double gmin, double gmax) {
    vec3 s;
    for (int k = 0; k < 3; ++k) {
        const double g = uniform(rng, gmin, gmax);
        s[k] = mass * g * g;
    }
    const vec3 principal(s.y() + s.z(), s.x() + s.z(), s.x() + s.y());
    const mat3 R = random_rotation(rng);
    const mat3 I = R * principal.asDiagonal() * R.transpose();
    return 0.5 * (I + I.transpose());
}

inline model random_tree(std::mt19937_64& rng, const random_tree_options& opt = {}) {
    std::vector<joint_kind> kinds;
    if (opt.revolute) kinds.push_back(joint_kind::revolute);
    if (opt.prismatic) kinds.push_back(joint_kind::prismatic);
    if (opt.fixed) kinds.push_back(joint_kind::fixed);
    if (opt.floating_children) kinds.push_back(joint_kind::floating);
    if (kinds.empty()) kinds.push_back(joint_kind::revolute);

    model m;
    const int n = uniform_int(rng, opt.min_bodies, opt.max_bodies);
    const bool floating_base = uniform01(rng) < opt.floating_base_probability;
    for (int i = 0; i < n; ++i) {
        body b;
        if (i == 0) {
            b.parent = -1;
        } else if (uniform01(rng) < opt.world_parent_probability) {
            b.parent = -1;
        } else if (uniform01(rng) < opt.chain_probability) {
            b.parent = i - 1;
        } else {
            b.parent = uniform_int(rng, 0, i - 1);
        }
        b.kind = (i == 0 && floating_base)
                     ? joint_kind::floating
                     : kinds[static_cast<std::size_t>(uniform_int(rng, 0, static_cast<int>(kinds.size()) - 1))];
        b.axis = random_unit_vec3(rng);
        b.rotation = random_rotation(rng);
        b.translation = uniform_vec3(rng, opt.placement_scale);
        b.mass = uniform(rng, opt.mass_min, opt.mass_max);
        b.com = uniform_vec3(rng, opt.com_scale);
        b.inertia_c = random_inertia_c(rng, b.mass, opt.gyration_min, opt.gyration_max);
        m.bodies.push_back(b);
    }
    return m;
}

// A random configuration: revolute angles in [−π, π], prismatic offsets in [−0.5, 0.5],
// floating origins in [−1, 1]³ with a uniformly random unit quaternion.
inline Eigen::VectorXd random_q(std::mt19937_64& rng, const model& m) {
    Eigen::VectorXd q(m.nq());
    for (int i = 0; i < m.size(); ++i) {
        const int iq = m.q_index(i);
        switch (m[i].kind) {
        case joint_kind::revolute: q[iq] = uniform(rng, -std::numbers::pi, std::numbers::pi); break;
        case joint_kind::prismatic: q[iq] = uniform(rng, -0.5, 0.5); break;
        case joint_kind::fixed: break;
        case joint_kind::floating:
            q.segment<3>(iq) = uniform_vec3(rng, 1.0);
            q.segment<4>(iq + 3) = random_quaternion(rng);
            break;
        }
    }
    return q;
}

// uniform in [−scale, scale]^n
inline Eigen::VectorXd random_vector(std::mt19937_64& rng, int n, double scale = 1.0) {
    Eigen::VectorXd x(n);
    for (int k = 0; k < n; ++k) x[k] = uniform(rng, -scale, scale);
    return x;
}

// one random spatial force per body, components uniform in [−scale, scale]
inline std::vector<vec6> random_forces(std::mt19937_64& rng, const model& m, double scale = 1.0) {
    std::vector<vec6> f(static_cast<std::size_t>(m.size()));
    for (vec6& x : f) x = random_vector(rng, 6, scale);
    return f;
}

}  // namespace ctga::test::featherstone
