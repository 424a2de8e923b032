// ctga as an embedded target would use it: float throughout, compiled with -fno-exceptions and
// -fno-rtti, and no heap. Every global operator new (plain, array, nothrow, aligned) is replaced
// by one that calls std::abort(), so a single allocation anywhere in the program (ctga, the
// standard library, this file) ends the run with SIGABRT instead of passing.
//
// It builds a checked rigid body from raw floats, integrates a free body and a body under a
// constant wrench for 10,000 steps with rk4, lie_rk4 and implicit_midpoint in both frames, and
// checks that
//   - every run completes and reports success, with the motor still unit to float rounding;
//   - the free body's kinetic energy is conserved to a float-sized relative error;
//   - under a wrench W constant in the fixed frame, the fixed-frame momentum obeys dP/dt = W
//     exactly, so P(t) = P(0) + t W (the wrench functor converts W to the body frame for the
//     body-frame model);
//   - NaN inputs (an initial velocity, the step size, the mass) are reported as
//     error_code::non_finite.
// It also runs a 7-dof arm's RNEA and ABA in float (ABA ∘ RNEA = identity to float rounding), simulates
// it for 2000 rk4 steps, checks NaN input is reported, and computes a three-body chain's mass
// matrix in one constant expression, static_asserted symmetric.
// Exit status 0 when every check passes, 1 otherwise. `ctga_embedded --allocate` performs one
// allocation on purpose, to show that the replacement operator new is in effect (it aborts).
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>

#include <ctga/ctga.hpp>

// ---- no heap: every replaceable allocation function aborts ----------------------------------

void* operator new(std::size_t) { std::abort(); }
void* operator new[](std::size_t) { std::abort(); }
void* operator new(std::size_t, const std::nothrow_t&) noexcept { std::abort(); }
void* operator new[](std::size_t, const std::nothrow_t&) noexcept { std::abort(); }
void* operator new(std::size_t, std::align_val_t) { std::abort(); }
void* operator new[](std::size_t, std::align_val_t) { std::abort(); }
void* operator new(std::size_t, std::align_val_t, const std::nothrow_t&) noexcept { std::abort(); }
void* operator new[](std::size_t, std::align_val_t, const std::nothrow_t&) noexcept { std::abort(); }

// Nothing can have been allocated, so deleting anything but a null pointer is an error too.
namespace {
void release(void* p) noexcept {
    if (p != nullptr) std::abort();
}
}  // namespace
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete(void* p, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { release(p); }

#if defined(__cpp_exceptions) || defined(__EXCEPTIONS) || defined(__cpp_rtti) || defined(__GXX_RTTI)
#error "ctga_embedded must be compiled with -fno-exceptions -fno-rtti"
#endif

namespace {

using namespace ctga;
using F = float;

// Bounds, about 10x what was measured at h = 1e-3 over 10,000 steps (g++ 12 at -O2 and -O3,
// x86-64; the same numbers at both). RK4's truncation error is ~1e-14 here (the same program
// in double: energy errors <= 2e-14), so these are float rounding.
//   free-body relative energy error   body frame 2.5e-6 ... 2.6e-6, fixed frame 1.4e-5 (rk4),
//                                     5.2e-5 (lie_rk4, implicit_midpoint); probably the
//                                     fixed-frame velocity of a body 2.3 from the origin,
//                                     which carries omega x t and loses digits to it
//   |P(T) - P(0) - T W| (relative)    <= 5.2e-5 (the midpoint's truncation error: 2e-7)
//   unit defect of the final motor    rk4 (renormalised each step): 1.5e-8 to 2.4e-7 (two
//                                     float eps, since the acceleration solves in coordinates:
//                                     the residue of the last renormalisation, so the bound is
//                                     four eps, not ten times a lucky rounding); lie_rk4 and
//                                     implicit_midpoint (moved by exp only, never
//                                     renormalised): 5.8e-4, a linear drift of about eps/2
//                                     per step: |exp(z)|^2 - 1 = -eps/2 for this step's
//                                     z (cos(phi) near 1 rounds the same way every step),
//                                     so the defect adds up instead of random-walking
constexpr F energy_bound_body = 2.5e-5F;
constexpr F energy_bound_fixed = 5e-4F;
constexpr F momentum_bound = 5e-4F;
constexpr F unit_bound_renormalised = 4 * std::numeric_limits<F>::epsilon();  // 4.8e-7
constexpr F unit_bound_exp_only = 6e-3F;

constexpr F h = 1e-3F;
constexpr long long steps = 10'000;

int failures = 0;
int checks = 0;

void check(bool ok, const char* what) {
    ++checks;
    if (!ok) {
        ++failures;
        std::printf("FAILED: %s\n", what);
    }
}

F abs_of(F x) { return x < F(0) ? -x : x; }

template <class V>
F max_norm(const V& v, std::size_t n) {
    F out = F(0);
    for (std::size_t i = 0; i < n; ++i) out = abs_of(v[i]) > out ? abs_of(v[i]) : out;
    return out;
}

// A wrench constant in the fixed frame, in the model's types: as given for a fixed-frame model,
// moved into the body frame (W_b = the co-adjoint action of g⁻¹) for a body-frame one.
template <frame Frame>
struct constant_space_wrench {
    wrench<F> W;
    constexpr wrench<F> operator()(const motor<F>& g, const screw<F>& /*s*/) const noexcept {
        if constexpr (Frame == frame::fixed) return W;
        else return transform(inverse(map_of(g)), W);
    }
};

// The body-frame velocity of a state of either frame.
template <frame Frame>
screw<F> body_velocity(const motor<F>& g, const screw<F>& s) {
    if constexpr (Frame == frame::body) return s;
    else return transform(inverse(map_of(g)), s);
}

// The fixed-frame momentum of a state of either frame: the body-frame momentum moved out by g.
template <frame Frame>
coscrew<F> space_momentum(const rigid_body<F>& b, const motor<F>& g, const screw<F>& s) {
    return transform(map_of(g), momentum(b.N, body_velocity<Frame>(g, s)));
}

F unit_error(const motor<F>& g) {
    const motor_defect<F> d = unit_defect(g);
    return abs_of(d.alpha_norm) > abs_of(d.alpha_beta) ? abs_of(d.alpha_norm) : abs_of(d.alpha_beta);
}

template <frame Frame, class Method>
void run_free_and_forced(const char* name, const Method& method, F unit_bound, const rigid_body<F>& b,
                         const motor<F>& g0, const screw<F>& s_body0, F& worst_energy) {
    const char* frame_name = Frame == frame::body ? "body" : "fixed";
    const screw<F> s0 = Frame == frame::body ? s_body0 : transform(map_of(g0), s_body0);

    // free body: energy
    const rigid_body_motion<F, Frame> free_model{b};
    const auto free_run = integrate(method, free_model, {g0, s0}, h, steps);
    const F E0 = kinetic_energy(b.N, s_body0);
    const F E1 = kinetic_energy(b.N, body_velocity<Frame>(free_run.state.g, free_run.state.s));
    const F energy_error = abs_of(E1 - E0) / E0;
    if (energy_error > worst_energy) worst_energy = energy_error;
    check(static_cast<bool>(free_run) && free_run.steps == steps, "free run completes");
    check(energy_error <= (Frame == frame::body ? energy_bound_body : energy_bound_fixed), "free-body energy conserved");
    check(unit_error(free_run.state.g) <= unit_bound, "free-body motor unit");

    // constant fixed-frame wrench: P(T) = P(0) + T W
    const wrench<F> W{F(0.05), F(-0.1), F(0.02), F(0.03), F(0), F(-0.02)};
    const rigid_body_motion<F, Frame, constant_space_wrench<Frame>> forced_model{b, {W}};
    const auto forced_run = integrate(method, forced_model, {g0, s0}, h, steps);
    const F T = h * static_cast<F>(steps);
    const coscrew<F> P0 = space_momentum<Frame>(b, g0, s0);
    const coscrew<F> P1 = space_momentum<Frame>(b, forced_run.state.g, forced_run.state.s);
    const coscrew<F> residual(P1 - P0 - T * W);
    const F momentum_error = max_norm(residual, 6) / (max_norm(P0, 6) + T * max_norm(W, 6));
    check(static_cast<bool>(forced_run) && forced_run.steps == steps, "forced run completes");
    check(momentum_error <= momentum_bound, "forced body: P(T) = P(0) + T W");
    check(unit_error(forced_run.state.g) <= unit_bound, "forced-body motor unit");

    std::printf("%-17s %-5s  %-4s  %9.2e  %9.2e  %9.2e   %-4s  %9.2e\n", name, frame_name,
                free_run ? "ok" : describe(free_run.error), static_cast<double>(energy_error),
                static_cast<double>(unit_error(free_run.state.g)), static_cast<double>(E1),
                forced_run ? "ok" : describe(forced_run.error), static_cast<double>(momentum_error));
}

template <class Method>
void run_both_frames(const char* name, const Method& method, F unit_bound, const rigid_body<F>& b, const motor<F>& g0,
                     const screw<F>& s_body0, F& worst_energy) {
    run_free_and_forced<frame::body>(name, method, unit_bound, b, g0, s_body0, worst_energy);
    run_free_and_forced<frame::fixed>(name, method, unit_bound, b, g0, s_body0, worst_energy);
}

// ---- kinematic trees ----------------------------------------------------------------------

// A 7-dof arm (revolute about z, y, z, y, z, y, z; frames 0.3 m apart) with masses 2 … 0.8 kg.
using arm7 = chains::tree<chains::link<-1, chains::revolute_z>, chains::link<0, chains::revolute_y>,
                          chains::link<1, chains::revolute_z>, chains::link<2, chains::revolute_y>,
                          chains::link<3, chains::revolute_z>, chains::link<4, chains::revolute_y>,
                          chains::link<5, chains::revolute_z>>;
template <class Tree, class T>
constexpr checked<chains::model<Tree, T>> make_chain() noexcept {
    chains::model<Tree, T> m;
    error_code e = error_code::none;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ([&] {
            const auto link = chains::make_link<typename Tree::template joint_at<I>>(
                rigid_motion(make_translator(T(0), T(0), I == 0 ? T(0) : T(0.3)), make_rotor(T(0.1) * T(I), T(1), T(0), T(0))),
                make_mass_properties(T(2) - T(0.2) * T(I), vec3<T>{T(0.01), T(0), T(0.15)},
                                     mat3<T>{{{T(0.02), T(0.001), T(0)}, {T(0.001), T(0.022), T(0)}, {T(0), T(0), T(0.006)}}}));
            if (!link) e = link.error;
            else m.template link<I>() = *link;
        }(), ...);
    }(std::make_index_sequence<Tree::size>{});
    return {m, e};
}

// A three-body chain's mass matrix computed by the compiler: one constant expression builds the
// checked model and runs the composite rigid body algorithm, and the result is static_asserted
// symmetric with a positive diagonal.
using chain3 = chains::tree<chains::link<-1, chains::revolute_z>, chains::link<0, chains::revolute_y>,
                            chains::link<1, chains::prismatic_x>>;
constexpr chains::joint_matrix<chain3, double> chain3_mass_matrix = [] {
    const auto m = make_chain<chain3, double>();
    return chains::crba(*m, chains::configuration<chain3, double>{0.4, -0.7, 0.2});
}();
static_assert(chain3_mass_matrix[0][1] == chain3_mass_matrix[1][0] && chain3_mass_matrix[0][2] == chain3_mass_matrix[2][0] &&
                  chain3_mass_matrix[1][2] == chain3_mass_matrix[2][1],
              "the mass matrix is symmetric");
static_assert(chain3_mass_matrix[0][0] > 0 && chain3_mass_matrix[1][1] > 0 && chain3_mass_matrix[2][2] > 0,
              "the mass matrix has a positive diagonal");

// RNEA then ABA of the arm in float: ABA(q, q̇, RNEA(q, q̇, q̈)) = q̈ to float rounding, the mass
// matrix symmetric, an unactuated arm simulated with rk4 keeps its energy, NaN input reported.
void run_arm(F& roundtrip_error, F& energy_error) {
    const auto made = make_chain<arm7, F>();
    check(static_cast<bool>(made), "the arm's links are valid");
    if (!made) return;
    const chains::model<arm7, F>& m = *made;
    chains::configuration<arm7, F> q{};
    chains::joint_vector<arm7, F> qd{}, qdd{};
    for (std::size_t i = 0; i < 7; ++i) {
        q[i] = F(0.3) * F(i) - F(1);
        qd[i] = F(0.5) - F(0.1) * F(i);
        qdd[i] = F(1) - F(0.25) * F(i);
    }
    const auto tau = chains::checked_call(chains::rnea, m, q, qd, qdd);
    check(static_cast<bool>(tau), "RNEA of the arm in float");
    const auto back = chains::checked_call(chains::aba, m, q, qd, *tau);
    check(static_cast<bool>(back), "ABA of the arm in float");
    roundtrip_error = F(0);
    for (std::size_t i = 0; i < 7; ++i) {
        const F d = back.value[i] - qdd[i];
        roundtrip_error = d > roundtrip_error ? d : -d > roundtrip_error ? -d : roundtrip_error;
    }
    check(roundtrip_error <= F(1e-3), "ABA(RNEA(q, q̇, q̈)) = q̈ in float");
    const auto H = chains::crba(m, q);
    bool symmetric = true;
    for (std::size_t r = 0; r < 7; ++r)
        for (std::size_t c = 0; c < 7; ++c) symmetric = symmetric && H[r][c] == H[c][r];
    check(symmetric, "the arm's mass matrix is symmetric");
    // 2 s of an unactuated arm under gravity
    const chains::tree_motion<arm7, F> sim{m};
    const motion_state<chains::coordinates<7, F>, chains::coordinates<7, F>> x0{{q}, {qd}};
    const F E0 = sim.energy(x0.g, x0.s);
    const auto run = integrate(rk4{}, sim, x0, F(1e-3), 2000);
    check(static_cast<bool>(run) && run.steps == 2000, "the arm simulates in float");
    const F dE = sim.energy(run.state.g, run.state.s) - E0;
    energy_error = (dE < F(0) ? -dE : dE) / (E0 < F(0) ? -E0 : E0);
    check(energy_error <= F(1e-3), "the unactuated arm keeps its energy in float");
    auto q_nan = q;
    q_nan[2] = std::numeric_limits<F>::quiet_NaN();
    check(chains::checked_call(chains::aba, m, q_nan, qd, *tau).error == error_code::non_finite, "NaN q reported by ABA");
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1 && std::strcmp(argv[1], "--allocate") == 0) {
        std::puts("allocating one byte: the replacement operator new aborts");
        std::fflush(stdout);
        void* volatile p = ::operator new(1);
        return p != nullptr ? 2 : 3;  // not reached
    }

    // mass 2, centre of mass off the body origin, an inertia tensor with products of inertia
    const auto made = make_rigid_body(F(2), vec3<F>{F(0.1), F(-0.2), F(0.3)},
                                      mat3<F>{{{F(2), F(0.1), F(0)}, {F(0.1), F(2.5), F(-0.05)}, {F(0), F(-0.05), F(3)}}});
    check(static_cast<bool>(made), "make_rigid_body accepts a valid body");
    if (!made) {
        std::printf("make_rigid_body: %s\n", describe(made.error));
        return 1;
    }
    const rigid_body<F> b = *made;
    const motor<F> g0 = rigid_motion(make_translator(F(0.5), F(-1), F(2)),
                                     make_rotor(F(0.7), F(1) / F(3), F(2) / F(3), F(2) / F(3)));
    const screw<F> s_body0{F(0.3), F(1), F(-0.4), F(0.2), F(-0.1), F(0.5)};

    std::printf("ctga embedded: float, -fno-exceptions -fno-rtti, operator new aborts; h = %g, %lld steps\n",
                static_cast<double>(h), steps);
    std::printf("%-17s %-5s  %-4s  %9s  %9s  %9s   %-4s  %9s\n", "method", "frame", "free", "dE/E", "unit", "E(T)",
                "wrch", "dP rel");
    F worst_energy = F(0);
    run_both_frames("rk4", rk4{}, unit_bound_renormalised, b, g0, s_body0, worst_energy);
    run_both_frames("lie_rk4", lie_rk4{}, unit_bound_exp_only, b, g0, s_body0, worst_energy);
    run_both_frames("implicit_midpoint", implicit_midpoint{}, unit_bound_exp_only, b, g0, s_body0, worst_energy);

    // NaN inputs are reported, not integrated
    const F nan = std::numeric_limits<F>::quiet_NaN();
    const rigid_body_motion<F, frame::body> model{b};
    const auto nan_velocity = integrate(rk4{}, model, {g0, screw<F>{F(0.3), nan, F(0), F(0), F(0), F(0)}}, h, steps);
    check(nan_velocity.error == error_code::non_finite && nan_velocity.steps == 0, "NaN velocity reported");
    const auto nan_step = integrate(lie_rk4{}, model, {g0, s_body0}, nan, steps);
    check(nan_step.error == error_code::non_finite && nan_step.steps == 0, "NaN step size reported");
    const auto nan_mass = make_rigid_body(nan, vec3<F>{}, mat3<F>{{{F(1), F(0), F(0)}, {F(0), F(2), F(0)}, {F(0), F(0), F(3)}}});
    check(nan_mass.error == error_code::non_finite, "NaN mass reported");
    std::printf("NaN velocity: %s; NaN step: %s; NaN mass: %s\n", describe(nan_velocity.error),
                describe(nan_step.error), describe(nan_mass.error));

    // a scene step: a planar puck under gravity hanging from the world by a spring, a box joined
    // to it by a spring–damper, and a static post, stepped together in float
    {
        using planar = subspace::planar;
        using puck = body_motion<F, planar, inertia_kind::sphere, wrench_model::uniform_field<F, planar>>;
        using box = body_motion<F, subspace::full, inertia_kind::diagonal>;
        const vec3<F> gravity{F(0), F(-9.81), F(0)};
        const auto world = make_scene(couple(spring_damper<0, ctga::world, F>{{F(0), F(0.1), F(0)}, {}, F(200), F(0.2)},
                                             spring_damper<0, 1, F>{{F(0), F(-0.1), F(0)}, {F(0.2), F(0), F(0)}, F(100), F(0.5)}),
                                      puck{{F(0.5), F(0.01)}, weight<planar>(F(0.5), gravity)},
                                      box{{F(1), F(0.02), F(0.03), F(0.04)}}, static_body<F>{g0});
        const auto x0 = world.initial_state(
            motion_state<puck::motor_type, puck::screw_type>{project<puck::motor_type>(motor<F>(make_translator(F(0.2), F(-0.3), F(0)))),
                                                             puck::screw_type{F(1), F(0), F(0)}},
            motion_state<motor<F>, screw<F>>{motor<F>(make_translator(F(0.5), F(-0.6), F(0.1))), s_body0});
        const auto run = integrate(rk4{}, world.model(), x0, h, steps);
        check(static_cast<bool>(run) && run.steps == steps, "a scene of a planar puck, a box and a static post steps");
        const motor_map<F> puck_at = map_of(motor<F>(part<0>(run.state.g)));
        // the puck stays in its plane exactly, and near its anchor (the springs hold it)
        check(puck_at.t[2] == F(0) && puck_at.t[0] * puck_at.t[0] + puck_at.t[1] * puck_at.t[1] < F(1),
              "the puck stays in its plane, held by its springs");
        std::printf("scene (float, rk4, %lld steps): %s; puck at (%.3f, %.3f, %.3f)\n", steps, describe(run.error),
                    static_cast<double>(puck_at.t[0]), static_cast<double>(puck_at.t[1]), static_cast<double>(puck_at.t[2]));
    }

    // a 7-dof arm in float
    {
        F roundtrip = F(0), energy = F(0);
        run_arm(roundtrip, energy);
        std::printf("7-dof arm (float): |ABA(RNEA(q̈)) - q̈| = %.2e, rk4 2000 steps |dE/E| = %.2e; constexpr 3-body H(0,1) = %g\n",
                    static_cast<double>(roundtrip), static_cast<double>(energy), chain3_mass_matrix[0][1]);
    }

    std::printf("worst free-body relative energy error %.2e (bounds %.1e body, %.1e fixed); %d/%d checks passed%s\n",
                static_cast<double>(worst_energy), static_cast<double>(energy_bound_body),
                static_cast<double>(energy_bound_fixed), checks - failures, checks, failures == 0 ? ", no heap use" : "");
    return failures == 0 ? 0 : 1;
}
