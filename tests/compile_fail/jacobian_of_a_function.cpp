// EXPECT: differentiates a formula
// A plain function (here ctga::exp of a screw: not a polynomial, not a formula) has no
// compile-time derivative: ctga::jacobian names what it takes instead of a silent wrong answer.
#include <ctga/ctga.hpp>
#include <ctga/operations/jacobian.hpp>

int main() {
    const ctga::screw<double> s{0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
    const auto J = ctga::jacobian<0>([](const ctga::screw<double>& x) { return ctga::exp(x); }, s);
    return J(0, 0) > 0;
}
