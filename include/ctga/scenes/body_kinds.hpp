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
// Inertia structures (body frame at the centre of mass, principal axes; the scalars each has):
//   sphere        m, d                 N = d·(rotation block) + m·(mass block)
//   axisymmetric  m, d_xy, d_z         about the body's e3 axis
//   diagonal      m, dx, dy, dz        principal axes (§5's diagonal inertia)
//   general       rigid_inertia N and mobility M as stored (24 and 36 blades): any body frame
// A planar body needs its plane's normal to be a principal axis through the centre of mass
// (sphere, axisymmetric or diagonal): then N keeps the plane's velocities in the plane.
#pragma once

#include <tuple>
#include <type_traits>

#include "ctga/mechanics/dynamics.hpp"
#include "ctga/mechanics/exp_log.hpp"
#include "ctga/mechanics/motion.hpp"
#include "ctga/mechanics/spatial.hpp"
#include "ctga/integrators/model.hpp"

namespace ctga {

namespace subspace {
struct full {
    template <class T>
    using screw_type = screw<T>;
    template <class T>
    using motor_type = motor<T>;
};
struct planar {
    template <class T>
    using screw_type = cl031::mv<T, "e1e2", "e1e", "e2e">;
    template <class T>
    using motor_type = cl031::mv<T, "1", "e1e2", "e1e", "e2e">;
};
struct rotation {
    template <class T>
    using screw_type = cl031::mv<T, "e2e3", "e3e1", "e1e2">;
    template <class T>
    using motor_type = rotor<T>;
};
struct translation {
    template <class T>
    using screw_type = cl031::mv<T, "e1e", "e2e", "e3e">;
    template <class T>
    using motor_type = translator<T>;
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

struct sphere {
    template <class T>
    struct data {
        T m, d;
    };
    template <class T>
    static constexpr auto arguments(const data<T>& b) noexcept {
        return std::tuple{scalar<T>{b.d}, scalar<T>{b.m}, scalar<T>{T(1) / b.d}, scalar<T>{T(1) / b.m}};
    }
    static constexpr auto N = [](auto d, auto m, auto, auto) { return d * rotation_block + m * mass_block; };
    static constexpr auto M = [](auto, auto, auto inv_d, auto inv_m) { return inv_d * mass_block + inv_m * rotation_block; };
};

struct axisymmetric {  // about e3
    template <class T>
    struct data {
        T m, d_xy, d_z;
    };
    template <class T>
    static constexpr auto arguments(const data<T>& b) noexcept {
        return std::tuple{scalar<T>{b.d_xy}, scalar<T>{b.d_z}, scalar<T>{b.m}, scalar<T>{T(1) / b.d_xy},
                          scalar<T>{T(1) / b.d_z}, scalar<T>{T(1) / b.m}};
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
    struct data {
        T m, dx, dy, dz;
    };
    template <class T>
    static constexpr auto arguments(const data<T>& b) noexcept {
        return std::tuple{scalar<T>{b.dx},         scalar<T>{b.dy},         scalar<T>{b.dz},
                          scalar<T>{b.m},          scalar<T>{T(1) / b.dx}, scalar<T>{T(1) / b.dy},
                          scalar<T>{T(1) / b.dz}, scalar<T>{T(1) / b.m}};
    }
    static constexpr auto N = [](auto dx, auto dy, auto dz, auto m, auto, auto, auto, auto) {
        return dx * cl062::basis<"a1ae1e"> + dy * cl062::basis<"a2ae2e"> + dz * cl062::basis<"a3ae3e"> + m * mass_block;
    };
    static constexpr auto M = [](auto, auto, auto, auto, auto ix, auto iy, auto iz, auto inv_m) {
        return ix * cl062::basis<"a2a3e2e3"> + iy * cl062::basis<"a3a1e3e1"> + iz * cl062::basis<"a1a2e1e2"> +
               inv_m * rotation_block;
    };
};

struct general {
    template <class T>
    using data = rigid_body<T>;
    template <class T>
    static constexpr auto arguments(const data<T>& b) noexcept {
        return std::tuple<const rigid_inertia<T>&, const mobility<T>&>{b.N, b.M};
    }
    static constexpr auto N = [](auto N, auto) { return N; };
    static constexpr auto M = [](auto, auto M) { return M; };
};

}  // namespace inertia_kind

// The body-frame equation of motion of a free body and of a body under a wrench W, for an
// inertia structure K: one formula each, its arguments s (and W) followed by K's scalars.
template <class K>
inline constexpr auto free_acceleration = formula([](auto s, auto... p) {
    using invariants::A;
    using invariants::E;
    const auto x = lift(s);
    const auto P = A & (K::N(p...) ^ x);
    return E & (K::M(p...) ^ (half * (P * bar(x) - bar(x) * P)));
});
template <class K>
inline constexpr auto forced_acceleration = formula([](auto s, auto W, auto... p) {
    using invariants::A;
    using invariants::E;
    const auto x = lift(s);
    const auto P = A & (K::N(p...) ^ x);
    return E & (K::M(p...) ^ (W - half * (bar(x) * P - P * bar(x))));
});

// X's blades viewed in Cl(0,6,2) (lift), as a multivector type.
template <class X>
using lifted_type = std::remove_cvref_t<decltype(eval(lift(std::declval<const X&>())))>;

// ṡ for a body of subspace S and inertia structure K, in S's screw type. The result's blades are
// those the formula can make non-zero; a body whose inertia would push its velocity out of the
// subspace does not compile (the assignment names the blade).
template <class S, class K, class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr typename S::template screw_type<T> body_acceleration(
    const typename K::template data<T>& body, const typename S::template screw_type<T>& s) noexcept {
    static_assert(!(std::is_same_v<S, subspace::planar> && std::is_same_v<K, inertia_kind::general>),
                  "ctga: a planar body needs an inertia with a principal axis along e3 through the centre of mass "
                  "(inertia_kind::sphere, axisymmetric or diagonal)");
    using lifted = lifted_type<typename S::template screw_type<T>>;
    return std::apply([&](const auto&... p) { return lower(lifted(free_acceleration<K>(s, p...))); }, K::arguments(body));
}

// dg/dt = ½ g s_b in S's motor type.
template <class S, class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr typename S::template motor_type<T> body_motor_rate(
    const typename S::template motor_type<T>& g, const typename S::template screw_type<T>& s) noexcept {
    return half * g * s;
}

namespace body_kinds_detail {
template <class K, class Screw, class Arguments>
struct acceleration_type;
template <class K, class Screw, class... P>
struct acceleration_type<K, Screw, std::tuple<P...>> {
    using type = decltype(free_acceleration<K>(std::declval<const Screw&>(), std::declval<P>()...));
};
}  // namespace body_kinds_detail

// The engine's price of one evaluation of the body-frame rates (ġ, ṡ) of a free body: what one
// stage of an explicit method costs.
template <class S, class K, class T = double>
inline constexpr expr::cost body_step_cost = [] {
    using screw_t = typename S::template screw_type<T>;
    using motor_t = typename S::template motor_type<T>;
    using args = decltype(K::arguments(std::declval<const typename K::template data<T>&>()));
    using accel = typename body_kinds_detail::acceleration_type<K, screw_t, args>::type;
    using rate = decltype(half * std::declval<const motor_t&>() * std::declval<const screw_t&>());
    constexpr expr::cost a = cost_of<accel, lifted_type<screw_t>>, r = cost_of<rate, motor_t>;
    return expr::cost{a.mul + r.mul, a.add + r.add};
}();

// One body of subspace S and inertia structure K as a model for the integrators (body frame,
// free): every operation of a step runs on S's blades. exp and renormalize go through the
// full motor (closed forms of exp_log.hpp and motion.hpp) and drop the blades that S's motions
// leave at exactly zero.
template <class T, class S, class K>
struct body_motion {
    using scalar_type = T;
    using motor_type = typename S::template motor_type<T>;
    using screw_type = typename S::template screw_type<T>;
    static constexpr frame velocity_frame = frame::body;

    typename K::template data<T> body;

    [[nodiscard]] constexpr screw_type acceleration(const motor_type&, const screw_type& s) const noexcept {
        return body_acceleration<S, K, T>(body, s);
    }
    [[nodiscard]] constexpr motor_type motor_rate(const motor_type& g, const screw_type& s) const noexcept {
        return body_motor_rate<S, T>(g, s);
    }
    [[nodiscard]] constexpr motor_type exp(const screw_type& z) const noexcept {
        return project<motor_type>(ctga::exp(screw<T>(z)));
    }
    [[nodiscard]] constexpr motor_type compose(const motor_type& a, const motor_type& b) const noexcept { return a * b; }
    [[nodiscard]] constexpr screw_type bracket(const screw_type& a, const screw_type& b) const noexcept {
        return paper::bracket(a, b);
    }
    [[nodiscard]] constexpr motor_type renormalize(const motor_type& g) const noexcept {
        return project<motor_type>(ctga::renormalize(motor<T>(g)));
    }
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
