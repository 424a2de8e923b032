// EXPECT: ctga: unknown blade name
// basis<Name> with a name that is not a blade of the algebra (Cl(0,6,2) has no a4: "a1a2a3a4"
// reads a1 a2 a3 a, then 4) is refused where the constant is declared, not only once it is used
// in an expression.
#include <ctga/core.hpp>
#include <ctga/mechanics/algebras.hpp>

constexpr auto bad = ctga::cl062::basis<"a1a2a3a4">;

int main() { return 0; }
