// The paper's momentum and Lie bracket compiled two ways: through ctga, and hand-written on 6-vectors
// (ω, v) / (l, p) with the 6×6 inertia of §2. check.sh counts the instructions of each function
// in the object file (objdump) and requires ctga's within 1.5× of the hand-written code. And RNEA
// called through its algorithm object (chains/arguments.hpp) and through its overload set, whose
// counts must be equal: the object adds nothing to a call.
#include <ctga/ctga.hpp>

using G = ctga::cl062;
using screw = G::mv<double, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e">;   // (ω, v)
using coscrew = G::mv<double, "a1a", "a2a", "a3a", "a2a3", "a3a1", "a1a2">;  // (l, p)
// row i of the 6×6 inertia: the co-screw direction; column j: the screw direction
using inertia = G::mv<double, "a1ae2e3", "a1ae3e1", "a1ae1e2", "a1ae1e", "a1ae2e", "a1ae3e", "a2ae2e3", "a2ae3e1",
                      "a2ae1e2", "a2ae1e", "a2ae2e", "a2ae3e", "a3ae2e3", "a3ae3e1", "a3ae1e2", "a3ae1e", "a3ae2e",
                      "a3ae3e", "a2a3e2e3", "a2a3e3e1", "a2a3e1e2", "a2a3e1e", "a2a3e2e", "a2a3e3e", "a3a1e2e3",
                      "a3a1e3e1", "a3a1e1e2", "a3a1e1e", "a3a1e2e", "a3a1e3e", "a1a2e2e3", "a1a2e3e1", "a1a2e1e2",
                      "a1a2e1e", "a1a2e2e", "a1a2e3e">;
using screw4 = ctga::cl031::mv<double, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e">;

constexpr auto momentum = ctga::formula([](auto N, auto s) { return G::basis<"a1a2a3a"> & (N ^ s); });
constexpr auto lie_bracket = ctga::formula([](auto a, auto b) { return ctga::half * (a * b - b * a); });

extern "C" {

[[gnu::noinline]] void ctga_momentum(const inertia& N, const screw& s, coscrew& P) { P = momentum(N, s); }

// P = N6 s, written out as hand-written spatial code does (straight-line, 36m 30a)
[[gnu::noinline]] void hand_momentum(const double (&N)[36], const double (&s)[6], double (&P)[6]) {
    P[0] = N[0] * s[0] + N[1] * s[1] + N[2] * s[2] + N[3] * s[3] + N[4] * s[4] + N[5] * s[5];
    P[1] = N[6] * s[0] + N[7] * s[1] + N[8] * s[2] + N[9] * s[3] + N[10] * s[4] + N[11] * s[5];
    P[2] = N[12] * s[0] + N[13] * s[1] + N[14] * s[2] + N[15] * s[3] + N[16] * s[4] + N[17] * s[5];
    P[3] = N[18] * s[0] + N[19] * s[1] + N[20] * s[2] + N[21] * s[3] + N[22] * s[4] + N[23] * s[5];
    P[4] = N[24] * s[0] + N[25] * s[1] + N[26] * s[2] + N[27] * s[3] + N[28] * s[4] + N[29] * s[5];
    P[5] = N[30] * s[0] + N[31] * s[1] + N[32] * s[2] + N[33] * s[3] + N[34] * s[4] + N[35] * s[5];
}

[[gnu::noinline]] void ctga_bracket(const screw4& a, const screw4& b, screw4& r) { r = lie_bracket(a, b); }

// (ω1 × ω2, ω1 × v2 − ω2 × v1)
[[gnu::noinline]] void hand_bracket(const double (&a)[6], const double (&b)[6], double (&r)[6]) {
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
    r[3] = a[1] * b[5] - a[2] * b[4] - (b[1] * a[5] - b[2] * a[4]);
    r[4] = a[2] * b[3] - a[0] * b[5] - (b[2] * a[3] - b[0] * a[5]);
    r[5] = a[0] * b[4] - a[1] * b[3] - (b[0] * a[4] - b[1] * a[3]);
}

// on an arm of three revolute joints
using arm = ctga::chains::tree<ctga::chains::link<-1, ctga::chains::revolute_z>, ctga::chains::link<0, ctga::chains::revolute_y>,
                               ctga::chains::link<1, ctga::chains::revolute_y>>;
using arm_vector = ctga::chains::joint_vector<arm>;

[[gnu::noinline]] void object_rnea(const ctga::chains::model<arm>& m, const arm_vector& q, const arm_vector& qd,
                                   const arm_vector& qdd, arm_vector& tau) {
    tau = ctga::chains::rnea(m, q, qd, qdd);
}
[[gnu::noinline]] void overloads_rnea(const ctga::chains::model<arm>& m, const arm_vector& q, const arm_vector& qd,
                                      const arm_vector& qdd, arm_vector& tau) {
    tau = ctga::chains::rnea_t{}(m, q, qd, qdd);
}
}
