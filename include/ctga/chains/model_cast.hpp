// A tree's model in another scalar type: every parameter converted, U(x), a mimic joint's coupling
// included. A pack type broadcasts the model to all its lanes (chains/batch.hpp: one robot, many
// states); dual numbers carry derivatives (the tests' references).
//
//   const ch::model<Tree, ctga::pack<double, 8>> lanes = ch::model_cast<ctga::pack<double, 8>>(m);
//
// Nothing is checked again: the model was checked when it was made (make_link), and U(x) keeps
// every value.
#pragma once

#include <array>
#include <cstddef>
#include <utility>

#include "ctga/chains/tree.hpp"

namespace ctga::chains {

namespace cast_detail {
template <class U, class T, std::size_t N>
constexpr std::array<U, N> cast_array(const std::array<T, N>& x) noexcept {
    std::array<U, N> out{};
    for (std::size_t k = 0; k < N; ++k) out[k] = U(x[k]);
    return out;
}

template <class U, class T>
constexpr motor_map<U> cast_map(const motor_map<T>& G) noexcept {
    motor_map<U> out;
    for (std::size_t r = 0; r < 3; ++r) out.R[r] = cast_array<U>(G.R[r]);
    out.t = cast_array<U>(G.t);
    return out;
}
}  // namespace cast_detail

template <class U, class Tree, class T>
[[nodiscard]] constexpr model<Tree, U> model_cast(const model<Tree, T>& m) noexcept {
    using cast_detail::cast_array;
    using cast_detail::cast_map;
    model<Tree, U> out;
    out.gravity = cast_array<U>(m.gravity);
    for (std::size_t k = 0; k < Tree::frame_count; ++k) out.frames[k] = cast_map<U>(m.frames[k]);
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ([&] {
            using J = typename Tree::template joint_at<I>;
            const auto& a = m.template link<I>();
            auto& b = out.template link<I>();
            b.placement = cast_map<U>(a.placement);
            b.inertia = parameters_cast<U>(a.inertia);
            if constexpr (has_armature<J>) b.armature = U(a.armature);
            if constexpr (is_mimic<J>) {
                b.joint.multiplier = U(a.joint.multiplier);
                b.joint.offset = U(a.joint.offset);
                if constexpr (has_run_time_axis<J>) b.joint.joint.u = cast_array<U>(a.joint.joint.u);
            } else if constexpr (has_run_time_axis<J>) {
                b.joint.u = cast_array<U>(a.joint.u);
            }
        }(), ...);
    }(std::make_index_sequence<Tree::size>{});
    return out;
}

}  // namespace ctga::chains
