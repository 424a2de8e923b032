// ctga_chains_bench's constrained dynamics of the quadruped (Solo 12's numbers on the legged tree,
// chains_legged.cpp's fixture): its four feet (the lower legs' points at (0, ±0.008, −0.16), where
// the URDF's feet are) held where they are in each state, four 3-D contacts (constrained/):
//   constrained_fd_quadruped/ctga   q̈ and the 12 contact forces (constrained_forward_dynamics)
//   delassus_quadruped/ctga         the 12 × 12 Delassus operator J H⁻¹ Jᵀ (delassus)
// beside the same run's aba_quadruped/ctga (the target: constrained forward dynamics ≤ 2× ABA);
// and a step of the quadruped standing on the ground on four sphere feet under a PD controller
// (contact_scenario, chains_mujoco.hpp: the same numbers for MuJoCo's and DART's rows):
//   contact_step_quadruped/ctga     contact_stepper::step (collision, limits, one solve, Euler)
//   contact_step_quadruped/mujoco   mj_step (chains_mujoco.cpp)
//   contact_step_quadruped/dart     World::step (chains_dart.cpp; DART 6.12, when found by CMake)
// each with its foot slip and sinking printed (stderr) after the same settling.
#include <cmath>
#include <memory>
#include <vector>

#include <ctga/constrained/constrained_dynamics.hpp>

#include "chains_contact_steps.hpp"
#include "chains_dart.hpp"

namespace bench::chains {
namespace {
namespace cn = ctga::constrained;
using feet = cn::constraint_set<legged_tree, double, 4>;

struct quadruped_case {
    fixture<legged_tree> f = make_fixture<legged_tree>(solo12(), 74);
    std::array<feet, 64> held{};

    quadruped_case() {
        for (std::size_t s = 0; s < 64; ++s) {
            const auto k = ch::forward_kinematics(f.m, f.states[s].q);
            for (int leg = 0; leg < 4; ++leg) {
                const std::size_t shank = static_cast<std::size_t>(3 + 3 * leg);
                const double y = leg % 2 == 0 ? 0.008 : -0.008;
                cn::constraint_block<double> b;
                b.a = static_cast<int>(shank);
                b.at_a.t = {0, y, -0.16};
                b.at_b = ctga::compose(k.pose[shank], b.at_a);  // held where it is
                if (held[s].add(b) != ctga::error_code::none) throw std::logic_error("chains_constrained: a foot refused");
            }
        }
    }
};

template <class Kernel>
void add_kernel(std::vector<entry>& table, const std::string& name, const quadruped_case& c, Kernel kernel) {
    const quadruped_case* p = &c;
    table.push_back({name,
                     [p, kernel](benchmark::State& st) {
                         std::size_t k = 0;
                         for (auto _ : st) {
                             auto r = kernel(*p, k);
                             benchmark::DoNotOptimize(r);
                             k = (k + 1) & 63;
                         }
                     },
                     [p, kernel](std::size_t calls) {
                         for (std::size_t i = 0; i < calls; ++i) {
                             auto r = kernel(*p, i & 63);
                             benchmark::DoNotOptimize(r);
                         }
                     }});
}

[[gnu::noinline]] auto constrained_fd(const quadruped_case& c, std::size_t k) {
    const auto& s = c.f.states[k];
    return cn::constrained_forward_dynamics(c.f.m, s.q, s.qd, s.tau, c.held[k]);
}
[[gnu::noinline]] auto delassus_of(const quadruped_case& c, std::size_t k) { return cn::delassus(c.f.m, c.f.states[k].q, c.held[k]); }
// Solo 12 standing on its feet: hips 0, thighs 0.8, knees −1.6 (each foot 0.223 m under its hip),
// dropped from 2 mm; spheres of 1.6 cm at the feet; h = 2 ms (MuJoCo's default step), μ = 1
// (MuJoCo's default friction), kp 10 N m/rad, damping 0.1 N m s/rad.
contact_scenario standing_quadruped() {
    contact_scenario s;
    s.label = "quadruped";
    for (const auto& b : solo12()) s.bodies.push_back(mujoco_detail::body_of(b));
    s.gravity = {0, 0, -9.81};
    const double r = 0.016;
    s.free_start = {contact_detail::free_qpos({0, 0, 2 * 0.16 * std::cos(0.8) + r + 0.002}, 0.0)};
    for (std::size_t leg = 0; leg < 4; ++leg) {
        s.target.insert(s.target.end(), {0.0, 0.8, -1.6});
        s.shapes.push_back({3 + 3 * leg, {0, leg % 2 == 0 ? 0.008 : -0.008, -0.16}, r, {}});
    }
    s.h = 0.002, s.mu = 1.0, s.kp = 10.0, s.damping = 0.1;
    s.settle = 1000, s.measure = 500;
    return s;
}

// ctga's numbers for DART's model check (add_dart_contact): the fixture's first 8 states in
// mujoco_case's coordinates (make_mujoco_case's conversion, which is compiled only with MuJoCo),
// H and τ = H q̈ + C on them from the forms constrained dynamics instantiates here already (H from
// the shared joint maps, C from the world motion: no other instantiation of CRBA or RNEA in this
// unit, whose compile time the issue bounds).
[[maybe_unused]] mujoco_case dart_reference(const fixture<legged_tree>& f) {
    mujoco_case c;
    c.label = "quadruped";
    c.nv = legged_tree::nv;
    for (std::size_t s = 0; s < 8; ++s) {
        const state<legged_tree>& x = f.states[s];
        std::vector<double> q;
        for (std::size_t i = 0; i < legged_tree::size; ++i) {
            const std::size_t o = legged_tree::q_offset[i];
            if (legged_tree::nq_of[i] == 8) {  // the floating joint's motor: its map's translation, its unit rotor
                ctga::motor<double> g{};
                for (std::size_t k = 0; k < 8; ++k) g[k] = x.q[o + k];
                const auto G = ctga::map_of(g);
                const double n = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2] + g[3] * g[3]);
                q.insert(q.end(), {G.t[0], G.t[1], G.t[2], g[0] / n, g[1] / n, g[2] / n, g[3] / n});
            } else if (legged_tree::nq_of[i] == 1) {
                q.push_back(x.q[o]);
            }
        }
        c.q.push_back(std::move(q));
        c.qd.emplace_back(x.qd.begin(), x.qd.end());
        c.qdd.emplace_back(x.qdd.begin(), x.qdd.end());
        namespace chd = ch::algorithm_detail;
        chd::joint_maps<legged_tree, double> X;
        chd::fill_joint_maps(X, f.m, x.q);
        const auto H = chd::mass_matrix(f.m, x.q, X);
        cn::tree_motion<legged_tree, double> g(ctga::uninitialized);
        cn::fill_tree_motion(g, f.m, x.q, x.qd, X);
        std::array<double, legged_tree::nv> tau = cn::bias_forces(f.m, g);
        for (std::size_t k = 0; k < legged_tree::nv; ++k)
            for (std::size_t j = 0; j < legged_tree::nv; ++j) tau[k] += H[k][j] * x.qdd[j];
        c.tau_ref.emplace_back(tau.begin(), tau.end());
        std::vector<double> h;
        for (const auto& row : H) h.insert(h.end(), row.begin(), row.end());
        c.H_ref.push_back(std::move(h));
    }
    return c;
}

}  // namespace

void add_constrained(std::vector<entry>& table) {
    static const quadruped_case c;
    add_kernel(table, "constrained_fd_quadruped/ctga", c, constrained_fd);
    add_kernel(table, "delassus_quadruped/ctga", c, delassus_of);
    using namespace contact_detail;
    const contact_scenario s = standing_quadruped();
    add_contact_step(table, s, std::make_shared<contact_robot<legged_tree, co::shape<co::sphere<double>>, 4, 8>>(s, ctga_model<legged_tree>(solo12())));
    if constexpr (dart_enabled) add_dart_contact(table, s, dart_reference(c.f));
}
}  // namespace bench::chains
