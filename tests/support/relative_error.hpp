// Relative differences of a result against an Eigen reference: max |a − b| / max(1, max |b|),
// for anything indexable a[i] (a joint vector, a screw) and a[i][j] (a joint-space matrix).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <Eigen/Core>

namespace ctga::test {

template <class A, class B>
double rel_error(const A& a, const Eigen::MatrixBase<B>& b) {
    double e = 0, s = 1;
    for (Eigen::Index i = 0; i < b.rows(); ++i)
        for (Eigen::Index j = 0; j < b.cols(); ++j) {
            double x;
            if constexpr (B::ColsAtCompileTime == 1) x = a[static_cast<std::size_t>(i)];  // a vector
            else x = a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
            e = std::max(e, std::abs(x - b(i, j)));
            s = std::max(s, std::abs(b(i, j)));
        }
    return e / s;
}

}  // namespace ctga::test
