// ctga_chains_bench's kernels of one real robot as its URDF comes: the header
// tools/urdf_to_ctga.py writes at build time (cmake: ctga_urdf_header, CTGA_BENCH_ROBOTS_DIR),
// compiled once per robot with -DCTGA_ROBOT=<name>, CTGA_ROBOT_NAME and CTGA_ROBOT_HEADER (its name
// as a string, "<name>.hpp") and registered
// as rnea_<name>/ctga, aba_<name>/ctga, crba_<name>/ctga, rnea_derivatives_<name>/ctga,
// aba_derivatives_<name>/ctga, minverse_<name>/ctga (the derivatives' max_error against long-double
// dual numbers, as the benchmark trees'). No hand-written spatial rows: its models are the
// benchmark trees' descriptions (chain_models.hpp), not URDF files.
#include <cstdio>
#include <cstdlib>

#include CTGA_ROBOT_HEADER

#include "chains_derivatives.hpp"

namespace bench::chains {
namespace {
using robot_tree = CTGA_ROBOT::tree;
constexpr const char* robot_name = CTGA_ROBOT_NAME;  // (CMake: the robot's name as a string)

void add_robot(std::vector<entry>& table) {
    static const derivative_fixture<robot_tree> d = [] {
        const auto m = CTGA_ROBOT::make_model<double>();
        if (!m) {
            std::fprintf(stderr, "%s: make_model failed: %s\n", robot_name, ctga::describe(m.error));
            std::abort();
        }
        return derivative_fixture<robot_tree>{fixture<robot_tree>{*m, {}, random_states<robot_tree>(97), {}}};
    }();
    const std::string label = robot_name;
    add<algorithm::rnea, implementation::ctga>(table, "rnea_" + label + "/ctga", d.f);
    add<algorithm::aba, implementation::ctga>(table, "aba_" + label + "/ctga", d.f);
    add<algorithm::crba, implementation::ctga>(table, "crba_" + label + "/ctga", d.f);
    add_derivative<dynamics::inverse, differentiation::ctga>(table, "rnea_derivatives_" + label + "/ctga", d);
    add_derivative<dynamics::forward, differentiation::ctga>(table, "aba_derivatives_" + label + "/ctga", d);
    add_derivative<dynamics::inverse_mass, differentiation::ctga>(table, "minverse_" + label + "/ctga", d);
}
const bool registered = (robot_tables().push_back(&add_robot), true);
}  // namespace
}  // namespace bench::chains
