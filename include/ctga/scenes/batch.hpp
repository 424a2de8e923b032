// Many bodies of one kind, stepped together: structure-of-arrays storage, SIMD packs of bodies.
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
// (bodies of one kind with different masses or moments go in different batches), broadcast to
// every lane of a pack once per step (body_cast, body_kinds.hpp).
//
// step_rk4(h) is ctga::rk4{}.step (renormalisation included) with a pack of Lanes bodies as the
// scalar: the same mechanism as a batch of robots (chains/batch.hpp, support/pack.hpp). Bodies
// i … i + Lanes − 1 are one vector load per component (the arrays above), one instruction stream
// of rk4 on body_motion<pack<T, Lanes>, S, K>, one vector store per component. The Lanes default
// is the target's vector width (native_lanes: 2 doubles with SSE2, 4 with AVX, 8 with AVX-512).
// The last size() mod Lanes bodies, and every body in a constant expression, are stepped by the
// same loop with T itself as the scalar. Every lane does rk4's operations on its body in rk4's
// order, so each body gets ctga::rk4{}.step(model(), state(i), h)'s numbers bit for bit as long as
// the compiler contracts a·b + c into fused multiply-adds alike in both codes (it may not: GCC
// contracts by default when the target has FMA, e.g. -march=native; then they agree to rounding).
//
// This replaced loops over the bodies written for the compilers' auto-vectorisers (with their own
// branch-free renormalisation), which were slower or no faster: 10,000 bodies of
// inertia_kind::diagonal, million body-steps per second, packs against those loops (Zen 5, GCC 12
// and Clang 14 at -O3): full bodies 18.9 against 11.6 (GCC, SSE2), 82 against 15 (GCC,
// -march=native --param=sra-max-scalarization-size-Ospeed=4096, as batches of robots are built:
// without the parameter GCC leaves a pack's motors in memory, 66), 108 against 91 (Clang,
// -march=native); planar bodies 64 against 51, 307 against 313, 309 against 228. (The loops'
// optional renormalisation with one division per body, a few ulps off rk4's, was faster still
// for planar bodies, 445 and 376: it is not kept; every body gets rk4's numbers.)
//
// Failures. The loop adds x − x over every new number (0 when x is finite, NaN when not) and
// tests the sum once: step_rk4 returns error_code::non_finite when any body's new state has a
// NaN or an infinity (first_non_finite() finds the body). The step is not undone: bodies with
// finite states are stepped correctly, and a non-finite one stays so. A non-finite h is rejected
// before anything is stepped.
//
// aos_step_rk4 is the array-of-structures reference: ctga::rk4{}.step for each body of a
// std::array of motion_states (bench/batch.cpp times the two).
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include "ctga/integrators/methods.hpp"
#include "ctga/integrators/model.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/scenes/body_kinds.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/pack.hpp"

namespace ctga {

// N ≤ Capacity bodies of subspace S and inertia structure K with one set of mass properties,
// stored as structure of arrays and stepped Lanes at a time (see the top of this file).
template <class T, class S, class K, std::size_t Capacity, std::size_t Lanes = native_lanes<T>>
class batch {
    static_assert(Lanes >= 1 && (Lanes & (Lanes - 1)) == 0,
                  "ctga::batch: Lanes (bodies per instruction stream) is a power of two");

public:
    using scalar_type = T;
    using motor_type = typename S::template motor_type<T>;
    using screw_type = typename S::template screw_type<T>;
    using body_type = typename K::template data<T>;
    using model_type = body_motion<T, S, K>;
    using state_type = motion_state<motor_type, screw_type>;

    static constexpr std::size_t lanes = Lanes;
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
        set(n_++, g, s);
        return true;
    }
    constexpr bool add(const state_type& x) noexcept { return add(x.g, x.s); }

    // Body i's pose, velocity and state as ctga types (i < size()).
    [[nodiscard]] constexpr motor_type pose(std::size_t i) const noexcept { return load<T, motor_type>(g_, i); }
    [[nodiscard]] constexpr screw_type velocity(std::size_t i) const noexcept { return load<T, screw_type>(s_, i); }
    [[nodiscard]] constexpr state_type state(std::size_t i) const noexcept { return {pose(i), velocity(i)}; }
    constexpr void set(std::size_t i, const motor_type& g, const screw_type& s) noexcept {
        store(g_, i, g);
        store(s_, i, s);
    }

    // The contiguous array of motor (screw) component c over the bodies: c in the order of
    // motor_type's (screw_type's) blades, entries 0 … size() − 1 meaningful.
    [[nodiscard]] constexpr const T* motor_component(std::size_t c) const noexcept { return g_[c].data(); }
    [[nodiscard]] constexpr const T* screw_component(std::size_t c) const noexcept { return s_[c].data(); }

    // One classical RK4 step of size h for every body (see the top of this file): the results of
    // ctga::rk4{}.step(model(), state(i), h), renormalisation included. Returns non_finite,
    // having stepped nothing, for a non-finite h; and non_finite, after the step, when some
    // body's new state has a NaN or an infinity.
    constexpr error_code step_rk4(const T& step) noexcept {
        const T h = step;  // by value: a reference could point into the arrays the loop stores to
        if (!is_finite(h)) return error_code::non_finite;
        std::size_t packed = 0;  // bodies [0, packed) in packs of Lanes
        bool finite = true;
        if constexpr (Lanes > 1) {
            if (!std::is_constant_evaluated()) {
                packed = n_ - n_ % Lanes;
                finite = advance<pack<T, Lanes>>(0, packed, h);
            }
        }
        finite = advance<T>(packed, n_, h) && finite;
        return finite ? error_code::none : error_code::non_finite;
    }

    // The first body whose state has a NaN or an infinity, or size() when there is none.
    [[nodiscard]] constexpr std::size_t first_non_finite() const noexcept {
        for (std::size_t i = 0; i < n_; ++i)
            if (!model().finite(pose(i), velocity(i))) return i;
        return n_;
    }

private:
    template <class P>
    static constexpr std::size_t width = std::is_same_v<P, T> ? 1 : Lanes;

    // rk4 for bodies [first, last), width<P> at a time, with P as the scalar; true when every
    // new number is finite. Flattened: rk4's step and all it calls inlined into the loop (GCC
    // otherwise calls rk4::step, passing the packs through memory: full bodies 42 against 55
    // million body-steps per second in 8 lanes).
    template <class P>
    [[gnu::flatten]] constexpr bool advance(std::size_t first, std::size_t last, const T h) noexcept {
        using model_p = body_motion<P, S, K>;
        using motor_p = typename S::template motor_type<P>;
        using screw_p = typename S::template screw_type<P>;
        const model_p model{inertia_kind::body_cast<P>(body_)};
        const P step(h);
        P defect(T(0));  // Σ (x − x) over the new numbers: 0, or NaN once one is not finite
        for (std::size_t i = first; i < last; i += width<P>) {
            const state_of<model_p> x{load<P, motor_p>(g_, i), load<P, screw_p>(s_, i)};
            state_of<model_p> y = rk4{.renormalize = false}.step(model, x, step).value;
            y.g = renormalized<P>(y.g);
            store(g_, i, y.g);
            store(s_, i, y.s);
            for (std::size_t c = 0; c < motor_size; ++c) defect += y.g[c] - y.g[c];
            for (std::size_t c = 0; c < screw_size; ++c) defect += y.s[c] - y.s[c];
        }
        return integrator_detail::all_of(defect == defect);
    }

    // The model's renormalize (project ∘ renormalize ∘ motor, body_kinds.hpp), the same
    // operations, without renormalize's debug-build assertion: a motor that cannot be
    // renormalised (a NaN or ∞, a zero rotor part) becomes NaNs, which the step reports.
    template <class P, class M>
    [[nodiscard]] CTGA_ALWAYS_INLINE static constexpr M renormalized(const M& g) noexcept {
        if constexpr (lane_wise<P>) {
            return project<M>(renormalize(motor<P>(g)));  // (lane-wise: NaN lanes, no assertion)
        } else {
            const checked<motor<T>> r = renormalize_checked(motor<T>(g));
            motor<T> out = r.value;
            if (r.error != error_code::none)
                for (std::size_t c = 0; c < out.size(); ++c) out[c] = std::numeric_limits<T>::quiet_NaN();
            return project<M>(out);
        }
    }

    // Component c of bodies i … i + width<P> − 1 as one P: a vector load for a pack.
    template <class P>
    [[nodiscard]] CTGA_ALWAYS_INLINE static constexpr P lanes_at(const T* from) noexcept {
        if constexpr (std::is_same_v<P, T>) return *from;
        else return P::load(from);
    }
    template <class P, class X, std::size_t N>
    [[nodiscard]] CTGA_ALWAYS_INLINE static constexpr X load(const std::array<std::array<T, Capacity>, N>& a,
                                                             std::size_t i) noexcept {
        return [&]<std::size_t... C>(std::index_sequence<C...>) { return X{lanes_at<P>(&a[C][i])...}; }(
            std::make_index_sequence<N>{});
    }
    template <class X, std::size_t N>
    CTGA_ALWAYS_INLINE static constexpr void store(std::array<std::array<T, Capacity>, N>& a, std::size_t i,
                                                   const X& x) noexcept {
        for (std::size_t c = 0; c < N; ++c) {
            if constexpr (std::is_same_v<std::remove_cvref_t<decltype(x[c])>, T>) a[c][i] = x[c];
            else x[c].store(&a[c][i]);
        }
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
