// ctga_accuracy: run time against error for every integrator in every representation, against the
// exact torque-free body (tests/support/freebody_exact.hpp), and the long-time energy behaviour.
//
//   ctga_accuracy OUT_DIR     (tools/accuracy.sh runs it and renders docs/accuracy.md)
//
// Writes
//   work_precision.csv   method, representation, frame, h, steps, seconds per run, attitude error
//                        ‖log(R_exactᵀ R)‖ at T, momentum error |R m_b − m0|/|m0| at T, maximum
//                        relative energy error over the run, and the largest difference of the
//                        final state from ctga's (same method, frame and h)
//   energy_history.csv   method, h, t, relative energy error: the Dzhanibekov body over 10⁴ s
//   far_from_origin.csv  |t|, relative error of the fixed-frame ṡ in the paper's form and about
//                        the body, against long double
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <ctga/ctga.hpp>

#include "support/dense_model.hpp"
#include "support/freebody_exact.hpp"
#include "support/matrix_model.hpp"

namespace {

using namespace ctga;
using namespace ctga::test;

// ---- the test problem: an asymmetric free body, translating and tumbling ------------------------
constexpr std::array<double, 3> principal{1, 2, 3};
constexpr std::array<double, 3> m0{1, 1.5, 1};          // body-frame angular momentum at t = 0
constexpr std::array<double, 3> com_velocity{0.3, -0.2, 0.5};
constexpr std::array<double, 3> start{1, 2, 3};         // position at t = 0 (R(0) = 1)
constexpr double t_end = 20;

mass_properties<double> the_body() { return *make_principal_mass_properties(1.0, principal[0], principal[1], principal[2]); }
motor<double> start_pose() { return rigid_motion(make_translator(start[0], start[1], start[2]), rotor<double>{1, 0, 0, 0}); }
screw<double> start_velocity_body() {
    return screw<double>{m0[0] / principal[0], m0[1] / principal[1], m0[2] / principal[2],
                         com_velocity[0],      com_velocity[1],      com_velocity[2]};
}

// The velocity in the body frame from a state of either frame.
screw<double> body_velocity(frame f, const motor<double>& g, const screw<double>& s) {
    return f == frame::body ? s : transform(inverse(map_of(g)), s);
}

struct errors {
    double attitude, momentum;
};
errors final_errors(frame f, const motor<double>& g, const screw<double>& s,
                    const freebody::torque_free_body<double>& exact) {
    const motor_map<double> G = map_of(g);
    const auto Re = exact.attitude(t_end);
    // Q = R_eᵀ R; its angle from the skew part and the trace, accurate at small angles
    double Q[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Q[i][j] = Re[0][i] * G.R[0][j] + Re[1][i] * G.R[1][j] + Re[2][i] * G.R[2][j];
    const double sx = Q[2][1] - Q[1][2], sy = Q[0][2] - Q[2][0], sz = Q[1][0] - Q[0][1];
    const double angle = std::atan2(std::sqrt(sx * sx + sy * sy + sz * sz) / 2, (Q[0][0] + Q[1][1] + Q[2][2] - 1) / 2);
    const screw<double> sb = body_velocity(f, g, s);
    const vec3<double> L = linear3::apply(G.R, vec3<double>{principal[0] * sb[0], principal[1] * sb[1], principal[2] * sb[2]});
    const double dL = std::hypot(L[0] - m0[0], L[1] - m0[1], L[2] - m0[2]) / std::hypot(m0[0], m0[1], m0[2]);
    return {angle, dL};
}
double energy(frame f, const motor<double>& g, const screw<double>& s) {
    const screw<double> sb = body_velocity(f, g, s);
    double e = 0;
    for (int i = 0; i < 3; ++i) e += principal[i] * sb[i] * sb[i] + sb[3 + i] * sb[3 + i];  // mass 1
    return e / 2;
}

// ---- the three representations, behind one adapter each -----------------------------------------
// to_state: a ctga state into the representation's; motor_of / screw_of: back, for measuring.
template <frame F>
struct ctga_rep {
    static constexpr const char* name = "ctga";
    using model = rigid_body_motion<double, F>;
    static model make() { return model{make_rigid_body(the_body())}; }
    static state_of<model> to_state(const motor<double>& g, const screw<double>& s) { return {g, s}; }
    static motor<double> motor_of(const motor<double>& g) { return g; }
    static screw<double> screw_of(const screw<double>& s) { return s; }
};
// ctga with the fixed-frame dynamics evaluated in space, as the paper writes them (§6)
template <frame F>
struct ctga_in_space_rep : ctga_rep<F> {
    static constexpr const char* name = "ctga_in_space";
    using model = rigid_body_motion<double, F, no_wrench, fixed_frame_evaluation::in_space>;
    static model make() { return model{make_rigid_body(the_body())}; }
};
template <frame F>
struct dense_rep {
    static constexpr const char* name = "dense";
    using model = dense_motion<double, F>;
    static model make() { return model{the_body()}; }
    static state_of<model> to_state(const motor<double>& g, const screw<double>& s) { return {dense_of(g), dense_of(s)}; }
    static motor<double> motor_of(const typename model::motor_type& g) { return motor_of_dense(g); }
    static screw<double> screw_of(const typename model::screw_type& s) { return screw_of_dense(s); }
};
template <frame F>
struct matrix_rep {
    static constexpr const char* name = "matrix";
    using model = matrix_motion<double, F>;
    static model make() { return model{the_body()}; }
    static state_of<model> to_state(const motor<double>& g, const screw<double>& s) {
        return {matrix_of(g), matrix_of(s)};
    }
    static motor<double> motor_of(const typename model::motor_type& g) { return to_ctga(g); }
    static screw<double> screw_of(const typename model::screw_type& s) { return to_ctga(s); }
};

struct final_state {
    motor<double> g;
    screw<double> s;
};
double difference(const final_state& a, const final_state& b) {
    double d = 0, scale = 1;
    for (std::size_t i = 0; i < 8; ++i) d = std::max(d, std::abs(a.g[i] - b.g[i])), scale = std::max(scale, std::abs(b.g[i]));
    for (std::size_t i = 0; i < 6; ++i) d = std::max(d, std::abs(a.s[i] - b.s[i])), scale = std::max(scale, std::abs(b.s[i]));
    return d / scale;
}

double benchmark_sink = 0;  // the timed runs' results land here, so none is optimised away

struct point {
    std::string method, rep;
    frame f;
    double h;
    long long steps;
    double seconds, attitude, momentum, energy, vs_ctga;
};

template <class Rep, frame F, class Method>
point measure(const char* method_name, const Method& method, double h, const freebody::torque_free_body<double>& exact,
              final_state& out, double min_seconds) {
    using clock = std::chrono::steady_clock;
    const auto model = Rep::make();
    const screw<double> sb = start_velocity_body();
    const motor<double> g0 = start_pose();
    const screw<double> s0 = F == frame::body ? sb : transform(map_of(g0), sb);
    const auto x0 = Rep::to_state(g0, s0);
    const long long steps = std::llround(t_end / h);
    // timed runs, without an observer, repeated to at least min_seconds
    int runs = 0;
    double seconds = 0;
    auto last = integrate(method, model, x0, h, steps);
    const auto t0 = clock::now();
    do {
        last = integrate(method, model, x0, h, steps);
        ++runs;
        seconds = std::chrono::duration<double>(clock::now() - t0).count();
    } while (seconds < min_seconds);
    // one observed run for the energy error along the way
    const double E0 = energy(F, g0, s0);
    double worst = 0;
    (void)integrate(method, model, x0, h, steps, [&](long long, const auto& x) {
        worst = std::max(worst, std::abs(energy(F, Rep::motor_of(x.g), Rep::screw_of(x.s)) - E0) / E0);
    });
    out = {Rep::motor_of(last.state.g), Rep::screw_of(last.state.s)};
    if (!last) std::fprintf(stderr, "%s/%s h=%g: %s\n", method_name, Rep::name, h, describe(last.error));
    const errors e = final_errors(F, out.g, out.s, exact);
    return {method_name, Rep::name, F, h, steps, seconds / runs, e.attitude, e.momentum, worst, 0};
}

template <frame F, class Method>
void sweep(const char* name, const Method& method, const std::vector<double>& steps,
           const freebody::torque_free_body<double>& exact, std::vector<point>& out) {
    for (double h : steps) {
        final_state a, b, c;
        point pc = measure<ctga_rep<F>, F>(name, method, h, exact, a, 0.2);
        point pm = measure<matrix_rep<F>, F>(name, method, h, exact, b, 0.2);
        point pd = measure<dense_rep<F>, F>(name, method, h, exact, c, 0.0);
        pm.vs_ctga = difference(b, a);
        pd.vs_ctga = difference(c, a);
        std::vector<point> row{pc, pm, pd};
        if constexpr (F == frame::fixed) {
            final_state e;
            row.push_back(measure<ctga_in_space_rep<F>, F>(name, method, h, exact, e, 0.2));
            row.back().vs_ctga = difference(e, a);
        }
        for (const point& p : row) {
            std::printf("%-18s %-13s %-5s h=%-7g %10.3e s  attitude %.2e  momentum %.2e  energy %.2e  vs ctga %.1e\n",
                        p.method.c_str(), p.rep.c_str(), F == frame::body ? "body" : "fixed", h, p.seconds, p.attitude,
                        p.momentum, p.energy, p.vs_ctga);
            out.push_back(p);
        }
    }
}

void work_precision(const std::string& dir) {
    const freebody::torque_free_body<double> exact({principal[0], principal[1], principal[2]}, {m0[0], m0[1], m0[2]});
    std::vector<point> points;
    const std::vector<double> coarse{0.4, 0.2, 0.1, 0.05, 0.025, 0.0125, 0.00625};
    const std::vector<double> fine{0.01, 0.005, 0.0025, 0.00125};
    const auto both_frames = [&](const char* name, const auto& method, const std::vector<double>& steps) {
        sweep<frame::body>(name, method, steps, exact, points);
        sweep<frame::fixed>(name, method, steps, exact, points);
    };
    both_frames("explicit_euler", explicit_euler{}, fine);
    both_frames("rk4", rk4{}, coarse);
    both_frames("lie_rk4", lie_rk4{}, coarse);
    // the three representations with the same solver (dense and 6×6 give no ∂a/∂s, so no Newton);
    // Newton against the fixed-point iteration: implicit_solvers below
    both_frames("implicit_midpoint", implicit_midpoint{.solver = implicit_solver::fixed_point}, coarse);
    FILE* f = std::fopen((dir + "/work_precision.csv").c_str(), "w");
    std::fprintf(f, "method,representation,frame,h,steps,seconds,attitude_error,momentum_error,max_energy_error,"
                    "difference_from_ctga\n");
    for (const point& p : points)
        std::fprintf(f, "%s,%s,%s,%.17g,%lld,%.6e,%.6e,%.6e,%.6e,%.6e\n", p.method.c_str(), p.rep.c_str(),
                     p.f == frame::body ? "body" : "fixed", p.h, p.steps, p.seconds, p.attitude, p.momentum, p.energy,
                     p.vs_ctga);
    std::fclose(f);
}

// ---- the implicit midpoint's two solvers at the work–precision step sizes (ctga) -----------------
// Newton's method with the exact ∂a/∂s (ctga::jacobian) against the fixed-point iteration:
// iterations per step, time per step, and whether every step converged.
template <frame F>
void solver_rows(FILE* f, const std::vector<double>& steps) {
    using clock = std::chrono::steady_clock;
    const auto model = ctga_rep<F>::make();
    const screw<double> sb = start_velocity_body();
    const motor<double> g0 = start_pose();
    const state_of<decltype(model)> x0{g0, F == frame::body ? sb : transform(map_of(g0), sb)};
    for (double h : steps) {
        const long long n = std::llround(t_end / h);
        for (const implicit_solver solver : {implicit_solver::newton, implicit_solver::fixed_point}) {
            long iterations = 0;
            const implicit_midpoint counted{.solver = solver, .iterations = &iterations};
            const auto run = integrate(counted, model, x0, h, n);
            const implicit_midpoint timed{.solver = solver};
            int runs = 0;
            double seconds = 0;
            const auto t0 = clock::now();
            do {
                const auto r = integrate(timed, model, x0, h, n);
                benchmark_sink = benchmark_sink + r.state.s[0];
                ++runs;
                seconds = std::chrono::duration<double>(clock::now() - t0).count();
            } while (seconds < 0.2);
            const char* name = solver == implicit_solver::newton ? "newton" : "fixed_point";
            const double per_step = double(iterations) / double(std::max(run.steps, 1LL));
            std::fprintf(f, "%s,%.17g,%s,%lld,%lld,%.4f,%.6e\n", F == frame::body ? "body" : "fixed", h, name, n, run.steps,
                         per_step, seconds / runs / double(n));
            std::printf("implicit midpoint %-5s h=%-7g %-11s %lld/%lld steps  %.2f iterations/step  %.3e s/step\n",
                        F == frame::body ? "body" : "fixed", h, name, run.steps, n, per_step, seconds / runs / double(n));
        }
    }
}
void implicit_solvers(const std::string& dir) {
    const std::vector<double> coarse{0.4, 0.2, 0.1, 0.05, 0.025, 0.0125, 0.00625};
    FILE* f = std::fopen((dir + "/implicit_solvers.csv").c_str(), "w");
    std::fprintf(f, "frame,h,solver,steps,converged_steps,iterations_per_step,seconds_per_step\n");
    solver_rows<frame::body>(f, coarse);
    solver_rows<frame::fixed>(f, coarse);
    std::fclose(f);
}

// ---- energy against time: the Dzhanibekov body over 10⁴ s (ctga, body frame) -------------------
void energy_history(const std::string& dir) {
    const std::array<double, 3> I{1, 2, 3}, mD{0.01, 2, 0.01};
    const rigid_body_motion<double, frame::body> model{
        make_rigid_body(*make_principal_mass_properties(1.0, I[0], I[1], I[2]))};
    const state_of<decltype(model)> x0{motor<double>{1, 0, 0, 0, 0, 0, 0, 0},
                                       screw<double>{mD[0] / I[0], mD[1] / I[1], mD[2] / I[2], 0, 0, 0}};
    const auto E = [&](const screw<double>& s) { return (I[0] * s[0] * s[0] + I[1] * s[1] * s[1] + I[2] * s[2] * s[2]) / 2; };
    const double E0 = E(x0.s), T = 1e4;
    FILE* f = std::fopen((dir + "/energy_history.csv").c_str(), "w");
    std::fprintf(f, "method,h,t,energy_error\n");
    const auto record = [&](const char* name, const auto& method, double h) {
        double next = h;  // sample at log-spaced times, 40 per decade
        const auto run = integrate(method, model, x0, h, std::llround(T / h), [&](long long n, const auto& x) {
            const double t = double(n) * h;
            if (t + 1e-12 < next) return;
            std::fprintf(f, "%s,%g,%.6e,%.6e\n", name, h, t, std::abs(E(x.s) - E0) / E0);
            next = t * std::pow(10.0, 1.0 / 40);
        });
        std::printf("energy history %s h=%g: %s after %lld steps\n", name, h, run ? "done" : describe(run.error), run.steps);
    };
    record("rk4", rk4{}, 0.1);
    record("rk4", rk4{}, 0.01);
    record("lie_rk4", lie_rk4{}, 0.1);
    record("implicit_midpoint", implicit_midpoint{}, 0.1);
    record("explicit_euler", explicit_euler{}, 0.01);
    std::fclose(f);
}

// ---- far from the origin: the error of the fixed-frame ṡ against |t| ---------------------------
void far_from_origin(const std::string& dir) {
    const vec3<double> com{0.1, -0.2, 0.3};
    const mat3<double> Ic{{{2, 0.1, 0}, {0.1, 2.5, -0.05}, {0, -0.05, 3}}};
    const rigid_body<double> b = make_rigid_body(*make_mass_properties(2.0, com, Ic));
    mat3<long double> Icl{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Icl[i][j] = Ic[i][j];
    const rigid_body<long double> bl =
        make_rigid_body(*make_mass_properties<long double>(2.0L, vec3<long double>{0.1L, -0.2L, 0.3L}, Icl));
    const screw<double> s_b{0.3, 1.0, -0.4, 0.2, -0.1, 0.5};
    const wrench<double> W_b{0.2, -0.1, 0.05, 1.0, 0.5, -0.3};
    FILE* f = std::fopen((dir + "/far_from_origin.csv").c_str(), "w");
    std::fprintf(f, "distance,paper_error,about_body_error\n");
    for (int k = 0; k <= 24; ++k) {
        const double d = std::pow(10.0, k / 4.0);
        const motor<double> g = rigid_motion(make_translator(0.6 * d, -0.48 * d, 0.64 * d), make_rotor(0.7, 1.0 / 3, 2.0 / 3, 2.0 / 3));
        const motor_map<double> G = map_of(g);
        const screw<double> s = transform(G, s_b);
        const wrench<double> W = transform(G, W_b);
        motor<long double> gl;
        screw<long double> sl;
        wrench<long double> Wl;
        for (std::size_t i = 0; i < 8; ++i) gl[i] = g[i];
        for (std::size_t i = 0; i < 6; ++i) sl[i] = s[i], Wl[i] = W[i];
        const screw<long double> ref = fixed_frame_rates_about_body(bl, gl, sl, Wl).s_dot;
        const screw<double> paper = fixed_frame_rates(b, g, s, W).s_dot;
        const screw<double> remedy = fixed_frame_rates_about_body(b, g, s, W).s_dot;
        long double scale = 0, ep = 0, er = 0;
        for (std::size_t i = 0; i < 6; ++i) {
            scale = std::max(scale, std::abs(ref[i]));
            ep = std::max(ep, std::abs(paper[i] - ref[i]));
            er = std::max(er, std::abs(remedy[i] - ref[i]));
        }
        std::fprintf(f, "%.6e,%.6e,%.6e\n", d, double(ep / scale), double(er / scale));
    }
    std::fclose(f);
}

}  // namespace

int main(int argc, char** argv) {
    const std::string dir = argc > 1 ? argv[1] : ".";
    far_from_origin(dir);
    energy_history(dir);
    work_precision(dir);
    implicit_solvers(dir);
    std::printf("wrote %s/work_precision.csv, energy_history.csv, far_from_origin.csv, implicit_solvers.csv (%g)\n",
                dir.c_str(), benchmark_sink);
    return 0;
}
