// A planar multi-body scene: a chain of three pucks hanging from a fixed point under gravity,
// linked by spring–dampers, plus a free puck sliding past and a static post. Every puck moves in
// the e1, e2 plane, so its screws have the three blades ω_z, v_x, v_y and each step of each body
// runs on those three components (ctga::body_step_cost prints what it costs).
#include <cmath>
#include <cstdio>

#include <ctga/ctga.hpp>

int main() {
    namespace cg = ctga;
    using planar = cg::subspace::planar;
    using puck = cg::body_motion<double, planar, cg::inertia_kind::sphere, cg::wrench_model::uniform_field<double, planar>>;
    using free_puck = cg::body_motion<double, planar, cg::inertia_kind::sphere>;
    const cg::vec3<double> gravity{0, -9.81, 0};
    const double m = 0.5, d = 0.01;  // mass and moment of inertia of each puck

    const auto world = cg::make_scene(
        cg::couple(cg::spring_damper<0, cg::world>{{0, 0.1, 0}, {0, 0, 0}, 400.0, 0.5},  // top puck to the ceiling
                   cg::spring_damper<0, 1>{{0, -0.1, 0}, {0, 0.1, 0}, 400.0, 0.5},
                   cg::spring_damper<1, 2>{{0, -0.1, 0}, {0, 0.1, 0}, 400.0, 0.5}),
        puck{{m, d}, cg::weight<planar>(m, gravity)}, puck{{m, d}, cg::weight<planar>(m, gravity)},
        puck{{m, d}, cg::weight<planar>(m, gravity)}, free_puck{{m, d}},
        cg::static_body<double>{cg::motor<double>(cg::make_translator(1.0, -1.0, 0.0))});

    using pose = puck::motor_type;
    using velocity = puck::screw_type;
    const auto at = [](double x, double y) { return cg::project<pose>(cg::motor<double>(cg::make_translator(x, y, 0.0))); };
    const auto x0 = world.initial_state(cg::motion_state<pose, velocity>{at(0.3, -0.25), velocity{0, 0, 0}},
                                        cg::motion_state<pose, velocity>{at(0.5, -0.5), velocity{0, 0, 0}},
                                        cg::motion_state<pose, velocity>{at(0.7, -0.75), velocity{2.0, 0, 0}},
                                        cg::motion_state<pose, velocity>{at(-2.0, -0.5), velocity{0.5, 1.0, 0}});

    constexpr auto hanging = cg::body_step_cost<planar, cg::inertia_kind::sphere, cg::wrench_model::uniform_field<double, planar>>;
    constexpr auto sliding = cg::body_step_cost<planar, cg::inertia_kind::sphere>;
    constexpr auto general = cg::body_step_cost<cg::subspace::full, cg::inertia_kind::general>;
    std::printf("one body step (engine count): hanging puck %zum %zua, free puck %zum %zua; a general 3D body %zum %zua\n",
                std::size_t(hanging.mul), std::size_t(hanging.add), std::size_t(sliding.mul), std::size_t(sliding.add),
                std::size_t(general.mul), std::size_t(general.add));
    std::printf("(plus the springs' point forces for the three chained pucks; the static post costs nothing)\n\n");

    std::printf("   t     puck 1 (x, y)      puck 2 (x, y)      puck 3 (x, y)      free puck (x, y)\n");
    const double h = 1e-3;
    auto x = x0;
    for (int k = 0; k <= 10; ++k) {
        std::printf("%5.2f", k * 0.3);
        cg::for_each_part(x.g, [](const auto& g) {
            const cg::motor_map<double> G = cg::map_of(cg::motor<double>(g));
            std::printf("   (%6.3f, %6.3f)", G.t[0], G.t[1]);
        });
        std::printf("\n");
        const auto run = cg::integrate(cg::lie_rk4{}, world.model(), x, h, 300);
        if (!run) {
            std::printf("stopped: %s\n", cg::describe(run.error));
            return 1;
        }
        x = run.state;
    }
    return 0;
}
