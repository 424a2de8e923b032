// The partials of y = algorithm(m, q, q̇, x) of a kinematic tree by forward-mode dual numbers
// (support/dual.hpp) run through ctga's own code (the scalar type is generic): with respect to q
// (tangent space: a revolute or prismatic q + δ, a floating joint's motor moved in its own frame
// by g exp(δ (ω, v)), seeded to first order as g (1 + δ/2)), q̇ and x (q̈ or τ), `chunk` columns
// per evaluation. y: a std::array of M duals (τ, q̈, or a frame's numbers).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>

#include <ctga/chains/passes.hpp>
#include <ctga/chains/tree.hpp>

#include "support/dual.hpp"
#include <ctga/chains/model_cast.hpp>

namespace ctga::test {

inline constexpr std::size_t chunk = 6;  // partials per dual evaluation
using chunk_dual = ctga_test::dual<chunk>;

// out[w][i][c] = ∂y_i/∂(q, q̇, x)_c for w = 0, 1, 2.
template <class Tree, class Algorithm>
auto dual_partials(const ctga::chains::model<Tree>& m, const ctga::chains::configuration<Tree>& q0, const ctga::chains::joint_vector<Tree>& qd0,
                   const ctga::chains::joint_vector<Tree>& x0, Algorithm algorithm) {
    namespace ch = ctga::chains;
    using D = chunk_dual;
    using Y = decltype(algorithm(std::declval<const ch::model<Tree, D>&>(), std::declval<const ch::configuration<Tree, D>&>(),
                                 std::declval<const ch::joint_vector<Tree, D>&>(), std::declval<const ch::joint_vector<Tree, D>&>()));
    constexpr std::size_t M = std::tuple_size_v<Y>;
    const ch::model<Tree, D> md = ctga::chains::model_cast<D>(m);
    std::array<std::array<std::array<double, Tree::nv>, M>, 3> out{};
    for (std::size_t wrt = 0; wrt < 3; ++wrt)
        for (std::size_t c0 = 0; c0 < Tree::nv; c0 += chunk) {
            // the seed of dof k: partial k − c0 when in this chunk
            const auto seed = [&](std::size_t k, double value) { return k >= c0 && k < c0 + chunk ? D::variable(value, k - c0) : D(value); };
            ch::configuration<Tree, D> q{};
            ch::joint_vector<Tree, D> qd{}, x{};
            for (std::size_t k = 0; k < Tree::nq; ++k) q[k] = D(q0[k]);
            for (std::size_t k = 0; k < Tree::nv; ++k) {
                qd[k] = wrt == 1 ? seed(k, qd0[k]) : D(qd0[k]);
                x[k] = wrt == 2 ? seed(k, x0[k]) : D(x0[k]);
            }
            if (wrt == 0)
                for (std::size_t b = 0; b < Tree::size; ++b) {
                    const std::size_t qo = Tree::q_offset[b], vo = Tree::v_offset[b];
                    const auto delta = [&](std::size_t k) { return seed(k, 0.0); };
                    if (Tree::nq_of[b] == 1) q[qo] = q[qo] + delta(vo);
                    if constexpr (Tree::nq >= 8) {  // (a tree without a floating joint: not compiled)
                        if (Tree::nq_of[b] == 8) {  // g (1 + ½(ω, v)): the motor moved in its own frame
                            const ctga::motor<D> g{q[qo], q[qo + 1], q[qo + 2], q[qo + 3], q[qo + 4], q[qo + 5], q[qo + 6], q[qo + 7]};
                            const ctga::motor<D> e{D(1.0),           delta(vo) * 0.5,     delta(vo + 1) * 0.5, delta(vo + 2) * 0.5,
                                                   D(0.0),           delta(vo + 3) * 0.5, delta(vo + 4) * 0.5, delta(vo + 5) * 0.5};
                            const ctga::motor<D> ge = g * e;
                            for (std::size_t k = 0; k < 8; ++k) q[qo + k] = ge[k];
                        }
                    }
                }
            const Y y = algorithm(md, q, qd, x);
            for (std::size_t i = 0; i < M; ++i)
                for (std::size_t c = c0; c < std::min(c0 + chunk, Tree::nv); ++c)
                    out[wrt][i][c] = ctga_test::derivative(y[i], c - c0);
        }
    return out;
}

}  // namespace ctga::test
