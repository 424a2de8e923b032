// Shapes on the ground and where they touch it: the collision layer's contact manifolds.
// A box tilted onto an edge, a capsule lying down, a pebble (a convex hull of random points), a
// cylinder standing and a sphere resting on a box, each a millimetre into its support; for each,
// contact_of gives up to four points with one normal, their separations and persistent ids.
//   contacts              prints the manifolds
//   contacts --svg FILE   also draws the scene (an oblique view, x right, z up, y receding) with
//                         the contact points and normals: docs/img/contacts.svg
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <ctga/collision/narrowphase.hpp>
#include <ctga/collision/shape_set.hpp>
#include <ctga/mechanics/motor.hpp>

namespace co = ctga::collision;
using ctga::vec3;

namespace {
using kinds = co::shape<co::box<double>, co::capsule<double>, co::cylinder<double>, co::sphere<double>, co::convex_hull<double, 24>>;

ctga::motor_map<double> posed(double angle_about_y, double x, double z) {
    return ctga::map_of(ctga::rigid_motion(ctga::make_translator(x, 0.0, z), ctga::make_rotor(angle_about_y, 0.0, 1.0, 0.0)));
}

co::convex_hull<double, 24> pebble() {
    std::mt19937_64 rng(5);
    std::normal_distribution<double> n;
    std::array<vec3<double>, 24> p{};
    for (auto& x : p) {
        vec3<double> d{n(rng), n(rng), n(rng)};
        const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        x = {0.35 * d[0] / l, 0.25 * d[1] / l, 0.2 * d[2] / l};
    }
    return *co::make_hull(p);
}

// An oblique view: screen x = x − 0.35 y, screen y = z + 0.25 y (in SVG units of 1 cm, y down).
std::array<double, 2> screen(const vec3<double>& x) { return {100 * (x[0] - 0.35 * x[1]), -100 * (x[2] + 0.25 * x[1])}; }

// The shape's outline in that view: along screen direction u, the support point along Pᵀ u.
std::string outline(const kinds& s, const ctga::motor_map<double>& p) {
    std::string path;
    for (int k = 0; k < 96; ++k) {
        const double a = 2 * std::acos(-1.0) * k / 96, ux = std::cos(a), uy = std::sin(a);
        vec3<double> d{ux, -0.35 * ux + 0.25 * uy, uy};
        const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (double& c : d) c /= l;
        const vec3<double> x = std::visit(
            [&](const auto& shape) {
                const vec3<double> local = ctga::linear3::apply_transposed(p.R, d);
                return ctga::linear3::add_scaled(co::to_world(p, core_support(shape, local)), core_radius(shape), d);
            },
            s);
        char buf[64];
        std::snprintf(buf, sizeof buf, "%c%.3f,%.3f", k == 0 ? 'M' : 'L', screen(x)[0], screen(x)[1]);
        path += buf;
    }
    return path + "Z";
}
}  // namespace

int main(int argc, char** argv) {
    const co::half_space<double> ground{};
    const ctga::motor_map<double> level = posed(0, 0, 0);
    struct placed {
        const char* name;
        kinds shape;
        ctga::motor_map<double> pose;
    };
    // each a millimetre into the ground: its lowest point at z = −0.001
    const double tilt = 0.35;
    std::vector<placed> scene{
        {"box on an edge", *co::make_box(0.3, 0.2, 0.15), posed(tilt, 0.0, 0.3 * std::sin(tilt) + 0.15 * std::cos(tilt) - 0.001)},
        {"capsule lying", *co::make_capsule(0.1, 0.3), posed(std::acos(0.0), 1.0, 0.099)},
        {"pebble", pebble(), posed(0.2, 1.9, 0.0)},
        {"cylinder standing", *co::make_cylinder(0.2, 0.25), posed(0, 2.7, 0.249)},
        {"sphere", *co::make_sphere(0.15), posed(0, 3.4, 0.149)},
    };
    // the pebble: lowered until it touches, from its separation
    scene[2].pose.t[2] -= co::separation_of(co::shape<co::half_space<double>>{ground}, level, scene[2].shape, scene[2].pose).distance + 0.001;

    std::string svg;
    for (const placed& b : scene) {
        const co::manifold<double> m = co::contact_of(co::shape<co::half_space<double>>{ground}, level, b.shape, b.pose, 0.002);
        std::printf("%-18s normal (%.3f %.3f %.3f), %zu point%s\n", b.name, m.normal[0], m.normal[1], m.normal[2], m.count, m.count == 1 ? "" : "s");
        svg += "<path d=\"" + outline(b.shape, b.pose) + "\" fill=\"#dde6f0\" stroke=\"#35506b\" stroke-width=\"0.6\"/>\n";
        for (std::size_t i = 0; i < m.count; ++i) {
            const auto& c = m.points[i];
            std::printf("    at (%7.4f %7.4f %7.4f)  separation %+.6f  id %08x\n", c.point_b[0], c.point_b[1], c.point_b[2], c.separation, c.id);
            char buf[256];
            std::snprintf(buf, sizeof buf,
                          "<line x1=\"%.3f\" y1=\"%.3f\" x2=\"%.3f\" y2=\"%.3f\" stroke=\"#c0392b\" stroke-width=\"0.8\"/>"
                          "<circle cx=\"%.3f\" cy=\"%.3f\" r=\"1.6\" fill=\"#c0392b\"/>\n",
                          screen(c.point_a)[0], screen(c.point_a)[1], screen(ctga::linear3::add_scaled(c.point_a, 0.12, m.normal))[0],
                          screen(ctga::linear3::add_scaled(c.point_a, 0.12, m.normal))[1], screen(c.point_a)[0], screen(c.point_a)[1]);
            svg += buf;
        }
        if (m.count == 0) return 1;  // each rests on the ground
    }
    if (argc == 3 && std::strcmp(argv[1], "--svg") == 0) {
        std::FILE* f = std::fopen(argv[2], "w");
        if (!f) return 1;
        std::fprintf(f,
                     "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"-50 -62 450 82\" width=\"900\" height=\"164\">\n"
                     "<path d=\"M-40,-10 L390,-10 L360,10 L-70,10 Z\" fill=\"#ece6d8\" stroke=\"#b3a483\" stroke-width=\"0.5\"/>\n"
                     "%s</svg>\n",
                     svg.c_str());
        std::fclose(f);
    }
    return 0;
}
