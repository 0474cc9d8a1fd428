/* The slip (orthoslip_solution_slip) against the tangential displacement gradient of
 * docs/theory.md (U1), (F4) integrated by GSL from the library's own tractions (valid C11
 * and C++17): per P/E, u(x) = -pi B E int_c^x (bq p + H[q]) dt for c < x < 1, with
 * H[q] = PV int q(t)/(t' - t) dt / pi (hilbert.h) and B, bq = A/(pi B) the closed forms of
 * elastic.h; the outer integral by GSL QAGS (its extrapolation handles the (t - c)^g start).
 * Also: u = 0 on the stick zone, u odd, and at mu = 0 u = -(1 - nu) arcsin(x)/pi. Every
 * test material, GOODMAN, SPENCE and COUPLED, to 1e-8 of |u| (quick mode, under valgrind: the
 * first material, COUPLED, one point: the nested quadrature is slow there). */
#include <math.h>
#include <stdio.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include "check.h"
#include "elastic.h"
#include "hilbert.h"
#include "residuals.h"

#define TOLERANCE 1e-8

typedef struct {
    hilbert_quad *inner;
    const traction_field *field;
    double bq;
} rate_params;

static double rate(double t, void *params)
{
    const rate_params *r = (const rate_params *)params;
    return slip_rate(r->inner, r->field, r->bq, t);
}

int main(void)
{
    static const orthoslip_method methods[] = {ORTHOSLIP_METHOD_GOODMAN, ORTHOSLIP_METHOD_SPENCE,
                                               ORTHOSLIP_METHOD_COUPLED};
    size_t n_mat, i, j, k;
    const test_material *mats = test_materials(&n_mat);
    const size_t n_points = test_quick() ? 1 : 3;
    gsl_integration_workspace *outer = gsl_integration_workspace_alloc(HILBERT_LIMIT);
    double worst = 0.0, worst_arcsin = 0.0;
    int cases = 0, failures = 0;
    gsl_set_error_handler_off();
    if (test_quick()) n_mat = 1;
    for (i = 0; i < n_mat; i++) {
        reference_constants rc = reference_constants_of(&mats[i]);
        double bp = rc.a / (TEST_PI * rc.c), bq = rc.a / (TEST_PI * rc.b), mu = 0.3;
        double scale = -TEST_PI * rc.b * rc.e;
        /* frictionless: p = 1/(pi sqrt(1 - x^2)), c = 0, q = 0 */
        {
            orthoslip_contact *contact = test_contact_new(&mats[i], 0.0, ORTHOSLIP_METHOD_GOODMAN);
            orthoslip_solution *s = NULL;
            const double xs[] = {-0.999, -0.5, 0.0, 0.3, 0.9, 1.0};
            double u[6];
            CHECK_OK(orthoslip_contact_solve(contact, &s));
            CHECK_OK(orthoslip_solution_slip(s, xs, 6, u));
            for (k = 0; k < 6; k++) {
                double exact = -(1.0 - rc.nu) * asin(xs[k]) / TEST_PI;
                worst_arcsin = fmax(worst_arcsin, fabs(u[k] - exact));
                CHECK_LE(fabs(u[k] - exact), 1e-13);
            }
            orthoslip_solution_free(s);
            orthoslip_contact_free(contact);
        }
        for (j = test_quick() ? 2 : 0; j < sizeof methods / sizeof methods[0]; j++) {
            orthoslip_contact *contact = test_contact_new(&mats[i], mu, methods[j]);
            orthoslip_solution *s = NULL;
            hilbert_quad h = hilbert_quad_new();
            traction_field f;
            rate_params params;
            gsl_function fn;
            double from = 0.0, integral = 0.0, stick[2], zero[2];
            CHECK_OK(orthoslip_contact_set_tolerance(contact, 1e-10));
            CHECK_OK(orthoslip_contact_set_traction_tolerance(contact, 1e-8)); /* the field's target */
            CHECK_OK(orthoslip_contact_solve(contact, &s));
            f = solution_field(s, methods[j], bp, mu);
            stick[0] = 0.5 * f.c;
            stick[1] = -0.99 * f.c;
            CHECK_OK(orthoslip_solution_slip(s, stick, 2, zero));
            CHECK(zero[0] == 0.0 && zero[1] == 0.0);
            params.inner = &h;
            params.field = &f;
            params.bq = bq;
            fn.function = rate;
            fn.params = &params;
            from = f.c;
            for (k = 1; k <= n_points; k++) {
                double x = f.c + (1.0 - f.c) * 0.95 * (double)k / (double)n_points;
                double piece = 0.0, abserr = 0.0, u[2], xx[2];
                int status = gsl_integration_qags(&fn, from, x, HILBERT_EPSABS, 1e-11,
                                                  HILBERT_LIMIT, outer, &piece, &abserr);
                if (status != GSL_SUCCESS) failures++;
                integral += piece;
                from = x;
                xx[0] = x;
                xx[1] = -x;
                CHECK_OK(orthoslip_solution_slip(s, xx, 2, u));
                CHECK(u[1] == -u[0] && u[0] < 0.0);
                worst = fmax(worst, fabs(u[0] - scale * integral) / fabs(u[0]));
                CHECK_LE(fabs(u[0] - scale * integral), TOLERANCE * fabs(u[0]));
            }
            failures += h.failures;
            cases++;
            hilbert_quad_free(&h);
            orthoslip_solution_free(s);
            orthoslip_contact_free(contact);
        }
    }
    gsl_integration_workspace_free(outer);
    printf("field_slip: %d cases, max |slip - GSL| / |slip| = %.2e, max |slip + (1 - nu) "
           "arcsin(x)/pi| at mu = 0: %.2e; %d GSL calls without GSL_SUCCESS\n",
           cases, worst, worst_arcsin, failures);
    return 0;
}
