// The collision geometry of a tree: shapes fixed to its bodies (a foot's sphere, a shin's capsule,
// a hand's box), each at a placement in its body's frame, as a URDF's <collision> elements are;
// and the static world they touch (a floor, a mesh, a height field), each shape at its pose.
//
//   constrained::robot_geometry<robot::tree, shape_kinds, double, 8> geo;
//   geo.attach(m, chains::frame<"FL_foot">, collision::sphere<double>{0.02});   // on a named frame
//   geo.exclude(2, 5);                                   // two bodies never tested against each other
//
// Pairs of a robot's own shapes are tested when their bodies differ, are not parent and child
// (a joint's two sides overlap by design) and are not excluded by the user; a body is never tested
// against itself. The shape kinds are a variant (collision/shape_set.hpp): the pair routines
// compiled are those of the kinds named, chosen at compile time.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <type_traits>
#include <variant>

#include "ctga/chains/frames.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/collision/shape_set.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga::constrained {

// A shape of the static world at its pose (the ground: a half-space at the identity).
template <class Shape, class T = double>
struct static_shape {
    Shape shape;
    motor_map<T> pose = chains::tree_detail::identity_map<T>();
};

template <class Tree, class Shape, class T, std::size_t Capacity>
class robot_geometry {
   public:
    struct attached {
        Shape shape;
        int body;
        motor_map<T> at;  // in the body's frame
    };

    [[nodiscard]] constexpr std::span<const attached> shapes() const noexcept { return {shapes_.data(), count_}; }

    // A shape on body b at placement `at` in its frame. Refused: capacity_exceeded, bad_index (b
    // not a body of the tree), non_finite (the placement).
    constexpr error_code attach(int body, const Shape& s, const motor_map<T>& at = chains::tree_detail::identity_map<T>()) noexcept {
        if (count_ == Capacity) return error_code::capacity_exceeded;
        if (body < 0 || body >= static_cast<int>(Tree::size)) return error_code::bad_index;
        for (const auto& row : at.R)
            for (const T& x : row)
                if (!is_finite(x)) return error_code::non_finite;
        if (!is_finite(at.t[0]) || !is_finite(at.t[1]) || !is_finite(at.t[2])) return error_code::non_finite;
        shapes_[count_++] = {s, body, at};
        return error_code::none;
    }
    // A shape at a named frame (placed there, then by `at` in the frame's axes); a misspelt frame does not compile.
    template <class F>
    constexpr error_code attach(const chains::model<Tree, T>& m, F f, const Shape& s,
                                const motor_map<T>& at = chains::tree_detail::identity_map<T>()) noexcept {
        using on = chains::frame_detail::frame_on<Tree, F>;
        static_assert(on::body >= 0, "ctga::constrained::robot_geometry::attach: the frame is on the world (a static shape goes to the world's list)");
        return attach(on::body, s, compose(chains::frame_detail::placement(m, f), at));
    }

    // The same shapes and exclusions with room for more (Capacity ≥ the other's count) or more
    // shape kinds (each of the other's kinds one of Shape's alternatives): a URDF's make_geometry()
    // grown by the shapes a user adds. Refused: capacity_exceeded.
    template <class Other, std::size_t N>
    [[nodiscard]] static constexpr checked<robot_geometry> from(const robot_geometry<Tree, Other, T, N>& other) noexcept {
        robot_geometry out;
        if (other.shapes().size() > Capacity) return {out, error_code::capacity_exceeded};
        for (const auto& s : other.shapes()) {
            if constexpr (std::is_same_v<Other, Shape>) out.shapes_[out.count_++] = {s.shape, s.body, s.at};
            else out.shapes_[out.count_++] = {std::visit([](const auto& kind) { return Shape(kind); }, s.shape), s.body, s.at};
        }
        out.excluded_ = other.excluded_;
        return {out, error_code::none};
    }

    // Bodies a and b never tested against each other (beyond parent and child, always skipped).
    constexpr error_code exclude(int a, int b) noexcept {
        if (a < 0 || b < 0 || a >= static_cast<int>(Tree::size) || b >= static_cast<int>(Tree::size)) return error_code::bad_index;
        excluded_[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)] = excluded_[static_cast<std::size_t>(b)][static_cast<std::size_t>(a)] = true;
        return error_code::none;
    }
    // Whether shapes on bodies a and b are tested (above).
    [[nodiscard]] constexpr bool collides(int a, int b) const noexcept {
        if (a == b || Tree::parent[static_cast<std::size_t>(a)] == b || Tree::parent[static_cast<std::size_t>(b)] == a) return false;
        return !excluded_[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)];
    }

   private:
    template <class, class, class, std::size_t>
    friend class robot_geometry;
    std::array<attached, Capacity> shapes_{};
    std::size_t count_ = 0;
    std::array<std::array<bool, Tree::size>, Tree::size> excluded_{};
};

}  // namespace ctga::constrained
