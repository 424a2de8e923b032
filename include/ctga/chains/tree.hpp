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
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

#include <boost/hana/at.hpp>
#include <boost/hana/tuple.hpp>

#include "ctga/algebra/fixed_string.hpp"
#include "ctga/chains/arguments.hpp"
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

// A named frame fixed to a body (−1: to the world): a link merged into its body by a fixed
// joint (a tool flange, a foot, a sensor), or a body's own frame. Its placement in the body's
// frame is a run-time parameter (model::frames).
template <fixed_string Name, int Body>
struct fixed_frame {
    static constexpr fixed_string name = Name;
    static constexpr int body = Body;
};

namespace tree_detail {
template <class E>
struct entry {
    static constexpr bool is_link = false, is_frame = false;
};
template <int P, class J>
struct entry<link<P, J>> {
    static constexpr bool is_link = true, is_frame = false;
    static constexpr int parent = P;
    static constexpr std::size_t nq = J::nq, nv = J::nv;
    static constexpr int master = [] {
        if constexpr (is_mimic<J>) return static_cast<int>(J::master);
        else return -1;
    }();
};
template <fixed_string N, int B>
struct entry<fixed_frame<N, B>> {
    static constexpr bool is_link = false, is_frame = true;
    static constexpr std::string_view name = fixed_frame<N, B>::name.view();
    static constexpr int body = B;
};

// The first N of an array of all the tree's entries (links come first).
template <std::size_t N, class A>
constexpr auto first(const A& all) {
    std::array<std::remove_cvref_t<decltype(all[0])>, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = all[i];
    return out;
}
}  // namespace tree_detail

// A kinematic tree: its bodies (link entries, in order) and then its named frames (fixed_frame
// entries). Bodies are numbered by the links only.
template <class... Entries>
struct tree {
    static_assert(((tree_detail::entry<Entries>::is_link || tree_detail::entry<Entries>::is_frame) && ...),
                  "ctga::chains::tree: every entry is a link<parent, joint> or a fixed_frame<\"name\", body>");
    static constexpr std::size_t size = (std::size_t{tree_detail::entry<Entries>::is_link} + ... + 0);
    static constexpr std::size_t frame_count = sizeof...(Entries) - size;
    static_assert(size > 0, "ctga::chains::tree: a tree needs at least one body");
    static_assert([] {
        constexpr bool is_link[] = {tree_detail::entry<Entries>::is_link...};
        for (std::size_t i = 0; i < sizeof...(Entries); ++i)
            if (is_link[i] != (i < size)) return false;
        return true;
    }(), "ctga::chains::tree: list the bodies (link entries) first, then the frames (fixed_frame entries)");

    static constexpr std::array<int, size> parent = tree_detail::first<size>(std::array<int, sizeof...(Entries)>{
        [] { if constexpr (tree_detail::entry<Entries>::is_link) return tree_detail::entry<Entries>::parent; else return 0; }()...});
    static constexpr bool parents_precede = [] {
        for (std::size_t i = 0; i < size; ++i)
            if (parent[i] < -1 || parent[i] >= static_cast<int>(i)) return false;
        return true;
    }();
    static_assert(parents_precede,
                  "ctga::chains::tree: every body's parent must be an earlier body (index < its own) or -1, the "
                  "world; list the bodies so that each comes after its parent");

    template <std::size_t I>
    using joint_at = typename std::tuple_element_t<I, std::tuple<Entries...>>::joint_type;

    static constexpr std::array<std::size_t, size> nq_of = tree_detail::first<size>(std::array<std::size_t, sizeof...(Entries)>{
        [] { if constexpr (tree_detail::entry<Entries>::is_link) return tree_detail::entry<Entries>::nq; else return std::size_t{0}; }()...});
    static constexpr std::array<std::size_t, size> nv_of = tree_detail::first<size>(std::array<std::size_t, sizeof...(Entries)>{
        [] { if constexpr (tree_detail::entry<Entries>::is_link) return tree_detail::entry<Entries>::nv; else return std::size_t{0}; }()...});
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

    // Mimic joints (joints.hpp): the body whose coordinates body i's joint reads, its own or its
    // master's; a master is an independent joint of one degree of freedom.
    static constexpr std::array<int, size> master = tree_detail::first<size>(std::array<int, sizeof...(Entries)>{
        [] { if constexpr (tree_detail::entry<Entries>::is_link) return tree_detail::entry<Entries>::master; else return -1; }()...});
    static constexpr bool has_mimic = [] {
        for (int m : master)
            if (m >= 0) return true;
        return false;
    }();
    static_assert([] {
        for (std::size_t i = 0; i < size; ++i)
            if (master[i] >= 0) {
                const auto j = static_cast<std::size_t>(master[i]);
                if (j >= size || j == i || master[j] >= 0 || nq_of[j] != 1 || nv_of[j] != 1) return false;
            }
        return true;
    }(), "ctga::chains::tree: a mimic joint's master must be another body of the tree whose joint is independent "
         "(not itself a mimic) and has one degree of freedom");
    static constexpr std::array<std::size_t, size> reads_from = [] {
        std::array<std::size_t, size> r{};
        for (std::size_t i = 0; i < size; ++i) r[i] = master[i] >= 0 ? static_cast<std::size_t>(master[i]) : i;
        return r;
    }();

    // The named frames: name, and the body each is fixed to (−1: the world).
    static constexpr std::array<std::string_view, frame_count> frame_names = [] {
        constexpr std::string_view all[] = {[] { if constexpr (tree_detail::entry<Entries>::is_frame) return tree_detail::entry<Entries>::name; else return std::string_view{}; }()..., std::string_view{}};
        std::array<std::string_view, frame_count> out{};
        for (std::size_t k = 0; k < frame_count; ++k) out[k] = all[size + k];
        return out;
    }();
    static constexpr std::array<int, frame_count> frame_body = [] {
        constexpr int all[] = {[] { if constexpr (tree_detail::entry<Entries>::is_frame) return tree_detail::entry<Entries>::body; else return 0; }()..., 0};
        std::array<int, frame_count> out{};
        for (std::size_t k = 0; k < frame_count; ++k) out[k] = all[size + k];
        return out;
    }();
    static_assert([] {
        for (int b : frame_body)
            if (b < -1 || b >= static_cast<int>(size)) return false;
        return true;
    }(), "ctga::chains::tree: a fixed_frame's body must be a body of the tree or -1, the world");
    static_assert([] {
        for (std::size_t a = 0; a < frame_count; ++a)
            for (std::size_t b = a + 1; b < frame_count; ++b)
                if (frame_names[a] == frame_names[b]) return false;
        return true;
    }(), "ctga::chains::tree: two frames have the same name");

    // Frame k of that name, or frame_count when there is none.
    static constexpr std::size_t frame_index_of(std::string_view name) noexcept {
        for (std::size_t k = 0; k < frame_count; ++k)
            if (frame_names[k] == name) return k;
        return frame_count;
    }
    // For tools: the frame of a name read at run time; unknown_frame when the tree has none.
    [[nodiscard]] static constexpr checked<std::size_t> find_frame(std::string_view name) noexcept {
        const std::size_t k = frame_index_of(name);
        if (k == frame_count) return {0, error_code::unknown_frame};
        return {k, error_code::none};
    }

    // true when body j is body i or one of its ancestors
    static constexpr bool supports(std::size_t j, std::size_t i) {
        for (int k = static_cast<int>(i); k >= 0; k = parent[static_cast<std::size_t>(k)])
            if (k == static_cast<int>(j)) return true;
        return false;
    }
};

template <class T>
inline constexpr bool is_tree = false;
template <class... E>
inline constexpr bool is_tree<tree<E...>> = true;

// A frame named at compile time: frame_pose(m, k, chains::frame<"tool0">). A name the tree does
// not have is a compile error naming it: the_tree_has_no_frame_named<'t', 'o', 'o', 'l', '9'>
// (arguments.hpp).
template <fixed_string Name>
struct frame_name {
    static constexpr fixed_string name = Name;
};
template <fixed_string Name>
inline constexpr frame_name<Name> frame{};

namespace tree_detail {
// A type whose size is asked where frame Name is looked up (static_assert(sizeof(…))): a class
// whose instantiation reports the name when the tree has no such frame. Apart from computing the
// index, so that Clang reports the name once, not again for every constant computed from it.
template <class Tree, fixed_string Name>
using frame_named = std::conditional_t<(Tree::frame_index_of(Name.view()) < Tree::frame_count), std::true_type,
                                       spelt<the_tree_has_no_frame_named, Name>>;
}  // namespace tree_detail

template <class Tree, fixed_string Name>
consteval std::size_t frame_index() {
    static_assert(sizeof(tree_detail::frame_named<Tree, Name>));
    return Tree::frame_index_of(Name.view());
}

namespace tree_detail {
template <class T>
constexpr motor_map<T> identity_map() noexcept {
    return {{{{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}}, {}};
}
}  // namespace tree_detail

// A joint's armature (with_armature<J>, joints.hpp): the reflected rotor inertia a, kg m² for a
// revolute joint, kg for a prismatic one. Other joints have none: an empty member, which a number
// cannot be assigned to.
struct no_armature {
    template <class T>
    no_armature& operator=(const T&) noexcept {
        static_assert(sizeof(T) == 0,
                      "ctga::chains: this joint has no armature: declare it with_armature<J> (turned<P, with_armature<J>>) "
                      "in the tree type");
        return *this;
    }
};
template <joint Joint, class T>
using armature_of = std::conditional_t<has_armature<Joint>, T, no_armature>;

// The run-time parameters of one body.
template <joint Joint, class T = double>
struct link_parameters {
    motor_map<T> placement = tree_detail::identity_map<T>();  // joint frame in the parent's
    body_inertia<T> inertia{};                                      // N by (m, h, I_o), body frame
    typename Joint::template parameters<T> joint{};                 // e.g. the unit axis of revolute_about
    [[no_unique_address]] armature_of<Joint, T> armature{};         // with_armature<J>'s rotor inertia
};

namespace tree_detail {
template <class Tree, class T, std::size_t... I>
auto links_tuple(std::index_sequence<I...>) -> boost::hana::tuple<link_parameters<typename Tree::template joint_at<I>, T>...>;
template <class Tree, class T>
struct links_of {
    using type = decltype(links_tuple<Tree, T>(std::make_index_sequence<Tree::size>{}));
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
    // frame k's placement in its body's frame (the world's for body −1); identity until set
    std::array<motor_map<T>, Tree::frame_count> frames = [] {
        std::array<motor_map<T>, Tree::frame_count> f;
        for (auto& x : f) x = tree_detail::identity_map<T>();
        return f;
    }();

    template <std::size_t I>
    [[nodiscard]] constexpr auto& link() noexcept { return boost::hana::at_c<I>(links); }
    template <std::size_t I>
    [[nodiscard]] constexpr const auto& link() const noexcept { return boost::hana::at_c<I>(links); }
};

// f(k, a) for every joint with an armature a (with_armature), k its velocity number, in body order.
template <class Tree, class T, class F>
constexpr void each_armature(const model<Tree, T>& m, F&& f) noexcept {
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ([&] {
            if constexpr (has_armature<typename Tree::template joint_at<I>>) f(Tree::v_offset[I], m.template link<I>().armature);
        }(), ...);
    }(std::make_index_sequence<Tree::size>{});
}
// The armatures by velocity number (0 where a joint has none: a floating joint's six).
template <class Tree, class T>
[[nodiscard]] constexpr std::array<T, Tree::nv> armature_by_dof(const model<Tree, T>& m) noexcept {
    std::array<T, Tree::nv> a{};
    each_armature(m, [&](std::size_t k, const T& x) { a[k] = x; });
    return a;
}

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

namespace tree_detail {
// A placement motor as the map the algorithms read: finite, a unit motor up to rounding (near_unit:
// it is renormalised, never silently replaced by another motion).
template <class T>
constexpr checked<motor_map<T>> placement_map(const motor<T>& g) noexcept {
    if (!all_finite(g[0], g[1], g[2], g[3], g[4], g[5], g[6], g[7])) return {{}, error_code::non_finite};
    if (!near_unit(g)) return {{}, error_code::not_a_motor};
    const checked<motor<T>> r = renormalize_checked(g);  // the rounding residue only
    if (!r) return {{}, r.error};
    return {map_of(*r), error_code::none};
}
// R = P to a few roundings (a turned or aligned joint's placement, joints.hpp).
template <class T>
constexpr bool is_the_turn(const mat3<T>& R, const turn& P) noexcept {
    const mat3<T> expected = turn_matrix<T>(P);
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            const T d = R[i][j] - expected[i][j];
            if (!((d < T(0) ? -d : d) <= T(64) * std::numeric_limits<T>::epsilon())) return false;
        }
    return true;
}
}  // namespace tree_detail

// One body's parameters from its placement motor and its checked mass properties; then, for a
// mimic joint, its coupling (q = multiplier · q_master + offset), and for the joints whose axis is
// a run-time parameter (revolute_about, prismatic_along, or a mimic of one: has_run_time_axis)
// their unit axis, which the other joints do not take (their type fixes it):
//   make_link<revolute_z>(placement, mass)
//   make_link<revolute_about>(placement, mass, axis)
//   make_link<mimic<prismatic_y, 7>>(placement, mass, coupling<T>{-1.0, 0.01})
// Reported: non_finite (a NaN or an infinity), not_a_motor (a placement that is not a unit motor
// up to rounding), not_aligned (a turned or aligned joint's placement whose rotation is not its type's turn), not_a_unit_axis
// (‖u‖ ≠ 1 beyond rounding), and the mass properties' own errors.
template <joint Joint, class T, class... Extra>
[[nodiscard]] constexpr checked<link_parameters<Joint, T>> make_link(const motor<T>& placement,
                                                                     const checked<mass_properties<T>>& mass,
                                                                     const Extra&... extra) noexcept {
    constexpr std::size_t n_coupling = is_mimic<Joint> ? 1 : 0, n_axis = has_run_time_axis<Joint> ? 1 : 0;
    static_assert(has_run_time_axis<Joint> || sizeof...(Extra) == n_coupling,
                  "ctga::chains::make_link: this joint's axis is fixed by its type (revolute_x, prismatic_z, ...): "
                  "pass no axis, or use revolute_about / prismatic_along for an axis given at run time");
    static_assert(!has_run_time_axis<Joint> || sizeof...(Extra) == n_coupling + n_axis,
                  "ctga::chains::make_link: revolute_about and prismatic_along need their unit axis (a vec3)");
    const auto args = std::tie(extra...);
    if constexpr (n_coupling == 1)
        static_assert(std::is_same_v<std::tuple_element_t<0, std::tuple<Extra...>>, coupling<T>>,
                      "ctga::chains::make_link: a mimic joint takes its coupling<T>{multiplier, offset} after the mass");
    if constexpr (n_axis == 1)
        static_assert(std::is_same_v<std::tuple_element_t<n_coupling, std::tuple<Extra..., void>>, vec3<T>>,
                      "ctga::chains::make_link: the axis is a vec3 of the model's scalar type");
    const checked<motor_map<T>> X = tree_detail::placement_map(placement);
    if (!X) return {{}, X.error};
    if constexpr (is_turned<Joint>)
        if (!tree_detail::is_the_turn(X->R, placement_turn<Joint>)) return {{}, error_code::not_aligned};
    if (!mass) return {{}, mass.error};
    link_parameters<Joint, T> out;
    out.placement = *X;
    out.inertia = body_inertia_of(*mass);
    auto& own = [&]() -> auto& {
        if constexpr (is_mimic<Joint>) return out.joint.joint;
        else return out.joint;
    }();
    if constexpr (n_coupling == 1) {
        const coupling<T>& c = std::get<0>(args);
        if (!all_finite(c.multiplier, c.offset)) return {{}, error_code::non_finite};
        out.joint.multiplier = c.multiplier;
        out.joint.offset = c.offset;
    }
    if constexpr (n_axis == 1) {
        const vec3<T>& u = std::get<n_coupling>(args);
        if (!all_finite(u[0], u[1], u[2])) return {{}, error_code::non_finite};
        if (!tree_detail::unit(u)) return {{}, error_code::not_a_unit_axis};
        own.u = u;
    }
    (void)own;
    (void)args;
    return {out, error_code::none};
}

// A named frame's placement in its body's frame (model::frames), checked as a body's placement.
template <class T>
[[nodiscard]] constexpr checked<motor_map<T>> make_frame(const motor<T>& placement) noexcept {
    return tree_detail::placement_map(placement);
}

// Whether a joint of one degree of freedom turns its body (its S a rotation: revolute about a
// coordinate axis or a run-time axis, or a mimic of one), so that a rotational inertia alone
// resists it.
template <class J>
inline constexpr bool turns = [] {
    using own = typename joint_detail::axis_owner<J>::type;  // a mimic's followed joint
    if constexpr (requires { own::component; }) return own::component < 3;
    else return std::is_base_of_v<revolute_about, own>;
}();

// The first body whose joint moves (moves<J>) but meets no inertia, or −1: no armature, no mass in
// its body or below it, and (for a joint that turns) no rotational inertia there either (a link of
// mass 0 may keep an inertia tensor, as URDF files write it). Such a joint's row of the mass matrix
// is zero (H singular) and ABA divides by D = 0.
template <class Tree, class T>
[[nodiscard]] constexpr int massless_subtree(const model<Tree, T>& m) noexcept {
    std::array<T, Tree::size> mass{}, turning{}, armature{};  // carried mass, rotational inertia (trace of I_o)
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ([&] {
            const auto& l = m.template link<I>();
            mass[I] = l.inertia.mass();
            turning[I] = l.inertia.ixx[0] + l.inertia.iyy[0] + l.inertia.izz[0];
            if constexpr (!std::is_empty_v<decltype(l.armature)>) armature[I] = l.armature;
        }(), ...);
    }(std::make_index_sequence<Tree::size>{});
    for (std::size_t i = Tree::size; i-- > 0;)
        if (Tree::parent[i] >= 0) {
            mass[static_cast<std::size_t>(Tree::parent[i])] += mass[i];
            turning[static_cast<std::size_t>(Tree::parent[i])] += turning[i];
        }
    constexpr std::array<bool, Tree::size> moving = []<std::size_t... I>(std::index_sequence<I...>) {
        return std::array<bool, Tree::size>{moves<typename Tree::template joint_at<I>>...};
    }(std::make_index_sequence<Tree::size>{});
    constexpr std::array<bool, Tree::size> turning_joint = []<std::size_t... I>(std::index_sequence<I...>) {
        return std::array<bool, Tree::size>{turns<typename Tree::template joint_at<I>>...};
    }(std::make_index_sequence<Tree::size>{});
    for (std::size_t i = 0; i < Tree::size; ++i)
        if (moving[i] && !(mass[i] > T(0)) && !(armature[i] > T(0)) && !(turning_joint[i] && turning[i] > T(0)))
            return static_cast<int>(i);
    return -1;
}

}  // namespace ctga::chains
