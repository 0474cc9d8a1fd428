/* Ownership and evaluation semantics of the C ABI, for every method that solves:
 * - a contact keeps its own copy of the material, a solution outlives its contact (run under
 *   valgrind by the harness);
 * - tractions: p = q = 0 for |x| > 1; p = +INFINITY, q = +-INFINITY at x = +-1; batch and
 *   single-point evaluation agree bitwise; x may alias p or q; n = 0 writes nothing;
 * - c and 1 - c are consistent; the error estimate is >= 0 (not NaN); GOODMAN ignores the
 *   tolerance.
 * Contacts use tolerance 1e-2: this checks the interface, not accuracy, and keeps the
 * iterative methods cheap (also under valgrind). */
#include <float.h>
#include <math.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "check.h"
#include "elastic.h"

#define N_X 12

static void check_tractions(const orthoslip_solution *s, double c)
{
    const double x[N_X] = {-1.0,      -0.999, -0.5, -0.1,         0.0,     0.25,
                           c * 0.999, 0.97,   1.0,  nextafter(1.0, 2.0), -1.5, DBL_MAX};
    double p[N_X], q[N_X], buf[N_X], pq[N_X];
    size_t i;
    CHECK_OK(orthoslip_solution_tractions(s, x, N_X, p, q));
    for (i = 0; i < N_X; i++) {
        double pi, qi;
        CHECK_OK(orthoslip_solution_tractions(s, &x[i], 1, &pi, &qi));
        CHECK(memcmp(&pi, &p[i], sizeof pi) == 0 && memcmp(&qi, &q[i], sizeof qi) == 0);
        if (fabs(x[i]) > 1.0) CHECK(p[i] == 0.0 && q[i] == 0.0);
        if (fabs(x[i]) < 1.0) CHECK(isfinite(p[i]) && p[i] > 0.0 && isfinite(q[i]));
    }
    CHECK(p[0] == INFINITY && q[0] == -INFINITY);
    CHECK(p[8] == INFINITY && q[8] == INFINITY);

    /* In place: x aliasing p, then x aliasing q. */
    memcpy(buf, x, sizeof buf);
    CHECK_OK(orthoslip_solution_tractions(s, buf, N_X, buf, pq));
    CHECK(memcmp(buf, p, sizeof buf) == 0 && memcmp(pq, q, sizeof pq) == 0);
    memcpy(buf, x, sizeof buf);
    CHECK_OK(orthoslip_solution_tractions(s, buf, N_X, pq, buf));
    CHECK(memcmp(pq, p, sizeof pq) == 0 && memcmp(buf, q, sizeof buf) == 0);
}

int main(void)
{
    static const orthoslip_method methods[] = {
        ORTHOSLIP_METHOD_GOODMAN, ORTHOSLIP_METHOD_SPENCE, ORTHOSLIP_METHOD_COUPLED,
        ORTHOSLIP_METHOD_LCP, ORTHOSLIP_METHOD_AUTO};
    size_t n_mat, i, j, solved = 0;
    const test_material *mats = test_materials(&n_mat);
    gsl_set_error_handler_off();
    for (i = 0; i < n_mat; i++) {
        for (j = 0; j < sizeof methods / sizeof methods[0]; j++) {
            /* test_contact_new frees its material right after orthoslip_contact_new. */
            orthoslip_contact *k = test_contact_new(&mats[i], 0.4, methods[j]);
            orthoslip_solution *s = NULL;
            double c, w, err, c2 = -1.0;
            orthoslip_method used;
            CHECK_OK(orthoslip_contact_set_tolerance(k, 1e-2));
            /* c only: LCP's first-order tractions would need N = 1600 (traction_tolerance.c tests them) */
            CHECK_OK(orthoslip_contact_set_traction_tolerance(k, INFINITY));
            if (orthoslip_contact_solve(k, &s) != ORTHOSLIP_OK) {
                CHECK(s == NULL && methods[j] != ORTHOSLIP_METHOD_GOODMAN);
                orthoslip_contact_free(k);
                continue;
            }
            if (methods[j] == ORTHOSLIP_METHOD_GOODMAN) {
                orthoslip_solution *s2 = NULL;
                CHECK_OK(orthoslip_contact_set_tolerance(k, 1e-6));
                CHECK_OK(orthoslip_contact_solve(k, &s2));
                CHECK_OK(orthoslip_solution_stick_half_width(s2, &c2));
                orthoslip_solution_free(s2);
            }
            orthoslip_contact_free(k); /* the solution stays valid */
            CHECK_OK(orthoslip_solution_stick_half_width(s, &c));
            CHECK_OK(orthoslip_solution_slip_width(s, &w));
            CHECK_OK(orthoslip_solution_error_estimate(s, &err));
            CHECK_OK(orthoslip_solution_method(s, &used));
            CHECK(c > 0.0 && c < 1.0 && w > 0.0 && w <= 1.0);
            CHECK_LE(fabs((c + w) - 1.0), 4.0 * DBL_EPSILON);
            CHECK(err >= 0.0); /* +INFINITY: no bound known */
            CHECK(used != ORTHOSLIP_METHOD_AUTO);
            CHECK(methods[j] == ORTHOSLIP_METHOD_AUTO || used == methods[j]);
            if (methods[j] == ORTHOSLIP_METHOD_GOODMAN) CHECK(c2 == c);
            check_tractions(s, c);
            orthoslip_solution_free(s);
            solved++;
        }
    }
    printf("semantics: %zu material/method pairs solved and checked\n", solved);
    return 0;
}
