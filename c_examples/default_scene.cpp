// The default scene through the C++17 RAII wrapper (orthoslip.hpp): a carbon/epoxy ply
// (plane stress) under a rigid flat punch with mu = 0.3. A failed call throws
// orthoslip::error; main prints it and returns 1.
#include <cstdio>
#include <exception>
#include <vector>

#include <orthoslip.hpp>  // installed next to orthoslip.h

namespace {
const char *method_name(orthoslip_method m) {
    switch (m) {
    case ORTHOSLIP_METHOD_AUTO: return "AUTO";
    case ORTHOSLIP_METHOD_GOODMAN: return "GOODMAN";
    case ORTHOSLIP_METHOD_SPENCE: return "SPENCE";
    case ORTHOSLIP_METHOD_COUPLED: return "COUPLED";
    case ORTHOSLIP_METHOD_LCP: return "LCP";
    }
    return "unknown";
}
} // namespace

int main() {
    const double e11 = 181e9, e22 = 10.3e9, g12 = 7.17e9, nu12 = 0.28, mu = 0.3;
    try {
        std::printf("orthoslip %s (C++)\n", orthoslip_version());
        const auto ply = orthoslip::material::plane_stress(e11, e22, g12, nu12);
        const auto k = ply.effective();
        std::printf("effective: E = %.17g, nu = %.17g, delta = %.17g, kappa = %.17g\n", k.e, k.nu,
                    k.delta, k.kappa);
        const auto g = ply.green();
        std::printf("green: A = %.17g, B = %.17g, C = %.17g\n", g.a, g.b, g.c);

        orthoslip::contact punch(ply);
        punch.friction(mu).method(ORTHOSLIP_METHOD_AUTO);
        const auto s = punch.solve();
        std::printf("c = %.17g\n", s.stick_half_width());
        std::printf("1 - c = %.17g\n", s.slip_width());
        std::printf("method = %s\n", method_name(s.method()));
        std::printf("error estimate = %.3e\n", s.error_estimate());

        const int n = 21;
        std::vector<double> x(n);
        for (int i = 0; i < n; ++i) {
            x[i] = 0.99 * static_cast<double>(i - n / 2) / static_cast<double>(n / 2);
        }
        const auto t = s.at(x);
        std::printf("%10s %24s %24s\n", "x", "p", "q");
        for (int i = 0; i < n; ++i) {
            std::printf("%10.4f %24.17g %24.17g\n", x[i], t.p[i], t.q[i]);
        }

        const auto edge = s.edge_intensity();
        const auto st = s.stresses({0.0}, {-0.5});
        std::printf("edge intensity: k = %.17g, g = %.17g\n", edge.k, edge.g);
        std::printf("stresses at (0, -0.5): sxx = %.17g, syy = %.17g, sxy = %.17g\n", st.sxx[0],
                    st.syy[0], st.sxy[0]);
        std::printf("slip at x = 0.99: %.17g\n", s.slip({0.99})[0]);

        // Fretting: Q cycled between +-0.6 mu P (32 panels per half-width, 4 steps per
        // quarter cycle: a coarse, quick grid)
        orthoslip::cycle_options o;
        o.panels(32).steps(4);
        const auto cy = punch.solve_cycles(0.6 * mu, 10, o);
        const auto w1 = cy.dissipated_energy(0);
        std::printf("fretting cycles = %zu\n", cy.count());
        std::printf("fretting W1 = %.17g\n", w1.value);
        std::printf("fretting W1 error = %.3e\n", w1.error);
    } catch (const orthoslip::error &e) {
        std::fprintf(stderr, "default_scene: %s\n", e.what());
        return 1;
    } catch (const std::exception &e) {
        std::fprintf(stderr, "default_scene: %s\n", e.what());
        return 1;
    }
    return 0;
}
