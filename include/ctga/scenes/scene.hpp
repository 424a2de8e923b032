// A scene: a heterogeneous collection of bodies stepped together, each paying only for what its
// type declares (body_kinds.hpp).
//
//   auto world = ctga::make_scene(
//       ctga::body_motion<double, subspace::full, inertia_kind::diagonal>{{2, 2, 2.5, 3}},
//       ctga::body_motion<double, subspace::planar, inertia_kind::sphere, wrench_model::uniform_field<double, subspace::planar>>{...},
//       ctga::static_body<double>{pose});
//   auto state = world.initial_state(std::tuple{x0, x1});   // one motion_state per moving body
//   auto run = ctga::integrate(ctga::lie_rk4{}, world.model(), state, h, steps);
//
// The moving bodies form one model of the product group: its motor is the tuple of the bodies'
// motors, its screw the tuple of their screws, and every operation an integrator asks for is
// applied body by body (Boost.Hana unrolls the tuple at compile time, so each body runs its own
// straight-line code and no body waits on a virtual call). The same integrators as for one body
// therefore step the whole scene. Static bodies (a pose, no velocity) and kinematic bodies (a
// prescribed motion, evaluated when asked) are not part of the product: they cost nothing per
// step.
#pragma once

#include <tuple>
#include <type_traits>
#include <utility>

#include <boost/hana/at.hpp>
#include <boost/hana/bool.hpp>
#include <boost/hana/filter.hpp>
#include <boost/hana/for_each.hpp>
#include <boost/hana/front.hpp>
#include <boost/hana/remove_if.hpp>
#include <boost/hana/tuple.hpp>
#include <boost/hana/unpack.hpp>
#include <boost/hana/zip.hpp>

#include "ctga/integrators/model.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/coscrew.hpp"

namespace ctga {

// An element of the product of the bodies' spaces: one motor per moving body, or one screw per
// moving body (a point of the product group, or of its Lie algebra); +, − and scaling act part by part.
template <class... X>
struct per_body {
    boost::hana::tuple<X...> parts;

    template <class F, class... Others>
    [[nodiscard]] friend constexpr per_body zip_with(F f, const per_body& a, const Others&... others) {
        return {boost::hana::unpack(boost::hana::zip(a.parts, others.parts...), [&](const auto&... part) {
            return boost::hana::make_tuple(boost::hana::unpack(part, [&](const auto&... x) {
                return std::remove_cvref_t<decltype(boost::hana::front(part))>(f(x...));
            })...);
        })};
    }
    [[nodiscard]] friend constexpr per_body operator+(const per_body& a, const per_body& b) {
        return zip_with([](const auto& x, const auto& y) { return x + y; }, a, b);
    }
    [[nodiscard]] friend constexpr per_body operator-(const per_body& a, const per_body& b) {
        return zip_with([](const auto& x, const auto& y) { return x - y; }, a, b);
    }
    template <class T>
        requires std::is_arithmetic_v<T>
    [[nodiscard]] friend constexpr per_body operator*(const T& c, const per_body& a) {
        return zip_with([&](const auto& x) { return c * x; }, a);
    }
};

// A body that does not move: a pose and nothing to integrate.
template <class T = double>
struct static_body {
    motor<T> pose;
};
// A body whose motion is prescribed: g(t) = exp(t s) g0 for a constant fixed-frame velocity s,
// evaluated when asked.
template <class T = double>
struct kinematic_body {
    motor<T> start;
    screw<T> velocity;
    [[nodiscard]] constexpr motor<T> pose(const T& t) const noexcept { return ctga::exp(screw<T>(t * velocity)) * start; }
};

template <class B>
inline constexpr bool is_moving_body = true;
template <class T>
inline constexpr bool is_moving_body<static_body<T>> = false;
template <class T>
inline constexpr bool is_moving_body<kinematic_body<T>> = false;

// A spring–damper of zero rest length between a point of moving body I and a point of moving
// body J (indices among the scene's moving bodies, in order), or a fixed point of the world
// (J = world). With p the attachment points and v their velocities in the fixed frame, body I
// feels f = k (p_J − p_I) + c (v_J − v_I) at its point and body J feels −f at its own; in a
// body's frame that is the co-screw (a × f_b, f_b), f_b = Rᵀ f, a the attachment (§5: a force
// through a point). The potential energy is ½ k |p_J − p_I|².
inline constexpr std::size_t world = static_cast<std::size_t>(-1);
template <std::size_t I, std::size_t J, class T = double>
struct spring_damper {
    static constexpr std::size_t first = I, second = J;
    vec3<T> at_first;   // on body I, in its frame
    vec3<T> at_second;  // on body J, in its frame; a fixed point when J == world
    T stiffness{}, damping{};
};

namespace scene_detail {
// A point a of a body (its frame) in the fixed frame, and its velocity: p = R a + t,
// v = R (v_b + ω_b × a), from the rigid motion the motor encodes (map_of is homogeneous).
template <class T>
struct point_motion {
    vec3<T> p, v;
};
template <class T, class G, class Sc>
constexpr point_motion<T> point_of(const G& g, const Sc& s_b, const vec3<T>& a) noexcept {
    const motor_map<T> M = map_of(motor<T>(g));
    const screw<T> s(s_b);
    const vec3<T> w{s[0], s[1], s[2]};
    const vec3<T> local = linear3::add(vec3<T>{s[3], s[4], s[5]}, linear3::cross(w, a));
    return {linear3::add(linear3::apply(M.R, a), M.t), linear3::apply(M.R, local)};
}
// The wrench on a body at its attachment a from a fixed-frame force f, in the body's frame.
template <class T, class G>
constexpr coscrew<T> wrench_at(const G& g, const vec3<T>& a, const vec3<T>& f) noexcept {
    const motor_map<T> M = map_of(motor<T>(g));
    const vec3<T> fb = linear3::apply_transposed(M.R, f);
    const vec3<T> l = linear3::cross(a, fb);
    return coscrew<T>{l[0], l[1], l[2], fb[0], fb[1], fb[2]};
}
}  // namespace scene_detail

template <class... X>
struct springs {
    boost::hana::tuple<X...> list;
};

// The moving bodies of a scene as one model (body frame) for the integrators of methods.hpp.
template <class Springs, class... Models>
struct scene_model;
template <class... Springs, class... Models>
struct scene_model<springs<Springs...>, Models...> {
    static_assert(sizeof...(Models) > 0, "ctga: a scene needs at least one moving body");
    static_assert(((Models::velocity_frame == frame::body) && ...), "ctga: scene bodies use body-frame velocities");
    using scalar_type = std::common_type_t<typename Models::scalar_type...>;
    using motor_type = per_body<typename Models::motor_type...>;
    using screw_type = per_body<typename Models::screw_type...>;
    static constexpr frame velocity_frame = frame::body;

    boost::hana::tuple<Models...> bodies;
    springs<Springs...> coupling{};

    // body B is attached to a spring
    template <std::size_t B>
    static constexpr bool attached = ((Springs::first == B || Springs::second == B) || ...);

    // f(body, parts of the arguments...) for every body, collected into a per_body of type R.
    template <class R, class F, class... A>
    [[nodiscard]] constexpr R each(F f, const A&... a) const {
        return {boost::hana::unpack(boost::hana::zip(bodies, a.parts...), [&](const auto&... row) {
            return boost::hana::make_tuple(
                boost::hana::unpack(row, [&](const auto& body, const auto&... x) { return f(body, x...); })...);
        })};
    }

    [[nodiscard]] constexpr screw_type acceleration(const motor_type& g, const screw_type& s) const {
        return accelerations(g, s, std::make_index_sequence<sizeof...(Models)>{});
    }
    template <std::size_t... B>
    [[nodiscard]] constexpr screw_type accelerations(const motor_type& g, const screw_type& s, std::index_sequence<B...>) const {
        return {boost::hana::make_tuple(acceleration_of<B>(g, s)...)};
    }
    template <std::size_t B>
    [[nodiscard]] constexpr auto acceleration_of(const motor_type& g, const screw_type& s) const {
        const auto& body = boost::hana::at_c<B>(bodies);
        const auto& gb = boost::hana::at_c<B>(g.parts);
        const auto& sb = boost::hana::at_c<B>(s.parts);
        if constexpr (!attached<B>) return body.acceleration(gb, sb);
        else return body.acceleration(gb, sb, spring_wrench<B>(g, s));
    }
    // The sum of the springs' wrenches on body B, in its frame.
    template <std::size_t B>
    [[nodiscard]] constexpr coscrew<scalar_type> spring_wrench(const motor_type& g, const screw_type& s) const {
        using T = scalar_type;
        coscrew<T> total{};
        boost::hana::for_each(coupling.list, [&](const auto& spring) {
            using sp = std::remove_cvref_t<decltype(spring)>;
            if constexpr (sp::first == B || sp::second == B) {
                const auto& g1 = boost::hana::at_c<sp::first>(g.parts);
                const auto& s1 = boost::hana::at_c<sp::first>(s.parts);
                const scene_detail::point_motion<T> a = scene_detail::point_of<T>(g1, s1, spring.at_first);
                scene_detail::point_motion<T> b{spring.at_second, {}};
                if constexpr (sp::second != world)
                    b = scene_detail::point_of<T>(boost::hana::at_c<sp::second>(g.parts), boost::hana::at_c<sp::second>(s.parts),
                                                  spring.at_second);
                vec3<T> f{};
                for (std::size_t i = 0; i < 3; ++i)
                    f[i] = spring.stiffness * (b.p[i] - a.p[i]) + spring.damping * (b.v[i] - a.v[i]);
                if constexpr (sp::first == B) {
                    total = coscrew<T>(total + scene_detail::wrench_at(g1, spring.at_first, f));
                } else {
                    const vec3<T> minus_f{-f[0], -f[1], -f[2]};
                    total = coscrew<T>(total + scene_detail::wrench_at(boost::hana::at_c<B>(g.parts), spring.at_second, minus_f));
                }
            }
        });
        return total;
    }
    [[nodiscard]] constexpr motor_type motor_rate(const motor_type& g, const screw_type& s) const {
        return each<motor_type>([](const auto& b, const auto& gi, const auto& si) { return b.motor_rate(gi, si); }, g, s);
    }
    [[nodiscard]] constexpr motor_type exp(const screw_type& z) const {
        return each<motor_type>([](const auto& b, const auto& zi) { return b.exp(zi); }, z);
    }
    [[nodiscard]] constexpr motor_type compose(const motor_type& x, const motor_type& y) const {
        return each<motor_type>([](const auto& b, const auto& xi, const auto& yi) { return b.compose(xi, yi); }, x, y);
    }
    [[nodiscard]] constexpr screw_type bracket(const screw_type& x, const screw_type& y) const {
        return each<screw_type>([](const auto& b, const auto& xi, const auto& yi) { return b.bracket(xi, yi); }, x, y);
    }
    [[nodiscard]] constexpr motor_type renormalize(const motor_type& g) const {
        return each<motor_type>([](const auto& b, const auto& gi) { return b.renormalize(gi); }, g);
    }
    [[nodiscard]] constexpr bool unit(const motor_type& g) const {
        return boost::hana::unpack(boost::hana::zip(bodies, g.parts), [](const auto&... row) {
            return (boost::hana::unpack(row, [](const auto& b, const auto& gi) { return b.unit(gi); }) && ...);
        });
    }
    [[nodiscard]] constexpr bool finite(const motor_type& g, const screw_type& s) const {
        return boost::hana::unpack(boost::hana::zip(bodies, g.parts, s.parts), [](const auto&... row) {
            return (boost::hana::unpack(row, [](const auto& b, const auto& gi, const auto& si) { return b.finite(gi, si); }) &&
                    ...);
        });
    }
    [[nodiscard]] constexpr scalar_type magnitude(const screw_type& z) const {
        scalar_type out{};
        boost::hana::for_each(boost::hana::zip(bodies, z.parts), [&](const auto& row) {
            const scalar_type m = boost::hana::at_c<0>(row).magnitude(boost::hana::at_c<1>(row));
            out = m > out ? m : out;
        });
        return out;
    }
};

// A scene: its moving bodies as one model, and the bodies whose motion is prescribed (static and
// kinematic ones) as they are.
template <class Moving, class Prescribed>
struct scene {
    Moving moving;          // a scene_model
    Prescribed prescribed;  // a hana::tuple of static and kinematic bodies

    [[nodiscard]] constexpr const Moving& model() const noexcept { return moving; }
    // The scene's state from one motion_state per moving body, in order.
    template <class... States>
    [[nodiscard]] constexpr state_of<Moving> initial_state(const States&... x) const {
        return {typename Moving::motor_type{boost::hana::make_tuple(x.g...)},
                typename Moving::screw_type{boost::hana::make_tuple(x.s...)}};
    }
};

// Sorts the bodies at compile time: moving ones into the product model, the others aside; the
// springs (if any) couple moving bodies by their indices among the moving ones.
template <class... Springs, class... Bodies>
[[nodiscard]] constexpr auto make_scene(const springs<Springs...>& coupling, const Bodies&... bodies) {
    const auto all = boost::hana::make_tuple(bodies...);
    const auto moving = boost::hana::filter(all, [](const auto& b) {
        return boost::hana::bool_c<is_moving_body<std::remove_cvref_t<decltype(b)>>>;
    });
    const auto prescribed = boost::hana::remove_if(all, [](const auto& b) {
        return boost::hana::bool_c<is_moving_body<std::remove_cvref_t<decltype(b)>>>;
    });
    using model_t = decltype(boost::hana::unpack(moving, [](const auto&... m) {
        return scene_model<springs<Springs...>, std::remove_cvref_t<decltype(m)>...>{boost::hana::make_tuple(m...)};
    }));
    const model_t model =
        boost::hana::unpack(moving, [&](const auto&... m) { return model_t{boost::hana::make_tuple(m...), coupling}; });
    return scene<model_t, std::remove_cvref_t<decltype(prescribed)>>{model, prescribed};
}
template <class... Bodies>
[[nodiscard]] constexpr auto make_scene(const Bodies&... bodies) {
    return make_scene(springs<>{}, bodies...);
}
// The springs of a scene, by value: make_scene(ctga::couple(spring_damper<0, 1>{…}, …), bodies…).
template <class... X>
[[nodiscard]] constexpr springs<X...> couple(const X&... x) {
    return {boost::hana::make_tuple(x...)};
}

// f(part) for every body's part of a per_body, in order.
template <class... X, class F>
constexpr void for_each_part(const per_body<X...>& p, F&& f) {
    boost::hana::for_each(p.parts, f);
}

// Body i's part of a per_body (its motor or its screw).
template <std::size_t I, class... X>
[[nodiscard]] constexpr const auto& part(const per_body<X...>& p) noexcept {
    return boost::hana::at_c<I>(p.parts);
}

}  // namespace ctga
