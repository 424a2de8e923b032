// Random inputs, the same physical values for every implementation: a rigid body with a box's
// principal moments turned by a random rotation and its centre of mass off the origin, poses,
// velocities, co-screws and wrenches.
#include <cmath>
#include <random>

#include "kernels.hpp"

namespace bench {

namespace {

spatial::vec3 v3(double x, double y, double z) { return {x, y, z}; }
spatial::motion to_spatial(const ctga::screw<>& s) { return {v3(s[0], s[1], s[2]), v3(s[3], s[4], s[5])}; }
spatial::force to_spatial(const ctga::coscrew<>& P) { return {v3(P[0], P[1], P[2]), v3(P[3], P[4], P[5])}; }
spatial::dual_quaternion to_spatial(const ctga::motor<>& g) { return {{g[0], g[1], g[2], g[3]}, {g[4], g[5], g[6], g[7]}}; }
spatial::sym3 to_sym3(const ctga::mat3<double>& I) { return {I[0][0], I[0][1], I[1][1], I[0][2], I[1][2], I[2][2]}; }
vec6 to_eigen(const ctga::vec6<double>& x) { return Eigen::Map<const vec6>(x.data()); }
mat6 to_eigen(const ctga::mat6<double>& m) {
    mat6 out;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) out(i, j) = m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    return out;
}
Eigen::Quaterniond real_part(const ctga::motor<>& g) { return {g[0], g[1], g[2], g[3]}; }
Eigen::Quaterniond dual_part(const ctga::motor<>& g) { return {g[4], g[5], g[6], g[7]}; }

}  // namespace

input_batches make_inputs(std::size_t n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    const auto unit = [&] {
        double x = u(rng), y = u(rng), z = u(rng);
        const double r = std::sqrt(x * x + y * y + z * z);
        return std::array<double, 3>{x / r, y / r, z / r};
    };
    const auto pose = [&] {
        const auto a = unit();
        return ctga::motor<>(ctga::rigid_motion(ctga::make_translator(2 * u(rng), 2 * u(rng), 2 * u(rng)),
                                                ctga::make_rotor(3 * u(rng), a[0], a[1], a[2])));
    };
    const auto screw = [&] { return ctga::screw<>{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)}; };
    const auto coscrew = [&] { return ctga::coscrew<>{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)}; };

    input_batches out;
    for (std::size_t k = 0; k < n; ++k) {
        // the body: a box of sides a, b, c and mass m, turned by a random rotation
        const double m = 2 + u(rng), a = 1.2 + u(rng), b = 1.2 + u(rng), c = 1.2 + u(rng);
        const double d[3] = {m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12};
        const ctga::motor_map<> turn = ctga::map_of(pose());
        ctga::mat3<double> I{};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                for (int l = 0; l < 3; ++l) I[i][j] += turn.R[i][l] * d[l] * turn.R[j][l];
        const ctga::vec3<double> com{0.3 * u(rng), 0.3 * u(rng), 0.3 * u(rng)};
        const auto body = ctga::make_rigid_body(m, com, I);
        const ctga::motor<> g = pose(), g2 = pose();
        const ctga::screw<> s = screw(), s2 = screw();
        const ctga::coscrew<> P = coscrew(), W = coscrew();
        const ctga::motor_map<> G = ctga::map_of(g);

        out.ctga.push_back({*body, ctga::body_inertia_of(body->properties), g, g2, G, s, s2, P, W});

        const ctga::mat3<double> J = ctga::linear3::inverse_symmetric(body->properties.inertia_c);
        spatial::se3 X{{v3(G.R[0][0], G.R[0][1], G.R[0][2]), v3(G.R[1][0], G.R[1][1], G.R[1][2]),
                        v3(G.R[2][0], G.R[2][1], G.R[2][2])},
                       v3(G.t[0], G.t[1], G.t[2])};
        out.spatial.push_back({{m, v3(com[0], com[1], com[2]), to_sym3(body->properties.inertia_c)},
                               {1 / m, v3(com[0], com[1], com[2]), to_sym3(J)},
                               to_spatial(g), to_spatial(g2), X, to_spatial(s), to_spatial(s2), to_spatial(P),
                               to_spatial(W)});

        const mat6 N = to_eigen(ctga::inertia_matrix(body->N));
        mat6 H = mat6::Zero(), Hit = mat6::Zero();
        Eigen::Matrix3d R, T;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) R(i, j) = G.R[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
        T << 0, -G.t[2], G.t[1], G.t[2], 0, -G.t[0], -G.t[1], G.t[0], 0;
        H.topLeftCorner<3, 3>() = R;
        H.bottomRightCorner<3, 3>() = R;
        H.bottomLeftCorner<3, 3>() = T * R;
        Hit.topLeftCorner<3, 3>() = R;
        Hit.bottomRightCorner<3, 3>() = R;
        Hit.topRightCorner<3, 3>() = T * R;
        out.eigen.push_back({N, N.inverse(), H, Hit, real_part(g), dual_part(g), real_part(g2), dual_part(g2),
                             to_eigen(ctga::to_vector6(s)), to_eigen(ctga::to_vector6(s2)),
                             to_eigen(ctga::to_vector6(P)), to_eigen(ctga::to_vector6(W))});

        using ctga::dense::to_dense;
        const auto gl = ctga::eval(ctga::lift(g));
        out.dense.push_back({to_dense(body->N), to_dense(body->M), to_dense(gl), to_dense(ctga::eval(ctga::lift(g2))),
                             ctga::dense::bar(to_dense(gl)), to_dense(ctga::eval(ctga::lift(s))), to_dense(ctga::eval(ctga::lift(s2))),
                             to_dense(P), to_dense(W)});
    }
    return out;
}

}  // namespace bench
