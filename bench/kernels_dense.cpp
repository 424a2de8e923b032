// The operations in the naive dense reference: every product visits all 256 × 256 blade pairs
// of Cl(0,6,2), as an implementation without compile-time sparsity would.
#include "kernels.hpp"

namespace bench {

namespace {
using namespace ctga::dense;
const dense_mv A = dense_mv::blade("a1a2a3a");
const dense_mv E = dense_mv::blade("e1e2e3e");

dense_mv commutator_half(const dense_mv& x, const dense_mv& y) { return 0.5 * (gp(x, y) - gp(y, x)); }
dense_mv sandwich(const dense_mv& h, const dense_mv& x) { return gp(gp(h, x), conjugate(h)); }
dense_mv acceleration(const dense_mv& N, const dense_mv& M, const dense_mv& s, const dense_mv& W) {
    const dense_mv P = shuffle(A, wedge(N, s));
    return shuffle(E, wedge(M, W - commutator_half(bar(s), P)));
}

// the state's motor and screw as dense elements of Cl(0,6,2), and back (the e-half, §5)
constexpr auto motor_layout = decltype(ctga::eval(ctga::lift(ctga::motor<>{})))::layout;
constexpr auto screw_layout = decltype(ctga::eval(ctga::lift(ctga::screw<>{})))::layout;
template <auto L>
dense_mv from_state(const state& x, std::size_t first) {
    dense_mv out;
    for (std::size_t i = 0; i < L.size(); ++i) out[L.masks[i]] = L.signs[i] * x[first + i];
    return out;
}
template <auto L>
void to_state(const dense_mv& m, state& x, std::size_t first) {
    for (std::size_t i = 0; i < L.size(); ++i) x[first + i] = L.signs[i] * m[L.masks[i]];
}
}  // namespace

dense_mv momentum(const dense_inputs& in) { return shuffle(A, wedge(in.N, in.s)); }
double energy(const dense_inputs& in) { return 0.5 * shuffle(bar(in.s), wedge(in.N, in.s))[0]; }
dense_mv bracket(const dense_inputs& in) { return commutator_half(in.s, in.s2); }
dense_mv coadjoint(const dense_inputs& in) { return commutator_half(bar(in.s), in.P); }
dense_mv motor_product(const dense_inputs& in) { return gp(in.g, in.g2); }
dense_mv screw_transform(const dense_inputs& in) { return sandwich(in.g, in.s); }
dense_mv coscrew_transform(const dense_inputs& in) { return sandwich(in.g_bar, in.P); }
dense_mv inertia_transform(const dense_inputs& in) { return sandwich(gp(in.g, in.g_bar), in.N); }
dense_mv eom(const dense_inputs& in) { return acceleration(in.N, in.M, in.s, in.W); }

state step(const dense_inputs& in) {
    state x;
    to_state<motor_layout>(in.g, x, 0);
    to_state<screw_layout>(in.s, x, 8);
    return rk4(x, step_size, [&](const state& y) {
        const dense_mv g = from_state<motor_layout>(y, 0), s = from_state<screw_layout>(y, 8);
        state d;
        to_state<motor_layout>(0.5 * gp(g, s), d, 0);
        to_state<screw_layout>(acceleration(in.N, in.M, s, in.W), d, 8);
        return d;
    });
}

}  // namespace bench
