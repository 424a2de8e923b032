// The 7-dof arm of the compile-time cost units (arm7_dynamics.cpp, arm7_derivatives.cpp):
// revolute joints about z, y, z, y, z, y, z, each frame 0.3 m along the last; its model built from
// a run-time number so that nothing is folded away.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <optional>

#include <ctga/ctga.hpp>

namespace ch = ctga::chains;
using arm7 = ch::tree<ch::link<-1, ch::revolute_z>, ch::link<0, ch::revolute_y>, ch::link<1, ch::revolute_z>,
                      ch::link<2, ch::revolute_y>, ch::link<3, ch::revolute_z>, ch::link<4, ch::revolute_y>,
                      ch::link<5, ch::revolute_z>>;

// q = x i, q̇ = x, q̈ = −x for joint i: a state from one run-time number.
struct arm7_state {
    ch::configuration<arm7> q{};
    ch::joint_vector<arm7> qd{}, qdd{};
    explicit arm7_state(double x) {
        for (std::size_t i = 0; i < 7; ++i) q[i] = x * static_cast<double>(i), qd[i] = x, qdd[i] = -x;
    }
};

inline std::optional<ch::model<arm7>> arm7_model() {
    ch::model<arm7> m;
    bool ok = true;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ([&] {
            const auto link = ch::make_link<arm7::joint_at<I>>(
                ctga::rigid_motion(ctga::make_translator(0.0, 0.0, I == 0 ? 0.0 : 0.3), ctga::make_rotor(0.0, 0.0, 0.0, 1.0)),
                ctga::make_mass_properties(2.0 - 0.2 * I, ctga::vec3<double>{0.01, 0.0, 0.15},
                                           ctga::mat3<double>{{{0.02, 0.001, 0.0}, {0.001, 0.02, 0.0}, {0.0, 0.0, 0.005}}}));
            ok = ok && link;
            if (link) m.link<I>() = *link;
        }(), ...);
    }(std::make_index_sequence<arm7::size>{});
    if (!ok) return std::nullopt;
    return m;
}
