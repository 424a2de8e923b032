// Compile-only (tests/CMakeLists.txt builds it once per x86-64 level: -march=x86-64, x86-64-v3,
// x86-64-v4, with the project's warnings as errors): support/pack.hpp picks its instructions by
// the target's macros (__SSE2__, __AVX__, __AVX512F__), so each level compiles other code; a level
// the developer's machine lacks is still checked here. Every width of float and double: arithmetic,
// masks, select, √, cos and sin, a motor's exponential; and ABA on a small tree, eight robots at once.
#include <array>
#include <cstddef>

#include <ctga/chains/aba.hpp>
#include <ctga/chains/model_cast.hpp>
#include <ctga/mechanics/motor.hpp>
#include <ctga/support/math.hpp>
#include <ctga/support/pack.hpp>

namespace ch = ctga::chains;

template <class T, std::size_t L>
ctga::pack<T, L> exercise(const ctga::pack<T, L>& x, const ctga::pack<T, L>& y) {
    using P = ctga::pack<T, L>;
    const P s = ctga::math::sqrt(x * x + y * y);
    const auto cs = ctga::cos_sin(x);
    const P r = ctga::select(ctga::finite_lanes(s) && x < y, s - cs.cos, cs.sin / (y + P(T(2))));
    const ctga::screw<P> v{x, y, s, r, cs.cos, cs.sin};
    const ctga::motor<P> g(ctga::exp(v));
    return ctga::any(r > P(T(0))) ? r + g[0] : ctga::abs(r) * g[7];
}

template <class T, std::size_t L>
void instantiate(ctga::pack<T, L>* out, const ctga::pack<T, L>* in) {
    out[0] = exercise<T, L>(in[0], in[1]);
}

template void instantiate<float, 2>(ctga::pack<float, 2>*, const ctga::pack<float, 2>*);
template void instantiate<float, 4>(ctga::pack<float, 4>*, const ctga::pack<float, 4>*);
template void instantiate<float, 8>(ctga::pack<float, 8>*, const ctga::pack<float, 8>*);
template void instantiate<double, 2>(ctga::pack<double, 2>*, const ctga::pack<double, 2>*);
template void instantiate<double, 4>(ctga::pack<double, 4>*, const ctga::pack<double, 4>*);
template void instantiate<double, 8>(ctga::pack<double, 8>*, const ctga::pack<double, 8>*);

using arm = ch::tree<ch::link<-1, ch::floating>, ch::link<0, ch::revolute_z>, ch::link<1, ch::aligned<ch::revolute_y>>>;

// ABA of eight robots in one pack: q̈ for the lanes' q, q̇, τ.
ch::joint_vector<arm, ctga::pack<double, 8>> aba_in_lanes(const ch::model<arm>& m,
                                                         const ch::configuration<arm, ctga::pack<double, 8>>& q,
                                                         const ch::joint_vector<arm, ctga::pack<double, 8>>& qd,
                                                         const ch::joint_vector<arm, ctga::pack<double, 8>>& tau) {
    return ch::aba(ch::model_cast<ctga::pack<double, 8>>(m), q, qd, tau);
}
