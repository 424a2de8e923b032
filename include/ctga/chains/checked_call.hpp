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
//   not_a_motor   a floating joint's configuration with a zero rotor part (no rigid motion)
// (make_link checked each link's physics when the model was built; a model edited afterwards is
// checked here for non-finite numbers.)
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>

#include <boost/hana/for_each.hpp>

#include "ctga/algebra/multivector.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga::chains {

namespace algorithm_detail {
template <class T>
constexpr bool finite_all(const T& x) noexcept {
    if constexpr (std::is_arithmetic_v<T>) return is_finite(x);
    else if constexpr (requires { x.R; x.t; }) return finite_all(x.R) && finite_all(x.t);
    else if constexpr (requires { x.X; x.pose; x.v; x.a; }) return finite_all(x.X) && finite_all(x.pose) && finite_all(x.v) && finite_all(x.a);
    else if constexpr (requires { x.links; x.gravity; }) {  // a model: every link's numbers, frames, gravity
        bool ok = finite_all(x.gravity) && finite_all(x.frames);
        boost::hana::for_each(x.links, [&](const auto& l) {
            ok = ok && finite_all(l.placement) && finite_all(l.inertia) && finite_all(l.joint);
        });
        return ok;
    } else if constexpr (requires { x.parameters(); }) {  // body_inertia: its ten parameters
        return std::apply([](const auto&... p) { return (finite_all(p) && ...); }, x.parameters());
    } else if constexpr (requires { x.u; }) {  // a joint's run-time axis
        return finite_all(x.u);
    } else if constexpr (requires { x.multiplier; x.offset; x.joint; }) {  // a mimic joint's coupling
        return is_finite(x.multiplier) && is_finite(x.offset) && finite_all(x.joint);
    } else if constexpr (std::is_empty_v<T>) {  // a joint without parameters
        return true;
    } else if constexpr (multivector_type<T>) {
        for (std::size_t i = 0; i < T::size(); ++i)
            if (!is_finite(x[i])) return false;
        return true;
    } else {
        for (const auto& e : x)
            if (!finite_all(e)) return false;
        return true;
    }
}
// A floating joint's eight numbers are a motor when its rotor part is not zero (map_of reads any
// such motor as the rigid motion it encodes).
template <class Tree, class T>
constexpr error_code check_configuration(const std::array<T, Tree::nq>& q) noexcept {
    if (!finite_all(q)) return error_code::non_finite;
    for (std::size_t i = 0; i < Tree::size; ++i)
        if (Tree::nq_of[i] == 8) {
            const T* g = q.data() + Tree::q_offset[i];
            if (!(g[0] * g[0] + g[1] * g[1] + g[2] * g[2] + g[3] * g[3] > T(0))) return error_code::not_a_motor;
        }
    return error_code::none;
}
}  // namespace algorithm_detail

template <class Algorithm, class Tree, class T, class... Args>
[[nodiscard]] constexpr auto checked_call(const Algorithm& algorithm, const model<Tree, T>& m, const configuration<Tree, T>& q,
                                          const Args&... args) noexcept -> checked<decltype(algorithm(m, q, args...))> {
    using result = decltype(algorithm(m, q, args...));
    if (!algorithm_detail::finite_all(m)) return {result{}, error_code::non_finite};
    if (const error_code e = algorithm_detail::check_configuration<Tree>(q); e != error_code::none) return {result{}, e};
    if (!(algorithm_detail::finite_all(args) && ...)) return {result{}, error_code::non_finite};
    const result r = algorithm(m, q, args...);
    if (!algorithm_detail::finite_all(r)) return {result{}, error_code::non_finite};
    return {r, error_code::none};
}

}  // namespace ctga::chains
