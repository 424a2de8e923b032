// Relative differences of a result against a reference: max |a − b| / max(1, max |b|), b the
// independent value. rel_error takes anything indexable a[i] (a joint vector, a screw) and a[i][j]
// (a joint-space matrix) against an Eigen reference; rel takes two Eigen matrices (infinite when
// their shapes differ, so the check that uses it fails) or two numbers.
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

inline double rel(const Eigen::MatrixXd& x, const Eigen::MatrixXd& y) {
    if (x.rows() != y.rows() || x.cols() != y.cols()) return INFINITY;
    if (y.size() == 0) return 0;
    return (x - y).cwiseAbs().maxCoeff() / std::max(1.0, y.cwiseAbs().maxCoeff());
}
inline double rel(double x, double y) { return std::abs(x - y) / std::max(1.0, std::abs(y)); }

}  // namespace ctga::test
