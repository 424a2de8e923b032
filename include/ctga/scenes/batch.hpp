// Many bodies of one kind, stepped together in a structure-of-arrays layout.
//
//   ctga::batch<double, ctga::subspace::full, ctga::inertia_kind::diagonal, 10'000> bodies{{m, dx, dy, dz}};
//   bodies.add(g0, s0);                        // false once Capacity bodies are held
//   if (bodies.step_rk4(1e-3) != ctga::error_code::none) { /* a NaN or ∞ somewhere */ }
//   ctga::motor<double> g = bodies.pose(7);    // body 7's pose and velocity as ctga types
//
// Layout. For every component of the motor and of the body-frame velocity screw, one contiguous
// array over the bodies (8 + 6 arrays for subspace::full, 4 + 3 for planar): component c of body
// i is g_[c][i]. No heap: std::array storage of a fixed Capacity and a run-time count ≤ Capacity
// (the object is 14 × 8 × Capacity bytes for full bodies in double: put a large batch in static
// or heap storage).
//
// One set of mass properties. A batch holds identical bodies: one `K::data<T>` for all of them
// (bodies of one kind with different masses or moments go in different batches). The mass
// properties are then loop invariants: the inertia's scalars and their reciprocals (stored in
// K::data when it is made, body_kinds.hpp) sit in registers, so the per-body work is the equation of motion and nothing else, and every
// kind, `general` included (60 numbers per body), costs no memory traffic beyond the state.
//
// step_rk4(h) is the classical Runge–Kutta step of ctga::rk4{} on (g, s) in the body frame, the
// motor renormalised afterwards, as loops over the bodies whose bodies are straight-line code:
// load body i's components into ctga multivectors, evaluate the rates with body_motor_rate and
// body_acceleration (always-inline engine code), combine the stages with rk4::step's
// expressions, store; then renormalise. No branch depends on the data and every access is
// unit-stride, so GCC vectorises every loop across bodies (2 bodies per SSE2 register, 4 or 8
// with AVX or AVX-512) with no flags beyond -O2/-O3. The arithmetic is rk4's own, operation for
// operation, so with batch_renormalization::exact (the default) each body gets exactly the
// numbers of ctga::rk4{}.step(body_motion<T, S, K>{body}, x, h), as long as the compiler forms
// no fused multiply-adds (GCC contracts a·b + c by default in C++ when the target has FMA, e.g.
// -march=native, and may do so differently in the two codes: then they agree to rounding).
//
// Renormalisation without branches: branch_free.hpp.
//
// Failures. Each loop that stores also ORs together, branch-free, a flag word per component
// that marks a NaN or an infinity (an integer reduction over the bits of the new state, which
// vectorises too); after the loops step_rk4 tests it once and returns error_code::non_finite
// when any body's new state is not finite (first_non_finite() finds the body). The step is not
// undone: bodies with finite states are stepped correctly, and a non-finite one stays so. A
// non-finite h is rejected before anything is stepped.
//
// aos_step_rk4 is the array-of-structures reference: ctga::rk4{}.step for each body of a
// std::array of motion_states (bench/batch.cpp times the two).
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

#include "ctga/integrators/methods.hpp"
#include "ctga/integrators/model.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/scenes/body_kinds.hpp"
#include "ctga/scenes/branch_free.hpp"

namespace ctga {


// N ≤ Capacity bodies of subspace S and inertia structure K with one set of mass properties, in
// structure-of-arrays layout (see the top of this file).
template <class T, class S, class K, std::size_t Capacity, batch_renormalization Renormalization = batch_renormalization::exact>
class batch {
public:
    using scalar_type = T;
    using motor_type = typename S::template motor_type<T>;
    using screw_type = typename S::template screw_type<T>;
    using body_type = typename K::template data<T>;
    using model_type = body_motion<T, S, K>;
    using state_type = motion_state<motor_type, screw_type>;

    static constexpr std::size_t motor_size = motor_type::size();
    static constexpr std::size_t screw_size = screw_type::size();

    constexpr batch() noexcept = default;
    constexpr explicit batch(const body_type& body) noexcept : body_(body) {}

    [[nodiscard]] static constexpr std::size_t capacity() noexcept { return Capacity; }
    [[nodiscard]] constexpr std::size_t size() const noexcept { return n_; }
    [[nodiscard]] constexpr const body_type& body() const noexcept { return body_; }
    // The single-body model whose rk4 step the batch's step reproduces.
    [[nodiscard]] constexpr model_type model() const noexcept { return model_type{body_}; }

    constexpr void clear() noexcept { n_ = 0; }

    // Appends a body with pose g and body-frame velocity s; false (and nothing added) when the
    // batch is full. Nothing is validated here: step_rk4 reports non-finite states.
    constexpr bool add(const motor_type& g, const screw_type& s) noexcept {
        if (n_ == Capacity) return false;
        store(n_++, g, s);
        return true;
    }
    constexpr bool add(const state_type& x) noexcept { return add(x.g, x.s); }

    // Body i's pose, velocity and state as ctga types (i < size()).
    [[nodiscard]] constexpr motor_type pose(std::size_t i) const noexcept {
        return load<motor_type>(g_, i, std::make_index_sequence<motor_size>{});
    }
    [[nodiscard]] constexpr screw_type velocity(std::size_t i) const noexcept {
        return load<screw_type>(s_, i, std::make_index_sequence<screw_size>{});
    }
    [[nodiscard]] constexpr state_type state(std::size_t i) const noexcept { return {pose(i), velocity(i)}; }
    constexpr void set(std::size_t i, const motor_type& g, const screw_type& s) noexcept { store(i, g, s); }

    // The contiguous array of motor (screw) component c over the bodies: c in the order of
    // motor_type's (screw_type's) blades, entries 0 … size() − 1 meaningful.
    [[nodiscard]] constexpr const T* motor_component(std::size_t c) const noexcept { return g_[c].data(); }
    [[nodiscard]] constexpr const T* screw_component(std::size_t c) const noexcept { return s_[c].data(); }

    // One classical RK4 step of size h for every body (see the top of this file): the results of
    // ctga::rk4{}.step(model(), state(i), h) with renormalisation. Returns non_finite, having
    // stepped nothing, for a non-finite h; and non_finite, after the step, when some body's new
    // state has a NaN or an infinity.
    constexpr error_code step_rk4(const T& step) noexcept {
        // by value: a reference could point into the arrays the loop stores to, and would be
        // reloaded on every iteration (a block after the loop's exit test: no if-conversion)
        const T h = step;
        if (!is_finite(h)) return error_code::non_finite;
        typename flags::word bad = 0;
        std::array<T, block> scale{}, root{};  // per body of a block: the scale, and n² then its root
        for (std::size_t first = 0; first < n_; first += block) {
            const std::size_t last = first + block < n_ ? first + block : n_;
            bad |= advance(first, last, h);
            measure(first, last, scale, root);
            for (std::size_t j = 0; j < last - first; ++j) root[j] = renormalizer::root(root[j]);
            bad |= apply(first, last, scale, root);
        }
        return flags::any(bad) ? error_code::non_finite : error_code::none;
    }

    // The first body whose state has a NaN or an infinity, or size() when there is none.
    [[nodiscard]] constexpr std::size_t first_non_finite() const noexcept {
        for (std::size_t i = 0; i < n_; ++i) {
            for (std::size_t c = 0; c < motor_size; ++c)
                if (!is_finite(g_[c][i])) return i;
            for (std::size_t c = 0; c < screw_size; ++c)
                if (!is_finite(s_[c][i])) return i;
        }
        return n_;
    }

private:
    using flags = batch_detail::finiteness_flags<T>;
    using renormalizer = batch_detail::renormalizer<motor_type, Renormalization>;

    // The step runs over blocks of this many bodies, in four loops each: advance (the RK4
    // stages, leaving the unnormalised motors in g_), then the three stages of the
    // renormalisation (measure, root, apply; batch_detail::renormalizer), the intermediate
    // numbers in two arrays of a block's length. Each loop's body is then short enough for the
    // processor to overlap many iterations: the renormalisation is a chain of about 40
    // dependent operations (max, division, the Newton steps of the root, division), which in
    // one loop with the stages (~1,000 operations per body) overlapped nothing and took 45% of
    // the step. A block's motors (8 × 256 numbers) stay in the L1 cache between the loops.
    static constexpr std::size_t block = 256;

    // RK4 for bodies [first, last): rk4::step (methods.hpp) with the model's rates written out:
    // rates(model, x) is {motor_rate(g, s), acceleration(g, s)}, shifted(x, c, k) is
    // {g + c k.g, s + c k.s}. Stores the velocities and the unnormalised motors; returns the
    // velocities' finiteness flags.
    CTGA_ALWAYS_INLINE constexpr typename flags::word advance(std::size_t first, std::size_t last, const T h) noexcept {
        const body_type body = body_;  // a loop invariant, visibly not aliased by the stores
        const T h2 = h / T(2);
        const T w = h / T(6);
        typename flags::word bad = 0;
        for (std::size_t i = first; i < last; ++i) {
            const motor_type g = load<motor_type>(g_, i, std::make_index_sequence<motor_size>{});
            const screw_type s = load<screw_type>(s_, i, std::make_index_sequence<screw_size>{});
            const motor_type k1g(body_motor_rate<S, T>(g, s));
            const screw_type k1s(body_acceleration<S, K, T>(body, s));
            const motor_type g2(g + h2 * k1g);
            const screw_type s2(s + h2 * k1s);
            const motor_type k2g(body_motor_rate<S, T>(g2, s2));
            const screw_type k2s(body_acceleration<S, K, T>(body, s2));
            const motor_type g3(g + h2 * k2g);
            const screw_type s3(s + h2 * k2s);
            const motor_type k3g(body_motor_rate<S, T>(g3, s3));
            const screw_type k3s(body_acceleration<S, K, T>(body, s3));
            const motor_type g4(g + h * k3g);
            const screw_type s4(s + h * k3s);
            const motor_type k4g(body_motor_rate<S, T>(g4, s4));
            const screw_type k4s(body_acceleration<S, K, T>(body, s4));
            const motor_type y(g + w * (k1g + T(2) * (k2g + k3g) + k4g));
            const screw_type v(s + w * (k1s + T(2) * (k2s + k3s) + k4s));
            batch_detail::static_for<motor_size>([&](auto c) { g_[c][i] = y[c]; });
            batch_detail::static_for<screw_size>([&](auto c) {
                s_[c][i] = v[c];
                bad |= flags::of(v[c]);
            });
        }
        return bad;
    }

    // Renormalisation, stage 1 for bodies [first, last): the scale and n² of each motor.
    CTGA_ALWAYS_INLINE constexpr void measure(std::size_t first, std::size_t last, std::array<T, block>& scale,
                                              std::array<T, block>& n2) noexcept {
        for (std::size_t i = first; i < last; ++i) {
            const motor_type y = load<motor_type>(g_, i, std::make_index_sequence<motor_size>{});
            std::array<T, 8> x = renormalizer::unpack(y);
            n2[i - first] = renormalizer::measure(x, scale[i - first]);
            if constexpr (Renormalization == batch_renormalization::exact) {  // α/m
                motor_type out = y;
                renormalizer::pack(x, out);
                batch_detail::static_for<motor_size>([&](auto c) {
                    if constexpr (renormalizer::alpha_slot[c]) g_[c][i] = out[c];
                });
            }
        }
    }

    // Renormalisation, stage 3: the motors of bodies [first, last) renormalised in place;
    // returns their finiteness flags.
    CTGA_ALWAYS_INLINE constexpr typename flags::word apply(std::size_t first, std::size_t last,
                                                            const std::array<T, block>& scale,
                                                            const std::array<T, block>& root) noexcept {
        typename flags::word bad = 0;
        for (std::size_t i = first; i < last; ++i) {
            motor_type g = load<motor_type>(g_, i, std::make_index_sequence<motor_size>{});
            std::array<T, 8> x = renormalizer::unpack(g);
            renormalizer::apply(x, scale[i - first], root[i - first]);
            renormalizer::pack(x, g);
            batch_detail::static_for<motor_size>([&](auto c) {
                g_[c][i] = g[c];
                bad |= flags::of(g[c]);
            });
        }
        return bad;
    }

    template <class X, std::size_t N, std::size_t... C>
    [[nodiscard]] CTGA_ALWAYS_INLINE static constexpr X load(const std::array<std::array<T, Capacity>, N>& a,
                                                             std::size_t i, std::index_sequence<C...>) noexcept {
        return X{a[C][i]...};
    }
    constexpr void store(std::size_t i, const motor_type& g, const screw_type& s) noexcept {
        for (std::size_t c = 0; c < motor_size; ++c) g_[c][i] = g[c];
        for (std::size_t c = 0; c < screw_size; ++c) s_[c][i] = s[c];
    }

    body_type body_{};
    std::size_t n_ = 0;
    alignas(64) std::array<std::array<T, Capacity>, motor_size> g_{};  // g_[c][i]: component c of body i
    alignas(64) std::array<std::array<T, Capacity>, screw_size> s_{};
};

// The array-of-structures reference: ctga::rk4{}.step(model, x, h) for each of the first
// `count` states (all of them by default), each state stored as one motion_state. Returns
// non_finite for a non-finite h (nothing stepped) or when some new state is not finite
// (model.finite, as integrate checks), else none.
template <motion_model M, std::size_t N>
constexpr error_code aos_step_rk4(const M& model, std::array<state_of<M>, N>& states,
                                   const typename M::scalar_type& step, std::size_t count = N) noexcept {
    const typename M::scalar_type h = step;
    if (!is_finite(h)) return error_code::non_finite;
    bool finite = true;
    for (std::size_t i = 0; i < count && i < N; ++i) {
        const checked<state_of<M>> next = rk4{}.step(model, states[i], h);
        states[i] = next.value;
        finite = model.finite(next.value.g, next.value.s) && finite;
    }
    return finite ? error_code::none : error_code::non_finite;
}

}  // namespace ctga
