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
#include <limits>
#include <span>
#include <type_traits>

#include "ctga/collision/separation.hpp"
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
    std::array<contact_point<T>, 4> points;  // [0, count) in use

    constexpr manifold() noexcept : points{} {}
    // No points yet, along n. The points' storage is left unfilled at run time (a manifold is
    // returned by every contact query: filling its 256 bytes cost a query 9 ns, measured).
    explicit constexpr manifold(const vec3<T>& n) noexcept : normal(n) {
        if (std::is_constant_evaluated()) points = {};
    }

    // Adds a point when there is room (the routines add at most four).
    constexpr void add(const contact_point<T>& p) noexcept {
        if (count < points.size()) points[count++] = p;
    }
};

// Up to four of the candidate points (all of them when four or fewer): the deepest, the farthest
// from it, then the two on either side of their line that span the largest triangles with it
// (Box2D's reduction: the four that keep the most of the contact area); the four are extreme
// points of the candidates, so that reducing a growing set in stages keeps its corners. The
// candidates' indices (four_of), the normal the candidates' (for the sides of the line).
struct four_of {
    std::array<std::uint8_t, 4> index;
    std::size_t count;
};
template <class T>
[[nodiscard]] constexpr four_of best_four(std::span<const contact_point<T>> cand, const vec3<T>& normal) noexcept {
    const std::size_t nc = cand.size();
    if (nc <= 4) return {{0, 1, 2, 3}, nc};
    // the deepest; among points as deep to rounding (a face flat on a face), the one farthest from
    // their centre, so that a resting face keeps its corners
    std::size_t p1 = 0;
    vec3<T> centre{};
    T span = T(0);
    for (std::size_t e = 0; e < nc; ++e) {
        if ((cand[e].separation) < (cand[p1].separation)) p1 = e;
        centre = linear3::add_scaled(centre, T(1) / T(nc), cand[e].point_b);
    }
    for (std::size_t e = 0; e < nc; ++e) {
        const vec3<T> d = linear3::sub(cand[e].point_b, centre);
        span = span > linear3::dot(d, d) ? span : linear3::dot(d, d);
    }
    span = math::sqrt(span);
    const T deepest = cand[p1].separation;
    const T tie = T(64) * std::numeric_limits<T>::epsilon() * (span + (deepest < T(0) ? -deepest : deepest));
    for (std::size_t e = 0; e < nc; ++e) {
        const vec3<T> de = linear3::sub(cand[e].point_b, centre), d1 = linear3::sub(cand[p1].point_b, centre);
        if ((cand[e].separation) <= deepest + tie && linear3::dot(de, de) > linear3::dot(d1, d1)) p1 = e;
    }
    std::size_t p2 = nc;
    T far = T(-1);
    for (std::size_t e = 0; e < nc; ++e) {
        const vec3<T> d = linear3::sub(cand[e].point_b, cand[p1].point_b);
        if (e != p1 && linear3::dot(d, d) > far) far = linear3::dot(d, d), p2 = e;
    }
    const vec3<T> base = linear3::sub(cand[p2].point_b, cand[p1].point_b);
    std::size_t p3 = nc, p4 = nc;
    T most = T(0), least = T(0);  // the signed areas of p3's and p4's triangles
    for (std::size_t e = 0; e < nc; ++e) {
        if (e == p1 || e == p2) continue;
        const T area = linear3::dot(normal, linear3::cross(base, linear3::sub(cand[e].point_b, cand[p1].point_b)));
        if (p3 == nc || area > most) p3 = e, most = area;
        if (p4 == nc || area < least) p4 = e, least = area;
    }
    const auto at = [](std::size_t e) { return static_cast<std::uint8_t>(e); };
    return {{at(p1), at(p2), at(p3), at(p4)}, p4 != p3 ? std::size_t(4) : std::size_t(3)};
}
// The same, added to a manifold (its normal the candidates').
template <class T>
constexpr void add_best_four(manifold<T>& out, std::span<const contact_point<T>> cand) noexcept {
    const four_of f = best_four(cand, out.normal);
    for (std::size_t e = 0; e < f.count; ++e) out.add(cand[f.index[e]]);
}

// The same manifold seen from B: the normal reversed, each point's witnesses swapped.
template <class T>
[[nodiscard]] constexpr manifold<T> reversed(const manifold<T>& m) noexcept {
    manifold<T> out(vec3<T>{-m.normal[0], -m.normal[1], -m.normal[2]});
    for (std::size_t i = 0; i < m.count; ++i) out.add({m.points[i].point_b, m.points[i].point_a, m.points[i].separation, m.points[i].id});
    return out;
}

}  // namespace ctga::collision
