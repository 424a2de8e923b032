// Checked calls of the algorithms of a kinematic tree (algorithms.hpp).
//
//   auto qdd = chains::checked_call(chains::aba, m, q, qd, tau);   // checked<joint_vector>
//   if (!qdd) std::puts(ctga::describe(qdd.error));
//
// The algorithms are plain arithmetic: a NaN in q gives a NaN in τ. checked_call runs one
// on inputs it has checked and checks its result, so nothing non-finite passes for an answer:
//   non_finite    a NaN or infinity in the model (a link's placement, inertia, axis or coupling,
//                 a frame's placement, gravity),
//                 in q, q̇, q̈, τ, the wrenches, or in the result
//   not_a_unit_base  a floating joint's eight numbers that are not a unit motor up to rounding (a
//                 position and quaternion [x y z qx qy qz qw] pasted in: convert them with
//                 floating_base_configuration, floating_base.hpp)
//   negative_armature  a joint's armature (rotor inertia) below zero
// (make_link checked each link's physics when the model was built; a model edited afterwards is
// checked here for non-finite numbers.) With packs as the scalar (a model_cast model, L robots)
// every lane is checked on its own: the error is a lane_errors<L>.
//
//   auto tau = chains::checked_call(chains::rnea, lanes, q, qd, qdd);   // checked<…, lane_errors<8>>
//   if (tau.error[3] != ctga::error_code::none) { /* robot 3's input or result is bad */ }
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include <boost/hana/for_each.hpp>

#include "ctga/algebra/multivector.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"
#include "ctga/support/pack.hpp"

namespace ctga::chains {

namespace algorithm_detail {
// Whether numbers of type N are finite: a bool, or a pack's lane mask (support/pack.hpp).
template <class N>
using finite_mask = decltype(std::declval<const N&>() == std::declval<const N&>());
template <class N>
[[nodiscard]] constexpr finite_mask<N> every() noexcept {  // true (in every lane)
    const N zero(0);
    return zero == zero;
}

// Every number of x (a model, a motor map, a kinematics, nested arrays, multivectors) finite; x's
// numbers are of type N.
template <class N, class X>
[[nodiscard]] constexpr finite_mask<N> finite_all(const X& x) noexcept {
    if constexpr (std::is_same_v<X, N>) {
        if constexpr (lane_wise<N>) return finite_lanes(x);
        else return is_finite(x);
    } else if constexpr (requires { x.R; x.t; }) {
        return finite_all<N>(x.R) && finite_all<N>(x.t);
    } else if constexpr (requires { x.X; x.pose; x.v; x.a; }) {
        return finite_all<N>(x.X) && finite_all<N>(x.pose) && finite_all<N>(x.v) && finite_all<N>(x.a);
    } else if constexpr (requires { x.links; x.gravity; }) {  // a model: every link's numbers, frames, gravity
        finite_mask<N> ok = finite_all<N>(x.gravity) && finite_all<N>(x.frames);
        boost::hana::for_each(x.links, [&](const auto& l) {
            ok = ok && finite_all<N>(l.placement) && finite_all<N>(l.inertia) && finite_all<N>(l.joint) &&
                 finite_all<N>(l.armature);
        });
        return ok;
    } else if constexpr (requires { x.parameters(); }) {  // body_inertia: its ten parameters
        return std::apply([](const auto&... p) { return (every<N>() && ... && finite_all<N>(p)); }, x.parameters());
    } else if constexpr (requires { x.u; }) {  // a joint's run-time axis
        return finite_all<N>(x.u);
    } else if constexpr (requires { x.multiplier; x.offset; x.joint; }) {  // a mimic joint's coupling
        return finite_all<N>(x.multiplier) && finite_all<N>(x.offset) && finite_all<N>(x.joint);
    } else if constexpr (std::is_empty_v<X>) {  // a joint without parameters
        return every<N>();
    } else if constexpr (multivector_type<X>) {
        finite_mask<N> ok = every<N>();
        for (std::size_t i = 0; i < X::size(); ++i) ok = ok && finite_all<N>(x[i]);
        return ok;
    } else {
        finite_mask<N> ok = every<N>();
        for (const auto& e : x) ok = ok && finite_all<N>(e);
        return ok;
    }
}

// The first failure is the one reported: e where e failed, else f (a scalar's error_code; each
// lane's for packs); first_failure(e, ok, code): e, else code where ok fails.
[[nodiscard]] constexpr error_code first_of(error_code e, error_code f) noexcept { return e != error_code::none ? e : f; }
template <std::size_t L>
[[nodiscard]] constexpr lane_errors<L> first_of(lane_errors<L> e, const lane_errors<L>& f) noexcept {
    for (std::size_t l = 0; l < L; ++l) e[l] = first_of(e[l], f[l]);
    return e;
}
[[nodiscard]] constexpr error_code first_failure(error_code e, bool ok, error_code code) noexcept {
    return first_of(e, ok ? error_code::none : code);
}
template <class T, std::size_t L>
[[nodiscard]] constexpr lane_errors<L> first_failure(lane_errors<L> e, const lanes<T, L>& ok, error_code code) noexcept {
    for (std::size_t l = 0; l < L; ++l) e[l] = first_failure(e[l], ok[l], code);
    return e;
}

// Whether a floating joint's eight numbers g are a unit motor up to rounding (motor.hpp's
// near_unit, lane by lane for packs). map_of would read any motor with a rotor part as the rigid
// motion it encodes, so a pose written in another layout (Pinocchio's and ROS's position and
// quaternion [x y z qx qy qz qw] in the eight numbers) would pass for some other pose.
template <class T>
[[nodiscard]] constexpr finite_mask<T> unit_motor(const T* g) noexcept {
    if constexpr (lane_wise<T>) {
        using S = typename T::value_type;
        const T unit = T::generate([&](std::size_t l) {
            return near_unit(motor<S>{g[0][l], g[1][l], g[2][l], g[3][l], g[4][l], g[5][l], g[6][l], g[7][l]}) ? S(1) : S(0);
        });
        return unit == T(S(1));
    } else {
        return near_unit(motor<T>{g[0], g[1], g[2], g[3], g[4], g[5], g[6], g[7]});
    }
}

// Every joint's armature ≥ 0 (negative_armature).
template <class Tree, class T>
[[nodiscard]] constexpr finite_mask<T> armature_not_negative(const model<Tree, T>& m) noexcept {
    finite_mask<T> ok = every<T>();
    boost::hana::for_each(m.links, [&](const auto& l) {
        if constexpr (!std::is_empty_v<std::remove_cvref_t<decltype(l.armature)>>) ok = ok && !(l.armature < T(0));
    });
    return ok;
}

// q finite (non_finite) and every floating joint's eight numbers a unit motor (not_a_unit_base).
template <class Tree, class T>
[[nodiscard]] constexpr error_of_t<T> check_configuration(const std::array<T, Tree::nq>& q) noexcept {
    finite_mask<T> unit = every<T>();
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ([&] {
            if constexpr (Tree::nq_of[I] == 8) unit = unit && unit_motor(q.data() + Tree::q_offset[I]);
        }(), ...);
    }(std::make_index_sequence<Tree::size>{});
    const error_of_t<T> e = first_failure(error_of_t<T>{}, finite_all<T>(q), error_code::non_finite);
    return first_failure(e, unit, error_code::not_a_unit_base);
}
}  // namespace algorithm_detail

// The algorithm's result and why it is not acceptable, if it is not (see the top of the file).
// With packs (ctga::pack as T) each lane is checked on its own: the error is a lane_errors, the
// algorithm runs on every lane, and a failed lane's numbers are meaningless, the others' valid.
// (q is deduced as it is given, so that an algorithm that does not take it says why: arguments.hpp.)
template <class Algorithm, class Tree, class T, class Q, class... Args>
[[nodiscard]] constexpr auto checked_call(const Algorithm& algorithm, const model<Tree, T>& m, const Q& q,
                                          const Args&... args) noexcept
    -> checked<decltype(algorithm(m, q, args...)), error_of_t<T>> {
    using namespace algorithm_detail;
    using result = decltype(algorithm(m, q, args...));
    error_of_t<T> e = first_failure(error_of_t<T>{}, finite_all<T>(m), error_code::non_finite);
    e = first_failure(e, armature_not_negative(m), error_code::negative_armature);
    e = first_of(e, check_configuration<Tree>(q));
    e = first_failure(e, (every<T>() && ... && finite_all<T>(args)), error_code::non_finite);
    if constexpr (!lane_wise<T>) {
        if (e != error_code::none) return {result{}, e};  // (the algorithm is not run on bad input)
    }
    const result r = algorithm(m, q, args...);
    e = first_failure(e, finite_all<T>(r), error_code::non_finite);
    if constexpr (!lane_wise<T>) {
        if (e != error_code::none) return {result{}, e};
    }
    return {r, e};
}

}  // namespace ctga::chains
