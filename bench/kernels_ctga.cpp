// The operations through ctga: the paper's formulas on the library's types.
#include "kernels.hpp"

namespace bench {

using namespace ctga;

// N by its ten parameters (body_inertia, mechanics/body_inertia.hpp): the same element and the same 24m 18a as the
// 24-blade rigid_inertia, reading ten numbers
coscrew<> momentum(const ctga_inputs& in) { return ctga::momentum(in.N, in.s); }
double energy(const ctga_inputs& in) { return kinetic_energy(in.N, in.s); }
screw<> bracket(const ctga_inputs& in) { return ctga::bracket(in.s, in.s2); }
coscrew<> coadjoint(const ctga_inputs& in) { return ctga::coadjoint(in.s, in.P); }
motor<> motor_product(const ctga_inputs& in) { return in.g * in.g2; }
screw<> screw_transform(const ctga_inputs& in) { return transform(in.G, in.s); }
coscrew<> coscrew_transform(const ctga_inputs& in) { return transform(in.G, in.P); }
body_inertia<> inertia_transform(const ctga_inputs& in) { return transform(in.G, in.N); }
screw<> eom(const ctga_inputs& in) { return acceleration(in.body, in.s, in.W); }

state step(const ctga_inputs& in) {
    state x;
    for (std::size_t i = 0; i < 8; ++i) x[i] = in.g[i];
    for (std::size_t i = 0; i < 6; ++i) x[8 + i] = in.s[i];
    return rk4(x, step_size, [&](const state& y) {
        motor<> g;
        screw<> s;
        for (std::size_t i = 0; i < 8; ++i) g[i] = y[i];
        for (std::size_t i = 0; i < 6; ++i) s[i] = y[8 + i];
        const state_rate<> r = body_frame_rates(in.body, g, s, in.W);
        state d;
        for (std::size_t i = 0; i < 8; ++i) d[i] = r.g_dot[i];
        for (std::size_t i = 0; i < 6; ++i) d[8 + i] = r.s_dot[i];
        return d;
    });
}

}  // namespace bench
