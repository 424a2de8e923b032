// The operations hand-written on 6D spatial vectors (spatial.hpp), as without ctga.
#include "kernels.hpp"

namespace bench {

using namespace spatial;

force momentum(const spatial_inputs& in) { return in.Y * in.s; }
double energy(const spatial_inputs& in) { return kinetic_energy(in.Y, in.s); }
motion bracket(const spatial_inputs& in) { return cross(in.s, in.s2); }
force coadjoint(const spatial_inputs& in) { return cross(in.s, in.P); }
dual_quaternion motor_product(const spatial_inputs& in) { return in.g * in.g2; }
motion screw_transform(const spatial_inputs& in) { return act(in.X, in.s); }
force coscrew_transform(const spatial_inputs& in) { return act(in.X, in.P); }
inertia inertia_transform(const spatial_inputs& in) { return act(in.X, in.Y); }
motion eom(const spatial_inputs& in) { return acceleration(in.Y, in.Z, in.s, in.W); }

state step(const spatial_inputs& in) {
    state x;
    for (int i = 0; i < 4; ++i) x[static_cast<std::size_t>(i)] = in.g.r[i], x[static_cast<std::size_t>(4 + i)] = in.g.d[i];
    x[8] = in.s.w.x, x[9] = in.s.w.y, x[10] = in.s.w.z, x[11] = in.s.v.x, x[12] = in.s.v.y, x[13] = in.s.v.z;
    return rk4(x, step_size, [&](const state& y) {
        const dual_quaternion g{{y[0], y[1], y[2], y[3]}, {y[4], y[5], y[6], y[7]}};
        const motion s{{y[8], y[9], y[10]}, {y[11], y[12], y[13]}};
        const dual_quaternion gd = pose_rate(g, s);
        const motion sd = acceleration(in.Y, in.Z, s, in.W);
        return state{gd.r[0], gd.r[1], gd.r[2], gd.r[3], gd.d[0], gd.d[1], gd.d[2], gd.d[3],
                     sd.w.x,  sd.w.y,  sd.w.z,  sd.v.x,  sd.v.y,  sd.v.z};
    });
}

}  // namespace bench
