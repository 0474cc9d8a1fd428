/* The default scene through the C API: a carbon/epoxy ply (plane stress) under a rigid flat
 * punch with Coulomb friction mu = 0.3. Prints the effective constants, the Green constants
 * A, B, C, the stick half-width c, 1 - c, the method used, its error estimate, p, q at 21
 * points, and the energy dissipated in the first cycle of Q between +-0.6 mu P. Every status is checked; on failure the library's message is printed and the exit
 * code is 1. C11. */
#include <stdio.h>
#include <stdlib.h>

#include "orthoslip.h"

#define N_POINTS 21

/* Prints what failed, the status name and this thread's last error message. */
static void report_failure(const char *what, orthoslip_status status) {
    size_t len = orthoslip_last_error_message(NULL, 0);
    char *msg = malloc(len + 1);
    if (msg != NULL) {
        orthoslip_last_error_message(msg, len + 1);
    }
    fprintf(stderr, "default_scene: %s failed: %s: %s\n", what, orthoslip_status_string(status),
            msg != NULL ? msg : "(no memory for the message)");
    free(msg);
}

#define CHECK(call)                                                                            \
    do {                                                                                       \
        orthoslip_status check_status_ = (call);                                               \
        if (check_status_ != ORTHOSLIP_OK) {                                                   \
            report_failure(#call, check_status_);                                              \
            goto cleanup;                                                                      \
        }                                                                                      \
    } while (0)

static const char *method_name(orthoslip_method m) {
    switch (m) {
    case ORTHOSLIP_METHOD_AUTO: return "AUTO";
    case ORTHOSLIP_METHOD_GOODMAN: return "GOODMAN";
    case ORTHOSLIP_METHOD_SPENCE: return "SPENCE";
    case ORTHOSLIP_METHOD_COUPLED: return "COUPLED";
    case ORTHOSLIP_METHOD_LCP: return "LCP";
    }
    return "unknown";
}

int main(void) {
    const double e11 = 181e9, e22 = 10.3e9, g12 = 7.17e9, nu12 = 0.28, mu = 0.3;
    const orthoslip_method method = ORTHOSLIP_METHOD_AUTO; /* cheapest method meeting the tolerance */
    int exit_code = EXIT_FAILURE;
    orthoslip_material *material = NULL;
    orthoslip_contact *contact = NULL;
    orthoslip_solution *solution = NULL;
    orthoslip_cycle_options *options = NULL;
    orthoslip_cycles *cycles = NULL;

    printf("orthoslip %s (C)\n", orthoslip_version());
    printf("ply: E11 = %g Pa, E22 = %g Pa, G12 = %g Pa, nu12 = %g, plane stress; mu = %g\n", e11,
           e22, g12, nu12, mu);

    CHECK(orthoslip_material_new_plane_stress(e11, e22, g12, nu12, &material));
    double e, nu, delta, kappa;
    CHECK(orthoslip_material_effective(material, &e, &nu, &delta, &kappa));
    printf("effective: E = %.17g, nu = %.17g, delta = %.17g, kappa = %.17g\n", e, nu, delta,
           kappa);
    double a, b, c_green;
    CHECK(orthoslip_material_green(material, &a, &b, &c_green));
    printf("green: A = %.17g, B = %.17g, C = %.17g\n", a, b, c_green);

    CHECK(orthoslip_contact_new(material, &contact));
    CHECK(orthoslip_contact_set_friction(contact, mu));
    CHECK(orthoslip_contact_set_method(contact, method));
    CHECK(orthoslip_contact_solve(contact, &solution));

    double c, one_minus_c, c_error;
    orthoslip_method used;
    CHECK(orthoslip_solution_stick_half_width(solution, &c));
    CHECK(orthoslip_solution_slip_width(solution, &one_minus_c));
    CHECK(orthoslip_solution_method(solution, &used));
    CHECK(orthoslip_solution_error_estimate(solution, &c_error));
    printf("c = %.17g\n", c);
    printf("1 - c = %.17g\n", one_minus_c);
    printf("method = %s\n", method_name(used));
    printf("error estimate = %.3e\n", c_error);

    double x[N_POINTS], p[N_POINTS], q[N_POINTS];
    for (int i = 0; i < N_POINTS; ++i) {
        x[i] = 0.99 * (double)(i - N_POINTS / 2) / (double)(N_POINTS / 2);
    }
    CHECK(orthoslip_solution_tractions(solution, x, N_POINTS, p, q));
    printf("%10s %24s %24s\n", "x", "p", "q");
    for (int i = 0; i < N_POINTS; ++i) {
        printf("%10.4f %24.17g %24.17g\n", x[i], p[i], q[i]);
    }

    /* what engineers compute from it: the edge singularity p ~ k (1 - |x|)^(-g), the stresses
       half a punch width below the centre, the slip at x = 0.99 */
    double k, g, px = 0.0, py = -0.5, sxx, syy, sxy, sx = 0.99, slip;
    CHECK(orthoslip_solution_edge_intensity(solution, &k, &g));
    CHECK(orthoslip_solution_stresses(solution, &px, &py, 1, &sxx, &syy, &sxy));
    CHECK(orthoslip_solution_slip(solution, &sx, 1, &slip));
    printf("edge intensity: k = %.17g, g = %.17g\n", k, g);
    printf("stresses at (0, -0.5): sxx = %.17g, syy = %.17g, sxy = %.17g\n", sxx, syy, sxy);
    printf("slip at x = 0.99: %.17g\n", slip);

    /* fretting: Q cycled between +-0.6 mu P after the normal load, on a coarse, quick grid
       (32 panels per half-width, 4 load steps per quarter cycle); energies per P^2/E */
    size_t n_cycles;
    int steady;
    double w1, w1_error;
    CHECK(orthoslip_cycle_options_new(&options));
    CHECK(orthoslip_cycle_options_set_panels(options, 32));
    CHECK(orthoslip_cycle_options_set_steps(options, 4));
    CHECK(orthoslip_contact_solve_cycles_with_options(contact, options, 0.6 * mu, 10, &cycles));
    CHECK(orthoslip_cycles_count(cycles, &n_cycles, &steady));
    CHECK(orthoslip_cycles_dissipated_energy(cycles, 0, &w1));
    CHECK(orthoslip_cycles_dissipated_energy_error(cycles, 0, &w1_error));
    printf("fretting cycles = %zu\n", n_cycles);
    printf("fretting W1 = %.17g\n", w1);
    printf("fretting W1 error = %.3e\n", w1_error);
    exit_code = EXIT_SUCCESS;

cleanup:
    orthoslip_cycles_free(cycles);
    orthoslip_cycle_options_free(options);
    orthoslip_solution_free(solution);
    orthoslip_contact_free(contact);
    orthoslip_material_free(material);
    return exit_code;
}
