// EXPECT: refuse_unknown<ctga::expr::walker::relabel, [^>]*negated.*not a node kind|not a node kind.*refuse_unknown<ctga::expr::walker::relabel, [^>]*negated
// A node kind added to the engine without its node_shape (expr/nodes.hpp): the first walker that
// meets it (here relabel, which renumbers the right operand's leaves of a combination) stops with
// a compile error naming itself and the type, instead of passing the node through unchanged.
#include <ctga/core.hpp>

namespace {
template <class X>
struct negated {};  // a new node kind, not described by a node_shape
}  // namespace

int main() {
    constexpr ctga::layout<1> scalar{{0}, {1}};
    using tree = ctga::expr::sum<negated<ctga::expr::leaf<0, scalar>>, ctga::expr::leaf<1, scalar>, 1>;
    using shifted = ctga::expr::shift_t<tree, 2>;
    return sizeof(shifted) == 0;
}
