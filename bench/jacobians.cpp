// <jacobian>/<method>: a Jacobian three ways, timed, with its error against a reference.
//
//   eom_jacobian                  ∂ṡ/∂s of the equations of motion ṡ = E ∨ (M ∧ (W − {s, A ∨ (N ∧ s)}))
//                                 (ctga::motion_rate; 6 × 6)
//   inertia_transform_jacobian    ∂N'/∂g of the moved inertia N' = (g ḡ) N (g ḡ)* (§5) with respect to
//                                 the motor's eight numbers (N' canonical blades × 8)
//
//   /ctga    ctga::jacobian: the exact derivative, straight-line code from the normal form
//   /dual    the same formula run once on forward-mode dual numbers (tests/support/dual.hpp)
//   /fd      central finite differences of the formula, h = 1e-6 (relative to the input)
//
// Each benchmark reports max_error: max |J − J_ref| / max |J_ref| over its 64 inputs, J_ref the
// dual-number Jacobian in long double (independent of ctga's differentiation, 64-bit mantissa).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <random>
#include <tuple>
#include <utility>

#include <benchmark/benchmark.h>

#include <ctga/ctga.hpp>
#include <ctga/operations/jacobian.hpp>

#include "support/dual.hpp"

namespace {

using namespace ctga;

// ---- the two formulas and their inputs ------------------------------------------------------

// (g ḡ) N (g ḡ)*: the inertia moved by the motor g (§5), g as eight free numbers.
constexpr auto moved_inertia = formula([](auto g, auto N) {
    const auto x = lift(g);
    const auto gg = x * bar(x);
    return gg * N * conj(gg);
});

struct eom_input {
    body_inertia<double> N;
    mobility<double> M;
    screw<double> s;
    wrench<double> W;
};
struct transform_input {
    motor<double> g;
    body_inertia<double> N;
};

mass_properties<double> random_body(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const double a = 1.0 + 0.2 * u(rng), b = 1.4 + 0.2 * u(rng), d = 1.9 + 0.2 * u(rng);
    const double xy = 0.1 * u(rng), xz = 0.1 * u(rng), yz = 0.1 * u(rng);
    return *make_mass_properties(1.5 + u(rng), vec3<double>{0.3 * u(rng), 0.3 * u(rng), 0.3 * u(rng)},
                                 mat3<double>{{{a, xy, xz}, {xy, b, yz}, {xz, yz, d}}});
}
template <class X>
X random_multivector(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    X x;
    for (std::size_t i = 0; i < X::size(); ++i) x[i] = u(rng);
    return x;
}

const std::array<eom_input, 64>& eom_inputs() {
    static const auto in = [] {
        std::mt19937_64 rng(16);
        std::array<eom_input, 64> out{};
        for (auto& x : out) {
            const auto b = random_body(rng);
            x = {body_inertia_of(b), mobility_of(b), random_multivector<screw<double>>(rng),
                 random_multivector<wrench<double>>(rng)};
        }
        return out;
    }();
    return in;
}
const std::array<transform_input, 64>& transform_inputs() {
    static const auto in = [] {
        std::mt19937_64 rng(61);
        std::array<transform_input, 64> out{};
        for (auto& x : out)
            x = {exp(random_multivector<screw<double>>(rng)), body_inertia_of(random_body(rng))};
        return out;
    }();
    return in;
}

// ---- the three methods, as dense row-major Jacobians ----------------------------------------

template <std::size_t R, std::size_t C, class T = double>
using dense = std::array<std::array<T, C>, R>;

// the formula's value type for the rows: its canonical layout, in scalar type T
template <class F, class T, class... Args>
using value_of = multivector<typename decltype(std::declval<F>()(std::declval<Args>()...))::algebra_type, T,
                             decltype(std::declval<F>()(std::declval<Args>()...))::layout>;

// argument x with the components (or parameters) seeded as dual-number variables when Seed
template <std::size_t N, class T, bool Seed, class X>
auto as_dual(const X& x) {
    using D = ctga_test::dual<N, T>;
    if constexpr (multivector_type<X>) {
        multivector<typename X::algebra_type, D, X::layout> out;
        for (std::size_t i = 0; i < X::size(); ++i) out[i] = Seed ? D::variable(T(x[i]), i) : D(T(x[i]));
        return out;
    } else {  // body_inertia<double>
        body_inertia<D> out;
        const auto from = x.parameters();
        const auto to = out.parameters();
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            ((const_cast<typename body_inertia<D>::scalar&>(std::get<I>(to))[0] =
                  Seed ? D::variable(T(std::get<I>(from)[0]), I) : D(T(std::get<I>(from)[0]))),
             ...);
        }(std::make_index_sequence<10>{});
        return out;
    }
}

// ∂f/∂args[K] by dual numbers in scalar type T
template <std::size_t K, std::size_t Cols, class T, class F, class... Args>
auto by_dual(const F& f, const Args&... args) {
    const auto duals = [&]<std::size_t... I>(std::index_sequence<I...>) {
        return std::make_tuple(as_dual<Cols, T, I == K>(args)...);
    }(std::index_sequence_for<Args...>{});
    using V = value_of<F, ctga_test::dual<Cols, T>, const decltype(as_dual<Cols, T, false>(args))&...>;
    const V value = std::apply([&](const auto&... a) { return V(f(a...)); }, duals);
    dense<V::size(), Cols, T> out{};
    for (std::size_t r = 0; r < V::size(); ++r)
        for (std::size_t c = 0; c < Cols; ++c) out[r][c] = value[r].d[c];
    return out;
}

// ∂f/∂args[K] by central differences (argument K a multivector)
template <std::size_t K, class F, class... Args>
auto by_differences(const F& f, const Args&... args) {
    using V = value_of<F, double, const Args&...>;
    using A = std::remove_cvref_t<std::tuple_element_t<K, std::tuple<Args...>>>;
    dense<V::size(), A::size()> out{};
    for (std::size_t c = 0; c < A::size(); ++c) {
        auto up = std::make_tuple(args...), down = std::make_tuple(args...);
        const double x = std::get<K>(up)[c], h = 1e-6 * std::max(1.0, std::abs(x));
        std::get<K>(up)[c] = x + h;
        std::get<K>(down)[c] = x - h;
        const V fu = std::apply([&](const auto&... a) { return V(f(a...)); }, up);
        const V fd = std::apply([&](const auto&... a) { return V(f(a...)); }, down);
        for (std::size_t r = 0; r < V::size(); ++r) out[r][c] = (fu[r] - fd[r]) / (2 * h);
    }
    return out;
}

// ---- the kernels (not inlined: one call each, as the benchmark measures) ---------------------

[[gnu::noinline]] auto eom_ctga(const eom_input& in) {
    return jacobian<2>(motion_rate, in.N, in.M, in.s, in.W).dense();
}
[[gnu::noinline]] auto eom_dual(const eom_input& in) { return by_dual<2, 6, double>(motion_rate, in.N, in.M, in.s, in.W); }
[[gnu::noinline]] auto eom_fd(const eom_input& in) { return by_differences<2>(motion_rate, in.N, in.M, in.s, in.W); }
auto eom_reference(const eom_input& in) { return by_dual<2, 6, long double>(motion_rate, in.N, in.M, in.s, in.W); }

[[gnu::noinline]] auto transform_ctga(const transform_input& in) { return jacobian<0>(moved_inertia, in.g, in.N).dense(); }
[[gnu::noinline]] auto transform_dual(const transform_input& in) { return by_dual<0, 8, double>(moved_inertia, in.g, in.N); }
[[gnu::noinline]] auto transform_fd(const transform_input& in) { return by_differences<0>(moved_inertia, in.g, in.N); }
auto transform_reference(const transform_input& in) { return by_dual<0, 8, long double>(moved_inertia, in.g, in.N); }

// max |J − J_ref| / max |J_ref| over all inputs
template <class Inputs, class Kernel, class Reference>
double max_error(const Inputs& inputs, Kernel kernel, Reference reference) {
    double diff = 0, scale = 0;
    for (const auto& in : inputs) {
        const auto J = kernel(in);
        const auto R = reference(in);
        for (std::size_t r = 0; r < R.size(); ++r)
            for (std::size_t c = 0; c < R[r].size(); ++c) {
                diff = std::max(diff, static_cast<double>(std::abs(static_cast<long double>(J[r][c]) - R[r][c])));
                scale = std::max(scale, static_cast<double>(std::abs(R[r][c])));
            }
    }
    return scale > 0 ? diff / scale : diff;
}

template <class Inputs, class Kernel, class Reference>
void run(benchmark::State& state, const Inputs& inputs, Kernel kernel, Reference reference) {
    std::size_t i = 0;
    for (auto _ : state) {
        auto J = kernel(inputs[i++ & 63]);
        benchmark::DoNotOptimize(J);
    }
    state.counters["max_error"] = max_error(inputs, kernel, reference);
}

void eom_jacobian_ctga(benchmark::State& s) { run(s, eom_inputs(), eom_ctga, eom_reference); }
void eom_jacobian_dual(benchmark::State& s) { run(s, eom_inputs(), eom_dual, eom_reference); }
void eom_jacobian_fd(benchmark::State& s) { run(s, eom_inputs(), eom_fd, eom_reference); }
void transform_jacobian_ctga(benchmark::State& s) { run(s, transform_inputs(), transform_ctga, transform_reference); }
void transform_jacobian_dual(benchmark::State& s) { run(s, transform_inputs(), transform_dual, transform_reference); }
void transform_jacobian_fd(benchmark::State& s) { run(s, transform_inputs(), transform_fd, transform_reference); }

BENCHMARK(eom_jacobian_ctga)->Name("eom_jacobian/ctga");
BENCHMARK(eom_jacobian_dual)->Name("eom_jacobian/dual");
BENCHMARK(eom_jacobian_fd)->Name("eom_jacobian/fd");
BENCHMARK(transform_jacobian_ctga)->Name("inertia_transform_jacobian/ctga");
BENCHMARK(transform_jacobian_dual)->Name("inertia_transform_jacobian/dual");
BENCHMARK(transform_jacobian_fd)->Name("inertia_transform_jacobian/fd");

}  // namespace
