// The operations in the 6×6 matrix formalism of §2, with Eigen's fixed-size types.
#include "kernels.hpp"

namespace bench {

namespace {
using v3 = Eigen::Vector3d;
// Featherstone's crm(s) s2 and crf(s) P, through 3-vector cross products
vec6 motion_cross(const vec6& a, const vec6& b) {
    vec6 out;
    out << a.head<3>().cross(b.head<3>()), a.head<3>().cross(b.tail<3>()) + a.tail<3>().cross(b.head<3>());
    return out;
}
vec6 force_cross(const vec6& a, const vec6& F) {
    vec6 out;
    out << a.head<3>().cross(F.head<3>()) + a.tail<3>().cross(F.tail<3>()), a.head<3>().cross(F.tail<3>());
    return out;
}
Eigen::Quaterniond pure(const v3& v) { return Eigen::Quaterniond(0, v.x(), v.y(), v.z()); }
}  // namespace

vec6 momentum(const eigen_inputs& in) { return in.N * in.s; }
double energy(const eigen_inputs& in) { return 0.5 * in.s.dot(in.N * in.s); }
vec6 bracket(const eigen_inputs& in) { return motion_cross(in.s, in.s2); }
vec6 coadjoint(const eigen_inputs& in) { return force_cross(in.s, in.P); }
eigen_dual_quaternion motor_product(const eigen_inputs& in) {
    eigen_dual_quaternion out;
    out.real = in.g_real * in.g2_real;
    out.dual.coeffs() = (in.g_real * in.g2_dual).coeffs() + (in.g_dual * in.g2_real).coeffs();
    return out;
}
vec6 screw_transform(const eigen_inputs& in) { return in.H * in.s; }
vec6 coscrew_transform(const eigen_inputs& in) { return in.H_inverse_transpose * in.P; }
mat6 inertia_transform(const eigen_inputs& in) {
    return in.H_inverse_transpose * in.N * in.H_inverse_transpose.transpose();
}
vec6 eom(const eigen_inputs& in) { return in.N_inverse * (in.W - force_cross(in.s, in.N * in.s)); }

state step(const eigen_inputs& in) {
    state x;
    x[0] = in.g_real.w(), x[1] = in.g_real.x(), x[2] = in.g_real.y(), x[3] = in.g_real.z();
    x[4] = in.g_dual.w(), x[5] = in.g_dual.x(), x[6] = in.g_dual.y(), x[7] = in.g_dual.z();
    for (int i = 0; i < 6; ++i) x[static_cast<std::size_t>(8 + i)] = in.s[i];
    return rk4(x, step_size, [&](const state& y) {
        const Eigen::Quaterniond r(y[0], y[1], y[2], y[3]), d(y[4], y[5], y[6], y[7]);
        const vec6 s = Eigen::Map<const vec6>(y.data() + 8);
        // dg/dt = ½ g s_b: real ½ r ω, dual ½ (r v + d ω)
        const Eigen::Quaterniond w = pure(s.head<3>()), v = pure(s.tail<3>());
        const Eigen::Vector4d rd = 0.5 * (r * w).coeffs(), dd = 0.5 * ((r * v).coeffs() + (d * w).coeffs());
        const vec6 sd = in.N_inverse * (in.W - force_cross(s, in.N * s));
        return state{rd[3], rd[0], rd[1], rd[2], dd[3], dd[0], dd[1], dd[2], sd[0], sd[1], sd[2], sd[3], sd[4], sd[5]};
    });
}

}  // namespace bench
