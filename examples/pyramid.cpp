// A pyramid of 210 cubes comes to rest on the ground: Box3D's large_pyramid with a base of 20
// (ctga_contact_bench's pyramid_work), stepped by ctga::physics_world at 60 Hz with the frictional
// contact problem solved to a tolerance of 1e-3 on its natural-map residual each step.
//   pyramid                          2 s; prints the solver's report each second; fails (returns 1)
//                                    if the top cube moved more than 1 cm or a step reported an error
//   pyramid --seconds 60 --svg FILE  60 s, and draws it as it ends (front view, each cube shaded by
//                                    its row): docs/img/pyramid.svg
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include <ctga/collision/box.hpp>
#include <ctga/scenes/world.hpp>

namespace co = ctga::collision;
using ctga::vec3;

namespace {
constexpr int base = 20;
constexpr std::size_t cubes = base * (base + 1) / 2;
constexpr double half = 0.5, density = 100.0, friction = 0.6, h = 1.0 / 60;

using cube = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::diagonal, co::box<double>>;
using world = ctga::physics_world<double, co::box<double>, cube>;

// the cube's front face (z = +half in its frame) as an SVG path, x right and y up, 20 px a metre
std::string front_face(const ctga::motor_map<double>& m) {
    std::string path;
    const double corner[4][2] = {{-half, -half}, {half, -half}, {half, half}, {-half, half}};
    for (int k = 0; k < 4; ++k) {
        const vec3<double> p = ctga::linear3::add(ctga::linear3::apply(m.R, vec3<double>{corner[k][0], corner[k][1], half}), m.t);
        char buf[64];
        std::snprintf(buf, sizeof buf, "%c%.2f,%.2f", k == 0 ? 'M' : 'L', 20 * p[0], -20 * p[1]);
        path += buf;
    }
    return path + "Z";
}
}  // namespace

int main(int argc, char** argv) {
    double seconds = 2;
    const char* svg = nullptr;
    for (int a = 1; a + 1 < argc; a += 2) {
        if (std::strcmp(argv[a], "--seconds") == 0) seconds = std::atof(argv[a + 1]);
        else if (std::strcmp(argv[a], "--svg") == 0) svg = argv[a + 1];
    }
    ctga::world_settings<double> set;
    set.gravity = {0.0, -10.0, 0.0};
    set.solver.tolerance = 1e-3;  // N·s: the cubes weigh 100 kg, a step's weight is 16.7 N·s
    set.solver.max_sweeps = 100000;
    auto w = std::make_unique<world>(std::array<std::size_t, 1>{cubes}, ctga::world_capacity{.statics = 1, .contacts = 16 * cubes, .pairs = 8 * cubes},
                                     set);
    w->add_static(*co::make_box(400.0, 1.0, 400.0), ctga::motor<double>(ctga::make_translator(0.0, -1.0, 0.0)), {friction, 0.0});
    for (int i = 0; i < base; ++i)
        for (int j = i; j < base; ++j) {
            const double x = (i + 1) * half + 2 * (j - i) * half - base * half, y = (2 * i + 1) * half;
            if (!w->add_body<0>(*co::make_box(half, half, half), density, ctga::motor<double>(ctga::make_translator(x, y, 0.0)), {friction, 0.0}))
                return 1;
        }
    const vec3<double> top = ctga::map_of(w->pose<0>(cubes - 1)).t;
    const int steps = static_cast<int>(std::lround(seconds / h));
    double penetration = 0;
    for (int k = 1; k <= steps; ++k) {
        const ctga::step_report<double> r = w->step(h);
        if (r.error != ctga::error_code::none) {
            std::printf("step %d: error %d\n", k, static_cast<int>(r.error));
            return 1;
        }
        penetration = std::max(penetration, r.penetration);
        if (k % 60 == 0 || k == 1)
            std::printf("t = %5.2f s  %4zu contact points  residual %.2e after %5zu sweeps  penetration %.2e m\n", k * h, r.contacts,
                        r.contact.residual, r.contact.sweeps, r.penetration);
    }
    const vec3<double> d = ctga::linear3::sub(ctga::map_of(w->pose<0>(cubes - 1)).t, top);
    const double drift = std::sqrt(ctga::linear3::dot(d, d));
    std::printf("after %.0f s the top cube has moved %.2e m; the largest penetration was %.2e m\n", seconds, drift, penetration);
    if (svg) {
        std::FILE* f = std::fopen(svg, "w");
        if (!f) return 1;
        std::fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"-215 -428 430 448\" width=\"645\" height=\"672\">\n"
                        "<rect x=\"-215\" y=\"0\" width=\"430\" height=\"20\" fill=\"#ece6d8\" stroke=\"#b3a483\" stroke-width=\"0.5\"/>\n");
        std::size_t b = 0;
        for (int i = 0; i < base; ++i)
            for (int j = i; j < base; ++j, ++b) {
                const int shade = 225 - 6 * i;
                std::fprintf(f, "<path d=\"%s\" fill=\"rgb(%d,%d,%d)\" stroke=\"#35506b\" stroke-width=\"0.5\"/>\n",
                             front_face(ctga::map_of(w->pose<0>(b))).c_str(), shade - 30, shade - 10, shade + 25 > 255 ? 255 : shade + 25);
            }
        std::fprintf(f, "<text x=\"-205\" y=\"-412\" font-family=\"sans-serif\" font-size=\"11\">210 cubes after %.0f s at 60 Hz, "
                        "tolerance 1e-3: the top cube moved %.1e m, penetration at most %.1e m</text>\n</svg>\n",
                     seconds, drift, penetration);
        std::fclose(f);
    }
    return drift <= 0.01 ? 0 : 1;
}
