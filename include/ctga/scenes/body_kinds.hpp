// Bodies that declare what they have: the subspace their velocity lives in and the structure of
// their inertia. The equation of motion (§6) is written once,
//
//   ṡ = E ∨ (M ∧ (W − ½(s̄P − Ps̄))),   P = A ∨ (N ∧ s),
//
// and the engine multiplies only the blades the types name. A planar body's screws have the 3
// blades e1e2, e1e, e2e, so every product of its step works on 3 components; a sphere's N is
// d (a1ae1e + a2ae2e + a3ae3e) + m (a2a3e2e3 + a3a1e3e1 + a1a2e1e2) with one scalar d, so its
// Coriolis part ω × dω cancels in the normal form and no code computes it (cost_of shows it).
//
// Subspaces (the velocity's blades, and the motors they generate, closed under the product):
//   full          screw (6 blades)              motor (8)
//   planar        ω_z, v_x, v_y: e1e2 e1e e2e   1 e1e2 e1e e2e     (motion in the e1, e2 plane)
//   rotation      e2e3 e3e1 e1e2                rotor               (about the body origin)
//   translation   e1e e2e e3e                   translator
// Inertia structures (body frame at the centre of mass, principal axes; the scalars each has,
// and their reciprocals for the mobility, computed once when the data is made):
//   sphere        m, d                 N = d·(rotation block) + m·(mass block)
//   axisymmetric  m, d_xy, d_z         about the body's e3 axis
//   diagonal      m, dx, dy, dz        principal axes (§5's diagonal inertia)
//   general       rigid_inertia N (24 blades) and body_mobility M (1/m, c, J): any body frame
// A planar body needs its plane's normal to be a principal axis through the centre of mass
// (sphere, axisymmetric or diagonal): then N keeps the plane's velocities in the plane.
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>

#include "ctga/mechanics/dynamics.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/body_inertia.hpp"
#include "ctga/mechanics/inertia.hpp"
#include "ctga/mechanics/momentum.hpp"
#include "ctga/mechanics/rigid_body.hpp"
#include "ctga/integrators/model.hpp"

namespace ctga {

namespace subspace {
// force_type: a force vector f written on a screw's ω blades (e2e3, e3e1, e1e2 ↔ x, y, z), the
// components a uniform field can have in the subspace; bar(lift(·)) makes it the co-screw (0, f).
struct full {
    template <class T>
    using screw_type = screw<T>;
    template <class T>
    using motor_type = motor<T>;
    template <class T>
    using force_type = cl031::mv<T, "e2e3", "e3e1", "e1e2">;
};
struct planar {
    template <class T>
    using screw_type = cl031::mv<T, "e1e2", "e1e", "e2e">;
    template <class T>
    using motor_type = cl031::mv<T, "1", "e1e2", "e1e", "e2e">;
    template <class T>
    using force_type = cl031::mv<T, "e2e3", "e3e1">;
};
struct rotation {
    template <class T>
    using screw_type = cl031::mv<T, "e2e3", "e3e1", "e1e2">;
    template <class T>
    using motor_type = rotor<T>;
    template <class T>
    using force_type = cl031::mv<T, "e2e3", "e3e1", "e1e2">;
};
struct translation {
    template <class T>
    using screw_type = cl031::mv<T, "e1e", "e2e", "e3e">;
    template <class T>
    using motor_type = translator<T>;
    template <class T>
    using force_type = cl031::mv<T, "e2e3", "e3e1", "e1e2">;
};
}  // namespace subspace

namespace inertia_kind {

// A runtime scalar as an operand of a formula (a grade-0 element): one leaf wherever it appears.
template <class T>
using scalar = cl062::mv<T, "1">;

// the blocks of §5's diagonal inertia and of its inverse (mobility: entry (i, i) is the blade
// α̃_i ε_i, so the rotational entries sit on the mass block's blades and vice versa)
inline constexpr auto rotation_block = cl062::basis<"a1ae1e"> + cl062::basis<"a2ae2e"> + cl062::basis<"a3ae3e">;
inline constexpr auto mass_block = cl062::basis<"a2a3e2e3"> + cl062::basis<"a3a1e3e1"> + cl062::basis<"a1a2e1e2">;

// A kind's scalars (in the order they are given: m first) and their reciprocals, for the mobility.
// Both are fixed together by the constructor, the only way to set them, so a reciprocal can never
// be stale: a body with another mass is a new value.
template <class T, std::size_t N>
class scalars_and_reciprocals {
public:
    template <class... U>
        requires(sizeof...(U) == N && (std::is_convertible_v<U, T> && ...))
    constexpr scalars_and_reciprocals(const U&... v) noexcept
        : value_{static_cast<T>(v)...}, reciprocal_{T(T(1) / static_cast<T>(v))...} {}
    // another scalar type's, every number converted (a pack: broadcast), the reciprocals too
    template <class U>
    constexpr explicit scalars_and_reciprocals(const scalars_and_reciprocals<U, N>& b) noexcept
        : value_{}, reciprocal_{} {
        for (std::size_t i = 0; i < N; ++i) value_[i] = T(b.value_[i]), reciprocal_[i] = T(b.reciprocal_[i]);
    }

    [[nodiscard]] constexpr const T& m() const noexcept { return value_[0]; }
    [[nodiscard]] constexpr scalar<T> value(std::size_t i) const noexcept { return scalar<T>{value_[i]}; }
    [[nodiscard]] constexpr scalar<T> reciprocal(std::size_t i) const noexcept { return scalar<T>{reciprocal_[i]}; }

private:
    template <class, std::size_t>
    friend class scalars_and_reciprocals;
    std::array<T, N> value_;
    std::array<T, N> reciprocal_;
};

struct sphere {
    template <class T>
    using data = scalars_and_reciprocals<T, 2>;  // m, d
    template <class T>
    static constexpr auto arguments(const data<T>& b) noexcept {
        return std::tuple{b.value(1), b.value(0), b.reciprocal(1), b.reciprocal(0)};
    }
    static constexpr auto N = [](auto d, auto m, auto, auto) { return d * rotation_block + m * mass_block; };
    static constexpr auto M = [](auto, auto, auto inv_d, auto inv_m) { return inv_d * mass_block + inv_m * rotation_block; };
};

struct axisymmetric {  // about e3
    template <class T>
    using data = scalars_and_reciprocals<T, 3>;  // m, d_xy, d_z
    template <class T>
    static constexpr auto arguments(const data<T>& b) noexcept {
        return std::tuple{b.value(1), b.value(2), b.value(0), b.reciprocal(1), b.reciprocal(2), b.reciprocal(0)};
    }
    static constexpr auto N = [](auto dxy, auto dz, auto m, auto, auto, auto) {
        return dxy * (cl062::basis<"a1ae1e"> + cl062::basis<"a2ae2e">) + dz * cl062::basis<"a3ae3e"> + m * mass_block;
    };
    static constexpr auto M = [](auto, auto, auto, auto inv_dxy, auto inv_dz, auto inv_m) {
        return inv_dxy * (cl062::basis<"a2a3e2e3"> + cl062::basis<"a3a1e3e1">) + inv_dz * cl062::basis<"a1a2e1e2"> +
               inv_m * rotation_block;
    };
};

struct diagonal {
    template <class T>
    using data = scalars_and_reciprocals<T, 4>;  // m, dx, dy, dz
    template <class T>
    static constexpr auto arguments(const data<T>& b) noexcept {
        return std::tuple{b.value(1),      b.value(2),      b.value(3),      b.value(0),
                          b.reciprocal(1), b.reciprocal(2), b.reciprocal(3), b.reciprocal(0)};
    }
    static constexpr auto N = [](auto dx, auto dy, auto dz, auto m, auto, auto, auto, auto) {
        return dx * cl062::basis<"a1ae1e"> + dy * cl062::basis<"a2ae2e"> + dz * cl062::basis<"a3ae3e"> + m * mass_block;
    };
    static constexpr auto M = [](auto, auto, auto, auto, auto ix, auto iy, auto iz, auto inv_m) {
        return ix * cl062::basis<"a2a3e2e3"> + iy * cl062::basis<"a3a1e3e1"> + iz * cl062::basis<"a1a2e1e2"> +
               inv_m * rotation_block;
    };
};

// N as its 24 blades, M by the ten parameters of body_mobility (1/m, c, J): M = (t t̄) M_c (t t̄)*,
// which acts about the centre of mass, E ∨ (M ∧ X) = t (E ∨ (M_c ∧ (t̄* X t̄))) t* (body_inertia.hpp).
// (body_acceleration runs the typed acceleration(body, …), with N by its ten parameters: the same
// 24m 18a momentum.)
struct general {
    template <class T>
    using data = rigid_body<T>;
    template <class T>
    static constexpr auto arguments(const data<T>& b) noexcept {
        return std::tuple_cat(std::tuple<const rigid_inertia<T>&>{b.N}, b.Mb.parameters());
    }
    static constexpr auto N = [](auto N, auto...) { return N; };
    static constexpr auto M = [](auto, auto... m) { return body_mobility<>::element(m...); };
    static constexpr auto velocity = [](auto X, auto, auto... m) { return body_mobility<>::velocity_of(X, m...); };
};

// A body's data in scalar type U (a pack: the same body in every lane, scenes/batch.hpp): every
// number converted, U(x), none computed again (a lane holds the scalar's bits).
template <class U, class T, std::size_t N>
[[nodiscard]] constexpr scalars_and_reciprocals<U, N> body_cast(const scalars_and_reciprocals<T, N>& b) noexcept {
    return scalars_and_reciprocals<U, N>(b);
}
template <class U, class T>
[[nodiscard]] constexpr rigid_body<U> body_cast(const rigid_body<T>& b) noexcept {
    const auto each = [](auto& to, const auto& from) {
        for (std::size_t c = 0; c < from.size(); ++c) to[c] = U(from[c]);
    };
    rigid_body<U> out{};
    out.properties.mass = U(b.properties.mass);
    each(out.properties.com, b.properties.com);
    for (std::size_t r = 0; r < 3; ++r) each(out.properties.inertia_c[r], b.properties.inertia_c[r]);
    each(out.N, b.N);
    each(out.M, b.M);
    out.Nb = parameters_cast<U>(b.Nb);
    out.Mb = parameters_cast<U>(b.Mb);
    return out;
}

// E ∨ (M ∧ X): the kind's mobility acting on a co-screw X, in the kind's own form when it has one.
template <class K, class X, class... P>
constexpr auto mobility_acting(X x, P... p) noexcept {
    if constexpr (requires { K::velocity(x, p...); }) return K::velocity(x, p...);
    else return invariants::E & (K::M(p...) ^ x);
}

}  // namespace inertia_kind

// The body-frame equation of motion of a free body and of a body under a wrench W, for an
// inertia structure K: one formula each, its arguments s (and W) followed by K's scalars.
template <class K>
inline constexpr auto free_acceleration = formula([](auto s, auto... p) {
    using invariants::A;
    const auto x = lift(s);
    const auto P = A & (K::N(p...) ^ x);
    return inertia_kind::mobility_acting<K>(half * (P * bar(x) - bar(x) * P), p...);
});
template <class K>
inline constexpr auto forced_acceleration = formula([](auto s, auto W, auto... p) {
    using invariants::A;
    const auto x = lift(s);
    const auto P = A & (K::N(p...) ^ x);
    return inertia_kind::mobility_acting<K>(W - half * (bar(x) * P - P * bar(x)), p...);
});

// X's blades viewed in Cl(0,6,2) (lift), as a multivector type.
template <class X>
using lifted_type = std::remove_cvref_t<decltype(eval(lift(std::declval<const X&>())))>;

// ---- applied wrenches ------------------------------------------------------------------------

namespace wrench_model {
// No applied wrench: no wrench code at all.
struct none {};
// A uniform field (gravity): the weight m·a acts at the centre of mass, the body origin. The
// force is written on the ω blades of S's force_type (fixed frame); see weight().
template <class T, class S>
struct uniform_field {
    typename S::template force_type<T> force;
};
}  // namespace wrench_model

// The weight m·a of a body of subspace S in a field of acceleration a (fixed frame).
template <class S, class T>
[[nodiscard]] constexpr wrench_model::uniform_field<T, S> weight(const T& m, const vec3<T>& a) noexcept {
    using F = typename S::template force_type<T>;
    F f{};
    if constexpr (F::size() == 3) f = F{m * a[0], m * a[1], m * a[2]};
    else f = F{m * a[0], m * a[1]};  // planar: the field in the plane of motion
    return {f};
}

// A force f (on ω blades, fixed frame) through the body origin, as the body-frame co-screw
// (0, Rᵀ f): the sandwich g* F g moves F into the body frame (s_b = g* s g, §3) and bar (§5)
// takes a screw's ω blades to a co-screw's p blades (e2e3 ↦ a2a3, …).
inline constexpr auto body_frame_force = formula([](auto g, auto F) { return bar(lift(conj(g) * F * g)); });
template <class S, class T>
using body_force_type = std::remove_cvref_t<decltype(eval(bar(lift(std::declval<const typename S::template force_type<T>&>()))))>;

// ---- the equation of motion of a body kind ----------------------------------------------------

// ṡ for a body of subspace S and inertia structure K, in S's screw type, free or under a
// body-frame wrench W. A body moving in a subspace is held there by its constraint, which
// absorbs the components outside it: ṡ is the projection of the unconstrained ṡ. That is exact
// when N does not couple the subspace to the rest, i.e. for the kinds with the centre of mass at
// the body origin on principal axes (sphere, axisymmetric, diagonal); a general inertia needs
// the full subspace.
template <class S, class K, class T, class... W>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr typename S::template screw_type<T> body_acceleration(
    const typename K::template data<T>& body, const typename S::template screw_type<T>& s, const W&... applied) noexcept {
    static_assert(std::is_same_v<S, subspace::full> || !std::is_same_v<K, inertia_kind::general>,
                  "ctga: a body held in a subspace (planar, rotation, translation) needs an inertia with the centre of mass "
                  "at the body origin on principal axes (inertia_kind::sphere, axisymmetric or diagonal)");
    using lifted = lifted_type<typename S::template screw_type<T>>;
    if constexpr (std::is_same_v<K, inertia_kind::general>) {
        // 24 + 36 blades make one program longer than expr::inline_terms, which would run as a
        // loop (program.hpp); the typed acceleration stages P and the right-hand side as inlined
        // programs and solves about the centre of mass (body.Mb, body_inertia.hpp): 66m, not 78m.
        if constexpr (sizeof...(W) == 0) return ctga::acceleration(body, s, ctga::wrench<T>{});
        else return ctga::acceleration(body, s, ctga::wrench<T>(applied...));
    } else return std::apply(
        [&](const auto&... p) {
            if constexpr (sizeof...(W) == 0) return lower(project<lifted>(free_acceleration<K>(s, p...)));
            else return lower(project<lifted>(forced_acceleration<K>(s, applied..., p...)));
        },
        K::arguments(body));
}

// dg/dt = ½ g s_b in S's motor type.
template <class S, class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr typename S::template motor_type<T> body_motor_rate(
    const typename S::template motor_type<T>& g, const typename S::template screw_type<T>& s) noexcept {
    return half * g * s;
}

namespace body_kinds_detail {
template <class Formula, class Screw, class Extra, class Arguments>
struct acceleration_type;
template <class Formula, class Screw, class... X, class... P>
struct acceleration_type<Formula, Screw, std::tuple<X...>, std::tuple<P...>> {
    using type = decltype(std::declval<const Formula&>()(std::declval<const Screw&>(), std::declval<const X&>()...,
                                                         std::declval<P>()...));
};
}  // namespace body_kinds_detail

// The engine's price of one evaluation of the body-frame rates (ġ, ṡ): what one stage of an
// explicit method costs, the applied wrench included.
template <class S, class K, class Wrench = wrench_model::none, class T = double>
inline constexpr expr::cost body_step_cost = [] {
    using screw_t = typename S::template screw_type<T>;
    using motor_t = typename S::template motor_type<T>;
    using lifted = lifted_type<screw_t>;
    using args = decltype(K::arguments(std::declval<const typename K::template data<T>&>()));
    using rate = decltype(half * std::declval<const motor_t&>() * std::declval<const screw_t&>());
    constexpr expr::cost r = cost_of<rate, motor_t>;
    if constexpr (std::is_same_v<Wrench, wrench_model::none>) {
        using accel = typename body_kinds_detail::acceleration_type<decltype(free_acceleration<K>), screw_t, std::tuple<>, args>::type;
        constexpr expr::cost a = cost_of<accel, lifted>;
        return expr::cost{a.mul + r.mul, a.add + r.add};
    } else {
        using force_t = typename S::template force_type<T>;
        using W = body_force_type<S, T>;
        using field = decltype(std::declval<const T&>() *
                               body_frame_force(std::declval<const motor_t&>(), std::declval<const force_t&>()));
        using norm = decltype(std::declval<const motor_t&>() * conj(std::declval<const motor_t&>()));
        using accel = typename body_kinds_detail::acceleration_type<decltype(forced_acceleration<K>), screw_t, std::tuple<W>, args>::type;
        constexpr expr::cost w = cost_of<field, W>, n = cost_of<norm, cl031::mv<T, "1">>, a = cost_of<accel, lifted>;
        // (and one division: 1/|α|²)
        return expr::cost{a.mul + r.mul + w.mul + n.mul, a.add + r.add + w.add + n.add};
    }
}();

// One body of subspace S and inertia structure K under a wrench model, as a model for the
// integrators (body frame): every operation of a step runs on S's blades. exp and renormalize go through the
// full motor (closed forms of motor.hpp) and drop the blades that S's motions
// leave at exactly zero.
template <class T, class S, class K, class Wrench = wrench_model::none>
struct body_motion {
    using scalar_type = T;
    using subspace_type = S;
    using motor_type = typename S::template motor_type<T>;
    using screw_type = typename S::template screw_type<T>;
    static constexpr frame velocity_frame = frame::body;

    typename K::template data<T> body;
    Wrench applied{};

    [[nodiscard]] constexpr screw_type acceleration(const motor_type& g, const screw_type& s) const noexcept {
        if constexpr (std::is_same_v<Wrench, wrench_model::none>) {
            return body_acceleration<S, K, T>(body, s);
        } else {
            // divided by g g* = |α|², so that a motor off g g* = 1 (an RK4 stage) acts as the
            // rotation it encodes, as map_of does
            const T inv_norm = T(1) / scalar_part(g * conj(g));
            const body_force_type<S, T> W = project<body_force_type<S, T>>(inv_norm * body_frame_force(g, applied.force));
            return body_acceleration<S, K, T>(body, s, W);
        }
    }
    // The same under an additional body-frame wrench (a scene's springs): only bodies that have
    // one pay for it.
    [[nodiscard]] constexpr screw_type acceleration(const motor_type& g, const screw_type& s,
                                                    const coscrew<T>& extra) const noexcept {
        if constexpr (std::is_same_v<Wrench, wrench_model::none>) {
            return body_acceleration<S, K, T>(body, s, extra);
        } else {
            const T inv_norm = T(1) / scalar_part(g * conj(g));
            const coscrew<T> W = inv_norm * body_frame_force(g, applied.force) + extra;
            return body_acceleration<S, K, T>(body, s, W);
        }
    }
    [[nodiscard]] constexpr motor_type motor_rate(const motor_type& g, const screw_type& s) const noexcept {
        return body_motor_rate<S, T>(g, s);
    }
    [[nodiscard]] constexpr motor_type exp(const screw_type& z) const noexcept {
        return project<motor_type>(ctga::exp(screw<T>(z)));
    }
    [[nodiscard]] constexpr motor_type compose(const motor_type& a, const motor_type& b) const noexcept { return a * b; }
    [[nodiscard]] constexpr screw_type bracket(const screw_type& a, const screw_type& b) const noexcept {
        return ctga::bracket.formula(a, b);
    }
    [[nodiscard]] constexpr motor_type renormalize(const motor_type& g) const noexcept {
        return project<motor_type>(ctga::renormalize(motor<T>(g)));
    }
    [[nodiscard]] constexpr bool unit(const motor_type& g) const noexcept { return near_unit(motor<T>(g)); }
    [[nodiscard]] constexpr bool finite(const motor_type& g, const screw_type& s) const noexcept {
        for (std::size_t i = 0; i < g.size(); ++i)
            if (!is_finite(g[i])) return false;
        for (std::size_t i = 0; i < s.size(); ++i)
            if (!is_finite(s[i])) return false;
        return true;
    }
    [[nodiscard]] constexpr T magnitude(const screw_type& z) const noexcept {
        T out = T(0);
        for (std::size_t i = 0; i < z.size(); ++i) out = z[i] > out ? z[i] : (-z[i] > out ? -z[i] : out);
        return out;
    }
};

}  // namespace ctga
