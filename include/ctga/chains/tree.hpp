// A kinematic tree whose structure is a type (paper §7; Featherstone (2008) §4.1): body i has a
// parent λ(i) < i (−1: the fixed world) and a joint joining it to that parent. The structure
// is known to the compiler, so the algorithms (algorithms.hpp) are unrolled over the bodies,
// each with its own joint's code, and a parent that is not an earlier body is a compile error.
//
//   using arm = chains::tree<chains::link<-1, chains::revolute_z>,
//                            chains::link<0, chains::revolute_y>,
//                            chains::link<1, chains::revolute_y>>;
//   chains::model<arm> m;               // run-time parameters, filled by make_link
//
// Run-time parameters per body (link_parameters): the placement of its joint frame in the
// parent's frame (a motor, kept as its motor_map (R, t)), its inertia by the ten parameters of
// body_inertia (m, h = m c, I_o, in the body frame), and the joint's own parameters (the unit
// axis of revolute_about and prismatic_along). Plus gravity, in world coordinates.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>

#include <boost/hana/at.hpp>
#include <boost/hana/tuple.hpp>

#include "ctga/chains/joints.hpp"
#include "ctga/mechanics/body_inertia.hpp"
#include "ctga/mechanics/mass_properties.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga::chains {

// Body i of a tree: its parent's index (−1 for the world) and its joint.
template <int Parent, joint Joint>
struct link {
    static constexpr int parent = Parent;
    using joint_type = Joint;
};

template <class... Links>
struct tree {
    static constexpr std::size_t size = sizeof...(Links);
    static constexpr std::array<int, size> parent{Links::parent...};
    static constexpr bool parents_precede = [] {
        for (std::size_t i = 0; i < size; ++i)
            if (parent[i] < -1 || parent[i] >= static_cast<int>(i)) return false;
        return true;
    }();
    static_assert(size > 0, "ctga::chains::tree: a tree needs at least one body");
    static_assert(parents_precede,
                  "ctga::chains::tree: every body's parent must be an earlier body (index < its own) or -1, the "
                  "world; list the bodies so that each comes after its parent");

    template <std::size_t I>
    using joint_at = typename std::tuple_element_t<I, std::tuple<Links...>>::joint_type;

    static constexpr std::array<std::size_t, size> nq_of{Links::joint_type::nq...};
    static constexpr std::array<std::size_t, size> nv_of{Links::joint_type::nv...};
    // where body i's configuration and velocity numbers start in q and in q̇
    static constexpr auto q_offset = [] {
        std::array<std::size_t, size + 1> o{};
        for (std::size_t i = 0; i < size; ++i) o[i + 1] = o[i] + nq_of[i];
        return o;
    }();
    static constexpr auto v_offset = [] {
        std::array<std::size_t, size + 1> o{};
        for (std::size_t i = 0; i < size; ++i) o[i + 1] = o[i] + nv_of[i];
        return o;
    }();
    static constexpr std::size_t nq = q_offset[size];
    static constexpr std::size_t nv = v_offset[size];
    // the body whose joint velocity number k is
    static constexpr auto body_of_dof = [] {
        std::array<std::size_t, nv> b{};
        for (std::size_t i = 0; i < size; ++i)
            for (std::size_t k = v_offset[i]; k < v_offset[i + 1]; ++k) b[k] = i;
        return b;
    }();

    // true when body j is body i or one of its ancestors
    static constexpr bool supports(std::size_t j, std::size_t i) {
        for (int k = static_cast<int>(i); k >= 0; k = parent[static_cast<std::size_t>(k)])
            if (k == static_cast<int>(j)) return true;
        return false;
    }
};

template <class T>
inline constexpr bool is_tree = false;
template <class... L>
inline constexpr bool is_tree<tree<L...>> = true;

// The run-time parameters of one body.
template <joint Joint, class T = double>
struct link_parameters {
    motor_map<T> placement{{{{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}}, {}};  // joint frame in the parent's
    body_inertia<T> inertia{};                                      // N by (m, h, I_o), body frame
    typename Joint::template parameters<T> joint{};                 // e.g. the unit axis of revolute_about
};

namespace tree_detail {
template <class Tree, class T>
struct links_of;
template <class... L, class T>
struct links_of<tree<L...>, T> {
    using type = boost::hana::tuple<link_parameters<typename L::joint_type, T>...>;
};
}  // namespace tree_detail

// A tree's run-time parameters: one link_parameters per body (a heterogeneous tuple: each
// body's joint has its own parameter type) and gravity.
template <class Tree, class T = double>
    requires is_tree<Tree>
struct model {
    using tree_type = Tree;
    using scalar_type = T;
    typename tree_detail::links_of<Tree, T>::type links{};
    vec3<T> gravity{T(0), T(0), T(-9.81)};  // the acceleration of gravity, world coordinates

    template <std::size_t I>
    [[nodiscard]] constexpr auto& link() noexcept { return boost::hana::at_c<I>(links); }
    template <std::size_t I>
    [[nodiscard]] constexpr const auto& link() const noexcept { return boost::hana::at_c<I>(links); }
};

// ---- checked construction ---------------------------------------------------------------------

namespace tree_detail {
// ‖u‖ = 1 to a few roundings.
template <class T>
constexpr bool unit(const vec3<T>& u) noexcept {
    const T n2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    const T d = n2 - T(1);
    return (d < T(0) ? -d : d) <= T(64) * std::numeric_limits<T>::epsilon();
}
}  // namespace tree_detail

// One body's parameters from its placement motor, its checked mass properties, and for the
// joints whose axis is a run-time parameter (revolute_about, prismatic_along: has_run_time_axis)
// their unit axis, which the other joints do not take (their type fixes it):
//   make_link<revolute_z>(placement, mass)
//   make_link<revolute_about>(placement, mass, axis)
// Reported: non_finite (a NaN or an infinity), not_a_motor (a placement that is not a unit motor
// up to rounding, near_unit: it is renormalised, never silently replaced by another motion),
// not_a_unit_axis (‖u‖ ≠ 1 beyond rounding), and the mass properties' own errors.
template <joint Joint, class T, class... Axis>
[[nodiscard]] constexpr checked<link_parameters<Joint, T>> make_link(const motor<T>& placement,
                                                                     const checked<mass_properties<T>>& mass,
                                                                     const Axis&... axis) noexcept {
    static_assert(has_run_time_axis<Joint> || sizeof...(Axis) == 0,
                  "ctga::chains::make_link: this joint's axis is fixed by its type (revolute_x, prismatic_z, ...): "
                  "pass no axis, or use revolute_about / prismatic_along for an axis given at run time");
    static_assert(!has_run_time_axis<Joint> || sizeof...(Axis) == 1,
                  "ctga::chains::make_link: revolute_about and prismatic_along need their unit axis (a vec3)");
    static_assert(((std::is_same_v<Axis, vec3<T>>) && ...), "ctga::chains::make_link: the axis is a vec3 of the model's scalar type");
    if (!all_finite(placement[0], placement[1], placement[2], placement[3], placement[4], placement[5], placement[6], placement[7]))
        return {{}, error_code::non_finite};
    if (!near_unit(placement)) return {{}, error_code::not_a_motor};
    const checked<motor<T>> g = renormalize_checked(placement);  // the rounding residue only
    if (!g) return {{}, g.error};
    if (!mass) return {{}, mass.error};
    link_parameters<Joint, T> out;
    out.placement = map_of(*g);
    out.inertia = body_inertia_of(*mass);
    if constexpr (has_run_time_axis<Joint> && sizeof...(Axis) == 1) {
        const vec3<T>& u = (axis, ...);
        if (!all_finite(u[0], u[1], u[2])) return {{}, error_code::non_finite};
        if (!tree_detail::unit(u)) return {{}, error_code::not_a_unit_axis};
        out.joint.u = u;
    }
    return {out, error_code::none};
}

}  // namespace ctga::chains
