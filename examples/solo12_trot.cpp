// Solo 12 (ODRI's open quadruped, 2.5 kg) from its real URDF (examples/data/solo12.urdf, floating
// base) lies on its belly, stands up and trots in place. Its URDF's collision geometry is meshes
// that are not shipped (the header is converted with --meshes omit), so the example attaches its
// own through robot_geometry: a ball at each FOOT frame, a box for the trunk. The controller is a
// first legged-robot controller: a joint-space PD towards a fold of the legs (P in τ, D as the
// stepper's implicit joint damping), plus each supporting foot's share of the weight as
// feed-forward, τ −= Jᵀ (0, 0, m g / n); the trot lifts the diagonal pairs FL+HR and FR+HL in turn,
// at 2 Hz. Steps of 1 ms (constrained/contact_step.hpp) over 4 s: lying until 0.2 s, standing up
// until 1.2 s, standing still until 2 s, trotting to 4 s.
//
// Every 0.1 s it prints the feet's normal forces and the belly's, the feet's sum against the
// weight, the trunk's height, the fastest slip of a stance foot and the solver's residual. It
// checks, and returns 1 if one fails: standing, the feet's mean force is the weight and the trunk
// is at the stance's height; trotting, the stance feet do not slip, every foot leaves the ground,
// the trunk stays up and in place; every step's solve converged.
#include <array>
#include <cmath>
#include <cstdio>
#include <span>

#include <ctga/chains/center_of_mass.hpp>
#include <ctga/chains/forward_kinematics.hpp>
#include <ctga/chains/frame_jacobian.hpp>
#include <ctga/chains/frames.hpp>
#include <ctga/constrained/contact_step.hpp>

#include "solo12.hpp"  // generated: namespace solo12 { using tree = …; make_model<T>(); make_limits<T>(); }

namespace ch = ctga::chains;
namespace cn = ctga::constrained;
namespace co = ctga::collision;
using robot = solo12::tree;
using robot_shape = co::shape<co::sphere<double>, co::box<double>>;
using ground = co::shape<co::half_space<double>>;

constexpr double pi = 3.141592653589793;
constexpr double foot_radius = 0.016;  // the ball around each FOOT frame's origin (the FOOT link's centre of mass is 0.4 mm off it)
constexpr double belly = 0.03;         // the trunk box's half height (half length 0.2 m, half width 0.07 m)
constexpr double leg = 0.16;           // HFE to KFE and KFE to FOOT, along the leg (the URDF's <origin>s)

// A leg's joint angles (HAA, HFE, KFE) for fold θ: (0, θ, −2θ) on a front leg, (0, −θ, 2θ) on a
// hind one, the knees towards the trunk's middle. Both halves of the leg then make angle θ with
// the vertical: the foot is under the HFE axis, 2 leg cos θ below it, and the HFE axis is level
// with the trunk's origin (the HAA and HFE <origin>s have z = 0).
constexpr std::array<double, 3> fold(std::size_t l, double theta) {
    const double s = l < 2 ? 1.0 : -1.0;  // the legs in the tree's order: FL, FR, HL, HR
    return {0.0, s * theta, -2 * s * theta};
}

double smoothstep(double x) {
    x = std::fmin(1.0, std::fmax(0.0, x));
    return x * x * (3 - 2 * x);
}

int main() {
    const auto model = solo12::make_model<double>();
    const auto limits = solo12::make_limits<double>();
    if (!model || !limits) return std::printf("solo12: %s\n", ctga::describe(!model ? model.error : limits.error)), 1;
    const ch::model<robot>& m = *model;

    cn::robot_geometry<robot, robot_shape, double, 5> geometry;
    const co::sphere<double> ball{foot_radius};
    for (const ctga::error_code e : {geometry.attach(m, ch::frame<"FL_FOOT">, ball), geometry.attach(m, ch::frame<"FR_FOOT">, ball),
                                     geometry.attach(m, ch::frame<"HL_FOOT">, ball), geometry.attach(m, ch::frame<"HR_FOOT">, ball),
                                     geometry.attach(m, ch::frame<"base_link">, co::box<double>{{0.2, 0.07, belly}})})
        if (e != ctga::error_code::none) return std::printf("solo12: geometry: %s\n", ctga::describe(e)), 1;
    std::array<int, 5> body{};  // shapes 0–3 the feet (each on its lower leg: FOOT is fixed to it), 4 the trunk
    for (std::size_t s = 0; s < 5; ++s) body[s] = geometry.shapes()[s].body;
    const std::array<cn::static_shape<ground>, 1> world{};  // the ground: z ≤ 0

    cn::contact_stepper<robot, double, 16> stepper;
    stepper.limits = *limits;  // the URDF's bounds are ±10 rad: never reached
    for (std::size_t k = 6; k < robot::nv; ++k) stepper.limits.damping[k] = 0.3;  // the PD's D (N m s/rad), implicit
    cn::step_settings<double> settings;                                           // h = 1 ms, tolerance 1e-9 N s
    settings.mu = 1.0;                                                            // the URDF's <lateral_friction> (for Bullet)
    const double h = settings.step, kp = 10.0;                                    // the PD's P (N m/rad)

    // lying: the belly 1 mm above the ground and the feet as high, 2 leg cos θ = belly − foot_radius
    const double lying = std::acos((belly - foot_radius) / (2 * leg)), stance = 0.8, lift = 0.25, gait = 2.0;
    const double height = 2 * leg * std::cos(stance) + foot_radius;  // the trunk's at the stance
    ch::configuration<robot> q{};
    const ctga::motor<double> trunk = ctga::rigid_motion(ctga::make_translator(0.0, 0.0, belly + 1e-3), ctga::make_rotor(0.0, 0.0, 0.0, 1.0));
    for (std::size_t k = 0; k < 8; ++k) q[k] = trunk[k];
    for (std::size_t l = 0; l < 4; ++l)
        for (std::size_t j = 0; j < 3; ++j) q[8 + 3 * l + j] = fold(l, lying)[j];
    ch::joint_vector<robot> qd{};
    const double weight = ch::center_of_mass(m, ch::forward_kinematics(m, q)).mass * 9.81;
    std::printf("solo12: %zu dofs, weight %.2f N; lying (fold %.3f rad), standing up by 1.2 s (fold %.1f rad, trunk at %.4f m), trotting from 2 s\n",
                robot::nv, weight, lying, stance, height);
    std::printf("   t     FL     FR     HL     HR    belly  feet/weight  trunk z  slip (m/s)  residual\n");

    double worst_slip = 0, worst_residual = 0, sum_window = 0, height_window = 0, lowest_trunk = 1, highest_lift = 0;
    int samples = 0, unconverged = 0;
    std::array<int, 4> airborne{};  // the trot's steps each foot spent off the ground
    std::array<double, 5> force{};  // the last step's normal forces on the shapes (N)
    for (int n = 0; n <= 4000; ++n) {
        const double t = h * n, phase = std::sin(2 * pi * gait * (t - 2.0));
        // the folds: the stand-up ramp, then FL+HR (phase > 0) and FR+HL (phase < 0) lifted in turn by
        // lift sin²: a foot leaves and lands at rest. A foot supports (carries its share of the
        // weight) while not lifted and once the last step found it on the ground: a landing foot is
        // not pushed down before it lands.
        const double rise = smoothstep(t - 0.2);  // 0 lying, 1 standing
        std::array<double, 4> theta{};
        std::array<bool, 4> support{};
        int supporting = 0;
        for (std::size_t l = 0; l < 4; ++l) {
            const double side = t < 2.0 ? 0.0 : std::fmax(0.0, l == 0 || l == 3 ? phase : -phase), up = side * side;
            theta[l] = lying + (stance - lying) * rise + lift * up;
            support[l] = up == 0 && force[l] > 0;
            supporting += support[l];
        }
        ch::joint_vector<robot> tau{};
        for (std::size_t l = 0; l < 4; ++l)
            for (std::size_t j = 0; j < 3; ++j) tau[6 + 3 * l + j] = kp * (fold(l, theta[l])[j] - q[8 + 3 * l + j]);
        // the feed-forward: a supporting foot pushes the ground with m g / n, τ −= Jᵀ (0, 0, m g / n) (J's row 5: the foot's vz)
        const auto carry = [&](std::size_t l, auto foot) {
            if (!support[l]) return;
            const ch::jacobian_matrix<robot, double> J = ch::frame_jacobian(m, q, foot, ch::reference::local_world_aligned);
            for (std::size_t k = 6; k < robot::nv; ++k) tau[k] -= J[k][5] * rise * weight / supporting;
        };
        carry(0, ch::frame<"FL_FOOT">), carry(1, ch::frame<"FR_FOOT">), carry(2, ch::frame<"HL_FOOT">), carry(3, ch::frame<"HR_FOOT">);

        const auto report = stepper.step(m, q, qd, tau, geometry, std::span<const cn::static_shape<ground>>(world), settings);
        if (report.error != ctga::error_code::none) return std::printf("step %d: %s\n", n, ctga::describe(report.error)), 1;
        unconverged += !report.solver.converged;
        worst_residual = std::fmax(worst_residual, report.solver.residual);
        // each shape's normal force: its contacts' normal impulses over h (a contact's body A is its shape's)
        force = {};
        for (std::size_t i = 0; i < stepper.blocks().size(); ++i)
            for (std::size_t s = 0; s < 5; ++s)
                if (stepper.blocks()[i].kind == cn::block_kind::contact && stepper.blocks()[i].a == body[s]) force[s] += stepper.impulses()[3 * i] / h;
        const double sum = force[0] + force[1] + force[2] + force[3];
        const auto k = ch::forward_kinematics(m, q, qd);
        const double z = k.pose[0].t[2];
        // a stance foot's slip (it supported before the step and still touches): the speed along the
        // ground of its ball's lowest point, v + ω × (0, 0, −r)
        double slip = 0;
        const auto slide = [&](std::size_t l, auto foot) {
            const ctga::screw<double> v = ch::frame_velocity(m, k, foot, ch::reference::local_world_aligned);
            if (support[l] && force[l] > 0) slip = std::fmax(slip, std::hypot(v[3] - foot_radius * v[1], v[4] + foot_radius * v[0]));
            if (t > 2.0) highest_lift = std::fmax(highest_lift, ch::frame_pose(m, k, foot).t[2] - foot_radius);
        };
        slide(0, ch::frame<"FL_FOOT">), slide(1, ch::frame<"FR_FOOT">), slide(2, ch::frame<"HL_FOOT">), slide(3, ch::frame<"HR_FOOT">);
        if (t >= 1.5 && t < 2.0) sum_window += sum, height_window += z, ++samples;
        if (t > 2.0) {
            worst_slip = std::fmax(worst_slip, slip), lowest_trunk = std::fmin(lowest_trunk, z);
            for (std::size_t l = 0; l < 4; ++l) airborne[l] += !(force[l] > 0);
        }
        if (n % 100 == 0)
            std::printf("  %.1f  %5.2f  %5.2f  %5.2f  %5.2f   %5.2f   %8.5f    %.4f    %.1e     %.0e\n", t, force[0], force[1], force[2], force[3],
                        force[4], sum / weight, z, slip, report.solver.residual);
    }
    const double mean_sum = sum_window / samples / weight, mean_height = height_window / samples;
    const ctga::vec3<double> end = ch::forward_kinematics(m, q).pose[0].t;
    const double drift = std::hypot(end[0], end[1]);  // the trunk's horizontal distance from its start
    std::printf("standing (1.5-2 s): the feet's mean force %.6f of the weight; trunk at %.4f m (the stance's %.4f m)\n", mean_sum, mean_height,
                height);
    std::printf("trotting (2-4 s): stance-foot slip at most %.1e m/s; feet off the ground %d %d %d %d ms, lifted up to %.3f m;\n"
                "  trunk down to %.4f m, %.1e m from where it stood up\n",
                worst_slip, airborne[0], airborne[1], airborne[2], airborne[3], highest_lift, lowest_trunk, drift);
    std::printf("solver: %d unconverged steps, largest residual %.1e N s\n", unconverged, worst_residual);

    // The checks. Standing still, the feet's impulses over the window are the weight's plus the
    // robot's change of momentum, m Δv: m Δv / (m g 0.5 s) < 1e-4 while Δv < 0.5 mm/s (settled,
    // Δv is 1e-5 m/s: 3e-6 of the weight), and a foot's force lost or counted twice is 0.25.
    // The balls roll outwards by r Δθ (1.2 cm) as the lower legs turn from the lying fold to the
    // stance, and friction then holds the feet there, spread: the trunk stands 2–3 mm lower than
    // the stance's height; 5 mm allows for that, not for a leg giving way. A foot that sticks has
    // no speed along the ground at the step's start (the solve's condition); measured at its end,
    // the ball has rolled on by h ω: below 1e-4 m/s; one that slides moves at cm/s.
    bool ok = true;
    const auto check = [&](bool passed, const char* what) {
        if (!passed) std::printf("FAILED: %s\n", what);
        ok = ok && passed;
    };
    check(std::fabs(mean_sum - 1) < 1e-4, "standing, the feet's mean force is the weight to 1e-4");
    check(std::fabs(mean_height - height) < 5e-3, "standing, the trunk is within 5 mm of the stance's height");
    check(worst_slip < 1e-3, "trotting, no stance foot slips faster than 1 mm/s");
    for (std::size_t l = 0; l < 4; ++l) check(airborne[l] > 600, "trotting, every foot is off the ground 30 % of the time");
    check(highest_lift > 0.03 && lowest_trunk > height - 0.02 && drift < 0.01, "trotting, the feet lift 3 cm, the trunk stays up and in place");
    check(unconverged == 0, "every step's solve converged (residual at most 1e-9 N s)");
    return ok ? 0 : 1;
}
