/* The traction tolerance and the traction error estimate through the C ABI: bad inputs get
 * their status and leave the contact and the out-parameter alone; INFINITY ("tractions not
 * needed") lets AUTO take the cheapest method for c, a finite traction tolerance makes it
 * take one whose traction estimate meets it; the estimate is never NaN. Under valgrind
 * (quick) the COUPLED solves are left out: at b* = 0.2, mu~ = 100 they take ~1 s each
 * natively and tens of minutes under valgrind; the ABI calls are the same. */
#include <math.h>

#include "check.h"

#define SENTINEL (-123.456)

/* The reduced scene b* = 0.2, mu~ = 100 (docs/theory.md (R2): effective(1, 1 - 2 b*, 1, 1)),
 * where GOODMAN's c is within 1e-6 but its tractions are off by a few percent. */
static orthoslip_contact *reduced_scene(void)
{
    orthoslip_material *m = NULL;
    orthoslip_contact *k = NULL;
    CHECK_OK(orthoslip_material_new_effective(1.0, 0.6, 1.0, 1.0, &m));
    CHECK_OK(orthoslip_contact_new(m, &k));
    orthoslip_material_free(m);
    CHECK_OK(orthoslip_contact_set_friction(k, 100.0));
    CHECK_OK(orthoslip_contact_set_tolerance(k, 1e-6));
    return k;
}

/* Solves k and returns the method used, the c and traction estimates. */
static orthoslip_method solve(const orthoslip_contact *k, double *c_err, double *t_err)
{
    orthoslip_solution *s = NULL;
    orthoslip_method used;
    double p[3], q[3];
    const double x[3] = {-0.5, 0.3, 0.999};
    size_t i;
    CHECK_OK(orthoslip_contact_solve(k, &s));
    CHECK_OK(orthoslip_solution_method(s, &used));
    CHECK_OK(orthoslip_solution_error_estimate(s, c_err));
    CHECK_OK(orthoslip_solution_traction_error_estimate(s, t_err));
    CHECK_OK(orthoslip_solution_tractions(s, x, 3, p, q));
    for (i = 0; i < 3; i++) CHECK(isfinite(p[i]) && isfinite(q[i]) && p[i] > 0.0);
    orthoslip_solution_free(s);
    return used;
}

int main(void)
{
    const double bad[4] = {NAN, -1e-6, 0.0, -INFINITY};
    orthoslip_contact *k = reduced_scene();
    orthoslip_solution *s = NULL;
    double c_err, t_err, out = SENTINEL;
    size_t i;

    /* bad inputs: status, and nothing changed or written */
    CHECK_STATUS(orthoslip_contact_set_traction_tolerance(NULL, 1e-6),
                 ORTHOSLIP_ERROR_NULL_POINTER);
    for (i = 0; i < 4; i++)
        CHECK_STATUS(orthoslip_contact_set_traction_tolerance(k, bad[i]),
                     ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK(orthoslip_last_error_message(NULL, 0) > 0);
    CHECK_STATUS(orthoslip_solution_traction_error_estimate(NULL, &out),
                 ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK(out == SENTINEL);

    if (!test_quick()) {
        CHECK_OK(orthoslip_contact_solve(k, &s));
        CHECK_STATUS(orthoslip_solution_traction_error_estimate(s, NULL),
                     ORTHOSLIP_ERROR_NULL_POINTER);
        orthoslip_solution_free(s);

        /* default: the traction tolerance follows the tolerance (1e-6): not GOODMAN */
        CHECK(solve(k, &c_err, &t_err) != ORTHOSLIP_METHOD_GOODMAN);
        CHECK_LE(c_err, 1e-6);
        CHECK_LE(t_err, 1e-6);
    }

    /* tractions not needed: the cheapest method for c, with its (larger) traction bound */
    CHECK_OK(orthoslip_contact_set_traction_tolerance(k, INFINITY));
    CHECK(solve(k, &c_err, &t_err) == ORTHOSLIP_METHOD_GOODMAN);
    CHECK_LE(c_err, 1e-6);
    CHECK(t_err > 1e-6 && !isnan(t_err));
    CHECK_OK(orthoslip_contact_solve(k, &s));
    CHECK_STATUS(orthoslip_solution_traction_error_estimate(s, NULL),
                 ORTHOSLIP_ERROR_NULL_POINTER);
    orthoslip_solution_free(s);

    if (!test_quick()) {
        /* a loose traction tolerance apart from a tight one on c */
        CHECK_OK(orthoslip_contact_set_tolerance(k, 1e-9));
        CHECK_OK(orthoslip_contact_set_traction_tolerance(k, 1e-3));
        CHECK(solve(k, &c_err, &t_err) == ORTHOSLIP_METHOD_COUPLED);
        CHECK_LE(c_err, 1e-9);
        CHECK_LE(t_err, 1e-3);
    }

    /* a closed form asked for explicitly ignores both tolerances and reports its bounds */
    CHECK_OK(orthoslip_contact_set_method(k, ORTHOSLIP_METHOD_SPENCE));
    CHECK(solve(k, &c_err, &t_err) == ORTHOSLIP_METHOD_SPENCE);
    CHECK(!isnan(c_err) && !isnan(t_err) && t_err > 0.0);
    orthoslip_contact_free(k);
    return 0;
}
