// A quadruped from its URDF (tests/data/quadruped.urdf, floating base) dropped onto the ground,
// standing up to its stance under a PD controller and swaying its trunk from side to side:
// its URDF's collision geometry (make_geometry: spheres on its four feet, a box for its trunk, a
// mesh's convex hull on a hip), the ground a half-space, its URDF's joint limits
// (the knees reach theirs), a step of 1 ms (constrained/contact_step.hpp). Every 0.1 s it prints
// the four feet's normal forces, their sum against the weight, the fastest foot slip and the
// solver's residual.
//
//   quadruped_stand               the table
//   quadruped_stand --svg FILE    also the normal forces over time: docs/img/quadruped_stand.svg
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include <ctga/chains/algorithms.hpp>
#include <ctga/constrained/contact_step.hpp>

#include "quadruped.hpp"  // generated: namespace quadruped { using tree = …; make_model<T>(); make_limits<T>(); make_geometry<T>(); }

namespace ch = ctga::chains;
namespace cn = ctga::constrained;
namespace co = ctga::collision;
using robot = quadruped::tree;
using ground = co::shape<co::half_space<double>>;

int main(int argc, char** argv) {
    const auto model = quadruped::make_model<double>();
    const auto limits = quadruped::make_limits<double>();
    // the URDF's <collision>: a sphere of 2 cm on each foot, a box on the trunk, a hip cover's hull
    const auto geometry = quadruped::make_geometry<double>();
    if (!model || !limits || !geometry)
        return std::printf("quadruped: %s\n", ctga::describe(!model ? model.error : !limits ? limits.error : geometry.error)), 1;
    const ch::model<robot>& m = *model;
    const double r = 0.02;                                  // the feet's radius
    const std::array<cn::static_shape<ground>, 1> world{};  // the ground: z ≤ 0

    cn::contact_stepper<robot, double, 24> stepper;
    stepper.limits = *limits;
    for (std::size_t k = 6; k < robot::nv; ++k) stepper.limits.damping[k] = 8.0;  // the PD's D, implicit
    cn::step_settings<double> settings;                                            // h = 1 ms, tolerance 1e-9 N s
    settings.mu = 0.8;

    // start: legs straight, trunk 0.5 m up; the stance: thighs 0.45, knees −0.9
    ch::configuration<robot> q{};
    const ctga::motor<double> trunk = ctga::rigid_motion(ctga::make_translator(0.0, 0.0, 0.5), ctga::make_rotor(0.0, 0.0, 0.0, 1.0));
    for (std::size_t k = 0; k < 8; ++k) q[k] = trunk[k];
    ch::joint_vector<robot> qd{};
    const double weight = ch::center_of_mass(m, ch::forward_kinematics(m, q)).mass * 9.81;
    std::printf("quadruped: %zu dofs, weight %.2f N; dropped from 0.5 m, stance from 1 s, sway from 2 s\n", robot::nv, weight);
    std::printf("   t     FL      FR      RL      RR    sum/weight  slip (m/s)  limits  residual\n");

    std::string polylines[4];
    double worst_sum = 0, worst_slip = 0;
    const char* feet[4] = {"FL_foot", "FR_foot", "RL_foot", "RR_foot"};
    for (int n = 0; n <= 4000; ++n) {
        const double t = 1e-3 * n, stance = t < 1.0 ? 0.0 : t < 1.5 ? (t - 1.0) / 0.5 : 1.0;
        const double sway = t < 2.0 ? 0.0 : 0.15 * std::sin(2 * 3.141592653589793 * (t - 2.0));
        ch::joint_vector<robot> tau{};
        for (std::size_t leg = 0; leg < 4; ++leg) {
            const std::array<double, 3> target{sway, 0.45 * stance, -0.9 * stance};
            for (std::size_t j = 0; j < 3; ++j) tau[6 + 3 * leg + j] = 300.0 * (target[j] - q[8 + 3 * leg + j]);
        }
        const auto report = stepper.step(m, q, qd, tau, *geometry, std::span<const cn::static_shape<ground>>(world), settings);
        if (report.error != ctga::error_code::none) return std::printf("step %d: %s\n", n, ctga::describe(report.error)), 1;
        // each foot's normal force: its contact's normal impulse over h (body 3 + 3 leg: its calf)
        std::array<double, 4> force{};
        for (std::size_t i = 0; i < stepper.blocks().size(); ++i) {
            const cn::constraint_block<double>& b = stepper.blocks()[i];
            if (b.kind == cn::block_kind::contact && b.a > 0 && b.a % 3 == 0) force[static_cast<std::size_t>(b.a / 3 - 1)] += stepper.impulses()[3 * i] / settings.step;
        }
        const double sum = force[0] + force[1] + force[2] + force[3];
        const auto k = ch::forward_kinematics(m, q, qd);
        double slip = 0;
        for (const auto& v : {ch::frame_velocity(m, k, ch::frame<"FL_foot">, ch::reference::local_world_aligned),
                              ch::frame_velocity(m, k, ch::frame<"FR_foot">, ch::reference::local_world_aligned),
                              ch::frame_velocity(m, k, ch::frame<"RL_foot">, ch::reference::local_world_aligned),
                              ch::frame_velocity(m, k, ch::frame<"RR_foot">, ch::reference::local_world_aligned)})
            slip = std::fmax(slip, std::hypot(v[3] - r * v[1], v[4] + r * v[0]));  // the point touching: v + ω × (0, 0, −r)
        if (t > 3.0) worst_slip = std::fmax(worst_slip, slip), worst_sum = std::fmax(worst_sum, std::fabs(sum / weight - 1));
        for (std::size_t f = 0; f < 4; ++f) {
            char point[48];
            std::snprintf(point, sizeof point, "%.1f,%.1f ", 40 + 160 * t, 230 - 1.2 * force[f]);
            if (n % 10 == 0) polylines[f] += point;
        }
        if (n % 100 == 0)
            std::printf("  %.1f  %6.2f  %6.2f  %6.2f  %6.2f   %8.5f    %.1e      %zu     %.0e\n", t, force[0], force[1], force[2], force[3],
                        sum / weight, slip, report.limits, report.solver.residual);
    }
    std::printf("from 3 s to 4 s (swaying): the feet's forces sum to the weight to %.1e (the trunk accelerates: not 0), slip %.1e m/s\n", worst_sum,
                worst_slip);
    if (argc == 3 && std::strcmp(argv[1], "--svg") == 0) {
        if (std::FILE* out = std::fopen(argv[2], "w")) {
            const char* colour[4] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd"};
            std::fprintf(out, "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 720 260\" width=\"720\" height=\"260\" font-family=\"sans-serif\" font-size=\"11\">\n");
            std::fprintf(out, "<line x1=\"40\" y1=\"230\" x2=\"700\" y2=\"230\" stroke=\"#444\"/><line x1=\"40\" y1=\"20\" x2=\"40\" y2=\"230\" stroke=\"#444\"/>\n");
            for (int s = 0; s <= 4; ++s) std::fprintf(out, "<text x=\"%d\" y=\"245\" text-anchor=\"middle\">%d s</text>\n", 40 + 160 * s, s);
            for (int f = 0; f <= 150; f += 50) std::fprintf(out, "<text x=\"35\" y=\"%.0f\" text-anchor=\"end\">%d N</text>\n", 234 - 1.2 * f, f);
            for (std::size_t f = 0; f < 4; ++f) {
                std::fprintf(out, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1\" points=\"%s\"/>\n", colour[f], polylines[f].c_str());
                std::fprintf(out, "<text x=\"%zu\" y=\"15\" fill=\"%s\">%s</text>\n", 60 + 90 * f, colour[f], feet[f]);
            }
            std::fprintf(out, "<text x=\"450\" y=\"15\">normal force of each foot (weight/4 = %.1f N)</text>\n</svg>\n", weight / 4);
            std::fclose(out);
        }
    }
    return worst_slip < 1e-3 ? 0 : 1;
}
