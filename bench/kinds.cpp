// body_step/*: one RK4 step of one body of each kind (ctga::rk4{} on body_motion, body frame),
// the benchmark beside tests/body_kinds_test.cpp's cost_of figures: a step evaluates the rates
// four times, so its time should follow body_step_cost's order (general > diagonal > sphere >
// planar; gravity above free). Each kernel is a non-inlined function stepping one of 64 random
// states, cycling, so nothing folds.
#include <array>
#include <cmath>
#include <random>

#include <benchmark/benchmark.h>

#include <ctga/ctga.hpp>

namespace {

namespace sub = ctga::subspace;
namespace kind = ctga::inertia_kind;
using ctga::wrench_model::uniform_field;

template <class S>
using state_t = ctga::motion_state<typename S::template motor_type<double>, typename S::template screw_type<double>>;

template <class S>
std::array<state_t<S>, 64> random_states() {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::array<state_t<S>, 64> out{};
    for (auto& x : out) {
        const double ax = std::is_same_v<S, sub::planar> ? 0 : u(rng), ay = std::is_same_v<S, sub::planar> ? 0 : u(rng), az = 1;
        const double n = std::sqrt(ax * ax + ay * ay + az * az);
        const ctga::motor<double> g = ctga::rigid_motion(ctga::make_translator(u(rng), u(rng), std::is_same_v<S, sub::planar> ? 0 : u(rng)),
                                                       ctga::make_rotor(3 * u(rng), ax / n, ay / n, az / n));
        x = {ctga::project<typename S::template motor_type<double>>(g),
             ctga::project<typename S::template screw_type<double>>(ctga::screw<double>{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)})};
    }
    return out;
}

template <class Model>
[[gnu::noinline]] state_t<typename Model::subspace_type> one_step(const Model& model, const state_t<typename Model::subspace_type>& x) {
    return ctga::rk4{}.step(model, x, 1e-3).value;
}

template <class Model>
void body_step(benchmark::State& state, const Model& model) {
    const auto inputs = random_states<typename Model::subspace_type>();
    std::size_t i = 0;
    for (auto _ : state) {
        auto y = one_step(model, inputs[i++ & 63]);
        benchmark::DoNotOptimize(y);
    }
}

const kind::diagonal::data<double> box{2.0, 2.0, 2.5, 3.0};
const ctga::vec3<double> gravity{0.3, -9.81, 0};

const auto general = ctga::body_motion<double, sub::full, kind::general>{
    ctga::make_rigid_body(*ctga::make_principal_mass_properties(2.0, 2.0, 2.5, 3.0))};
const auto diagonal = ctga::body_motion<double, sub::full, kind::diagonal>{box};
const auto sphere = ctga::body_motion<double, sub::full, kind::sphere>{{2.0, 2.0}};
const auto planar = ctga::body_motion<double, sub::planar, kind::diagonal>{box};
const auto diagonal_gravity =
    ctga::body_motion<double, sub::full, kind::diagonal, uniform_field<double, sub::full>>{box, ctga::weight<sub::full>(2.0, gravity)};
const auto planar_gravity = ctga::body_motion<double, sub::planar, kind::diagonal, uniform_field<double, sub::planar>>{
    box, ctga::weight<sub::planar>(2.0, gravity)};

BENCHMARK_CAPTURE(body_step, full_general, general);
BENCHMARK_CAPTURE(body_step, full_diagonal, diagonal);
BENCHMARK_CAPTURE(body_step, full_sphere, sphere);
BENCHMARK_CAPTURE(body_step, planar_diagonal, planar);
BENCHMARK_CAPTURE(body_step, full_diagonal_gravity, diagonal_gravity);
BENCHMARK_CAPTURE(body_step, planar_diagonal_gravity, planar_gravity);

}  // namespace
