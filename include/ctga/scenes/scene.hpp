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

#include <boost/hana.hpp>

#include "ctga/integrators/model.hpp"
#include "ctga/mechanics/exp_log.hpp"
#include "ctga/mechanics/motion.hpp"

namespace ctga {

// An element of a product of vector spaces (the bodies' motors, or their screws): +, − and
// scaling act part by part.
template <class... X>
struct product {
    boost::hana::tuple<X...> parts;

    template <class F, class... Others>
    [[nodiscard]] friend constexpr product zip_with(F f, const product& a, const Others&... others) {
        return {boost::hana::unpack(boost::hana::zip(a.parts, others.parts...), [&](const auto&... part) {
            return boost::hana::make_tuple(boost::hana::unpack(part, [&](const auto&... x) {
                return std::remove_cvref_t<decltype(boost::hana::front(part))>(f(x...));
            })...);
        })};
    }
    [[nodiscard]] friend constexpr product operator+(const product& a, const product& b) {
        return zip_with([](const auto& x, const auto& y) { return x + y; }, a, b);
    }
    [[nodiscard]] friend constexpr product operator-(const product& a, const product& b) {
        return zip_with([](const auto& x, const auto& y) { return x - y; }, a, b);
    }
    template <class T>
        requires std::is_arithmetic_v<T>
    [[nodiscard]] friend constexpr product operator*(const T& c, const product& a) {
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

// The moving bodies of a scene as one model (body frame) for the integrators of methods.hpp.
template <class... Models>
struct scene_model {
    static_assert(sizeof...(Models) > 0, "ctga: a scene needs at least one moving body");
    static_assert(((Models::velocity_frame == frame::body) && ...), "ctga: scene bodies use body-frame velocities");
    using scalar_type = std::common_type_t<typename Models::scalar_type...>;
    using motor_type = product<typename Models::motor_type...>;
    using screw_type = product<typename Models::screw_type...>;
    static constexpr frame velocity_frame = frame::body;

    boost::hana::tuple<Models...> bodies;

    // f(body, parts of the arguments...) for every body, collected into a product of type R.
    template <class R, class F, class... A>
    [[nodiscard]] constexpr R each(F f, const A&... a) const {
        return {boost::hana::unpack(boost::hana::zip(bodies, a.parts...), [&](const auto&... row) {
            return boost::hana::make_tuple(
                boost::hana::unpack(row, [&](const auto& body, const auto&... x) { return f(body, x...); })...);
        })};
    }

    [[nodiscard]] constexpr screw_type acceleration(const motor_type& g, const screw_type& s) const {
        return each<screw_type>([](const auto& b, const auto& gi, const auto& si) { return b.acceleration(gi, si); }, g, s);
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

// A scene: its moving bodies as one model, and its static and kinematic bodies as they are.
template <class Moving, class Fixed>
struct scene {
    Moving moving;  // a scene_model
    Fixed fixed;    // a hana::tuple of static and kinematic bodies

    [[nodiscard]] constexpr const Moving& model() const noexcept { return moving; }
    // The scene's state from one motion_state per moving body, in order.
    template <class... States>
    [[nodiscard]] constexpr state_of<Moving> initial_state(const States&... x) const {
        return {typename Moving::motor_type{boost::hana::make_tuple(x.g...)},
                typename Moving::screw_type{boost::hana::make_tuple(x.s...)}};
    }
};

// Sorts the bodies at compile time: moving ones into the product model, the others aside.
template <class... Bodies>
[[nodiscard]] constexpr auto make_scene(const Bodies&... bodies) {
    const auto all = boost::hana::make_tuple(bodies...);
    const auto moving = boost::hana::filter(all, [](const auto& b) {
        return boost::hana::bool_c<is_moving_body<std::remove_cvref_t<decltype(b)>>>;
    });
    const auto fixed = boost::hana::remove_if(all, [](const auto& b) {
        return boost::hana::bool_c<is_moving_body<std::remove_cvref_t<decltype(b)>>>;
    });
    using model_t = decltype(boost::hana::unpack(moving, [](const auto&... m) {
        return scene_model<std::remove_cvref_t<decltype(m)>...>{boost::hana::make_tuple(m...)};
    }));
    const model_t model = boost::hana::unpack(moving, [](const auto&... m) { return model_t{boost::hana::make_tuple(m...)}; });
    return scene<model_t, std::remove_cvref_t<decltype(fixed)>>{model, fixed};
}

// Body i's part of a product (its motor or its screw).
template <std::size_t I, class... X>
[[nodiscard]] constexpr const auto& part(const product<X...>& p) noexcept {
    return boost::hana::at_c<I>(p.parts);
}

}  // namespace ctga
