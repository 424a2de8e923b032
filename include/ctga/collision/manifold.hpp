// A contact manifold: where two shapes touch, or come within a speculative margin, as up to four
// points sharing one normal n (unit, from A to B). Each point has its witnesses on A and on B,
// its separation along n (signed: < 0 overlapping), and an id made of the features that produced
// it (a box's corner, a capsule's end), the same from one step to the next while those features
// stay in contact, so that a solver can start from the impulses it found for that point before
// (warm starting). Four points span a resting face: a box on the ground gives its four lowest
// corners, a capsule lying on it its two ends.
// The constraint a point gives (parts 2 and 3): the normal force along n through the point is a
// line, a co-screw, and its pairing with a body's screw is the point's row of the contact Jacobian.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "ctga/mechanics/linear3.hpp"

namespace ctga::collision {

template <class T = double>
struct contact_point {
    vec3<T> point_a, point_b;  // point_b − point_a = separation · normal
    T separation;
    std::uint32_t id;  // the features of A and B that made the point
};

template <class T = double>
struct manifold {
    vec3<T> normal{};
    std::size_t count = 0;
    std::array<contact_point<T>, 4> points{};

    // Adds a point when there is room (the routines add at most four).
    constexpr void add(const contact_point<T>& p) noexcept {
        if (count < points.size()) points[count++] = p;
    }
};

// The same manifold seen from B: the normal reversed, each point's witnesses swapped.
template <class T>
[[nodiscard]] constexpr manifold<T> reversed(const manifold<T>& m) noexcept {
    manifold<T> out{{-m.normal[0], -m.normal[1], -m.normal[2]}, m.count, {}};
    for (std::size_t i = 0; i < m.count; ++i) out.points[i] = {m.points[i].point_b, m.points[i].point_a, m.points[i].separation, m.points[i].id};
    return out;
}

}  // namespace ctga::collision
