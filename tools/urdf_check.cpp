// The checker of tools/urdf_check.py: one robot header from tools/urdf_to_ctga.py (included as
// CTGA_ROBOT_HEADER, namespace CTGA_ROBOT), its model and its joint limits built (make_model,
// make_limits: limits=yes when check_limits accepts them), and the self-consistency of the
// dynamics at random states (a fixed seed), printed as one line of key=value pairs:
//   round_trip   max over states of |ABA(q, q̇, RNEA(q, q̇, q̈)) − q̈| / |q̈|: ABA's forward error,
//                which an ill-conditioned H (iCub: κ 3.5e12) makes as large as κ ε, in any algorithm
//   residual     |RNEA(q, q̇, q̈) − τ| / (|τ| + |H| |q̈|) at q̈ = ABA(q, q̇, τ): ABA's backward error,
//                rounding whatever the conditioning (what the check passes on, with the next four)
//   split        |H q̈ + C − τ| / |τ|, H from CRBA, C = RNEA(q, q̇, 0)
//   spd          whether H is symmetric (|H − Hᵀ| / |H| ≤ 1e-12) and Cholesky factors it
//   power        |dE/dt − q̇ᵀτ| at q̈ = ABA(τ), over the sum of the magnitudes of its terms: dE/dt =
//                Σ v_i·(N_i a_i) − M g·ċ (the bodies' kinetic energy rate from their true
//                accelerations, plus Σ a_k q̇_k q̈_k of the joints' armatures, the potential's from
//                the centre of mass's velocity), an identity no algorithm shares with ABA
//   aba_ld       |ABA(τ) − ABA_ld(τ)| / |ABA_ld(τ)|, ABA_ld the same model in long double (its
//                inertias built in long double from the file's numbers, its placements and axes
//                those of the double model): the accuracy of the double evaluation (not checked)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <type_traits>

#include <ctga/chains/model_cast.hpp>

#include CTGA_ROBOT_HEADER

namespace ch = ctga::chains;
namespace robot = CTGA_ROBOT;
using tree = robot::tree;

template <class V>
double norm(const V& x) {
    double s = 0;
    for (double c : x) s += c * c;
    return std::sqrt(s);
}

// The larger of a running maximum and x, a NaN counting as the worst (std::max would drop it: the
// check must not pass on NaN results).
double worst(double so_far, double x) { return std::isnan(x) || std::isnan(so_far) ? NAN : std::max(so_far, x); }

int main() {
    const auto built = robot::make_model<double>();
    if (!built) {
        std::printf("error=%s\n", ctga::describe(built.error));
        return 1;
    }
    const ch::model<tree> m = *built;
    const bool limits = static_cast<bool>(robot::make_limits<double>());
    const auto armature = ch::armature_by_dof(m);  // 0 but for the joints declared with_armature
    // the same model in long double: inertias from the file's numbers, placements and axes cast.
    // make_model<long double> checks at long double's precision and may refuse a placement or an
    // axis that double's accepted to its rounding (romeo_laas_small): then the double model, cast
    // (ld_model says which; the refusal goes to stderr)
    const auto built_ld = robot::make_model<long double>();
    ch::model<tree, long double> exact = built_ld ? *built_ld : ch::model_cast<long double>(m);
    std::printf("ld_model=%s\n", built_ld ? "file" : "cast");
    if (!built_ld) std::fprintf(stderr, "long double model refused: %s\n", ctga::describe(built_ld.error));
    const ch::model<tree, long double> cast = ch::model_cast<long double>(m);
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ((exact.template link<I>().placement = cast.template link<I>().placement,
          exact.template link<I>().joint = cast.template link<I>().joint), ...);
    }(std::make_index_sequence<tree::size>{});
    std::mt19937_64 rng(2027);
    std::uniform_real_distribution<double> u(-1, 1);
    double round_trip = 0, residual = 0, split = 0, power = 0, asym = 0, aba_ld = 0;
    bool spd = true;
    for (int trial = 0; trial < 20; ++trial) {
        ch::configuration<tree> q{};
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            ([&] {
                using J = typename tree::template joint_at<I>;
                constexpr std::size_t o = tree::q_offset[I];
                if constexpr (J::nq == 8) {  // floating (aligned or not): a motor
                    const auto g = ctga::rigid_motion(ctga::make_translator(u(rng), u(rng), u(rng)),
                                                      ctga::make_rotor(3 * u(rng), u(rng), u(rng), 1.0));
                    for (std::size_t k = 0; k < 8; ++k) q[o + k] = g[k];
                } else if constexpr (J::nq == 1) {
                    q[o] = 1.5 * u(rng);
                }
            }(), ...);
        }(std::make_index_sequence<tree::size>{});
        ch::joint_vector<tree> qd{}, qdd{};
        for (std::size_t k = 0; k < tree::nv; ++k) qd[k] = u(rng), qdd[k] = 2 * u(rng);
        const auto tau = ch::rnea(m, q, qd, qdd);
        const auto back = ch::aba(m, q, qd, tau);
        ch::joint_vector<tree> d{};
        for (std::size_t k = 0; k < tree::nv; ++k) d[k] = back[k] - qdd[k];
        round_trip = worst(round_trip, norm(d) / norm(qdd));
        const auto H = ch::crba(m, q);
        const auto C = ch::rnea(m, q, qd, ch::joint_vector<tree>{});
        double hn = 0, an = 0;
        for (std::size_t r = 0; r < tree::nv; ++r) {
            double x = C[r] - tau[r];
            for (std::size_t c = 0; c < tree::nv; ++c) {
                x += H[r][c] * qdd[c];
                hn += H[r][c] * H[r][c];
                an += (H[r][c] - H[c][r]) * (H[r][c] - H[c][r]);
            }
            d[r] = x;
        }
        split = worst(split, norm(d) / norm(tau));
        asym = worst(asym, std::sqrt(an / hn));
        spd = spd && static_cast<bool>(ctga::cholesky(H));
        // at q̈ = ABA(τ) for a random τ: the residual, the power, the long double evaluation
        ch::joint_vector<tree> tau2{};
        for (std::size_t k = 0; k < tree::nv; ++k) tau2[k] = 5 * u(rng);
        const auto a2 = ch::aba(m, q, qd, tau2);
        const auto tau_back = ch::rnea(m, q, qd, a2);
        for (std::size_t r = 0; r < tree::nv; ++r) d[r] = tau_back[r] - tau2[r];
        residual = worst(residual, norm(d) / (norm(tau2) + std::sqrt(hn) * norm(a2)));
        const auto k = ch::forward_kinematics(m, q, qd, a2);
        double dT = 0, scale = 0;
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            ([&] {
                const double x = ctga::pairing(ctga::momentum(m.template link<I>().inertia, k.a[I]), k.v[I]);
                dT += x, scale += std::abs(x);
            }(), ...);
        }(std::make_index_sequence<tree::size>{});
        for (std::size_t i = 0; i < tree::nv; ++i) dT += armature[i] * qd[i] * a2[i], scale += std::abs(armature[i] * qd[i] * a2[i]);
        const auto com = ch::center_of_mass(m, k);
        const double dV = -com.mass * (m.gravity[0] * com.velocity[0] + m.gravity[1] * com.velocity[1] + m.gravity[2] * com.velocity[2]);
        double P = 0;
        for (std::size_t i = 0; i < tree::nv; ++i) P += qd[i] * tau2[i], scale += std::abs(qd[i] * tau2[i]);
        power = worst(power, std::abs(dT + dV - P) / (scale + std::abs(dV)));
        ch::configuration<tree, long double> ql{};
        ch::joint_vector<tree, long double> qdl{}, taul{};
        std::copy(q.begin(), q.end(), ql.begin());
        std::copy(qd.begin(), qd.end(), qdl.begin());
        std::copy(tau2.begin(), tau2.end(), taul.begin());
        const auto a_ld = ch::aba(exact, ql, qdl, taul);
        long double e = 0, n = 0;
        for (std::size_t i = 0; i < tree::nv; ++i)
            e += (a2[i] - a_ld[i]) * (a2[i] - a_ld[i]), n += a_ld[i] * a_ld[i];
        aba_ld = worst(aba_ld, static_cast<double>(std::sqrt(e / n)));
    }
    std::printf("bodies=%zu frames=%zu nq=%zu nv=%zu mimic=%d mass=%.6g limits=%s round_trip=%.1e residual=%.1e "
                "split=%.1e spd=%s asym=%.1e power=%.1e aba_ld=%.1e\n",
                tree::size, tree::frame_count, tree::nq, tree::nv, int(tree::has_mimic),
                ch::center_of_mass(m, ch::forward_kinematics(m, ch::configuration<tree>{})).mass, limits ? "yes" : "no",
                round_trip, residual, split, spd ? "yes" : "no", asym, power, aba_ld);
    return limits && residual <= 1e-12 && split <= 1e-10 && spd && asym <= 1e-12 && power <= 1e-10 ? 0 : 2;
}
