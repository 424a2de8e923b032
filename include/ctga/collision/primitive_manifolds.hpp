// The contact manifold (manifold.hpp) of a box on a half-space, the pair a resting scene meets
// most, in closed form: every other pair's manifold comes from the shapes' support features
// (convex_manifolds.hpp, chosen by narrowphase.hpp: contact_of), which would take a box four
// times as long (103 against 25 ns at random poses, measured). A point is kept when its separation
// is at most the margin (speculative contacts: a solver sees a point before it closes).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "ctga/collision/box.hpp"
#include "ctga/collision/half_space.hpp"
#include "ctga/collision/manifold.hpp"
#include "ctga/collision/separation.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"

namespace ctga::collision {

// A box on a half-space: its corners within the margin, the deepest four (a box resting on a face
// gives that face's corners; tilted onto an edge, the edge's two). Corner id: bit i set for +h_i.
// Corner c is t_B + Σ ±h_i x_i, its height n·(t_B − o) + Σ ±h_i (n·x_i): three projections and
// eight sums, the world points formed for the kept corners only.
template <class T>
[[nodiscard]] constexpr manifold<T> manifold_between(const half_space<T>&, const motor_map<T>& pa, const box<T>& b,
                                                     const motor_map<T>& pb, const T& margin) noexcept {
    const vec3<T> n = axis_of(pa, 2);
    std::array<vec3<T>, 3> e{};  // h_i x_i
    std::array<T, 3> k{};        // h_i (n·x_i)
    for (std::size_t i = 0; i < 3; ++i) {
        e[i] = linear3::scale(b.half[i], axis_of(pb, i));
        k[i] = linear3::dot(n, e[i]);
    }
    const T base = linear3::dot(n, linear3::sub(pb.t, pa.t));
    std::array<T, 8> height{};
    for (std::uint32_t c = 0; c < 8; ++c)
        height[c] = base + ((c & 1u) ? k[0] : -k[0]) + ((c & 2u) ? k[1] : -k[1]) + ((c & 4u) ? k[2] : -k[2]);
    // the four deepest, by selection (each pass takes the deepest left, ties to the lower id)
    manifold<T> m(n);
    std::uint32_t taken = 0;
    for (std::size_t pass = 0; pass < 4; ++pass) {
        std::uint32_t best = 8;
        for (std::uint32_t c = 0; c < 8; ++c)
            if (!((taken >> c) & 1u) && (best == 8 || height[c] < height[best])) best = c;
        if (!(height[best] <= margin)) break;
        taken |= 1u << best;
        vec3<T> x = pb.t;
        for (std::size_t i = 0; i < 3; ++i) x = linear3::add_scaled(x, (best >> i) & 1u ? T(1) : T(-1), e[i]);
        m.add({linear3::add_scaled(x, -height[best], n), x, height[best], best});
    }
    return m;
}

}  // namespace ctga::collision
