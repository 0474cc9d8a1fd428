/* Goodman's stick half-width against GSL, and the Green's constants against the closed forms
 * of docs/theory.md §2.
 * - A, B, C (orthoslip_material_green) and E, nu, delta, kappa (orthoslip_material_effective)
 *   equal the closed forms computed here from the engineering constants (relative 1e-12);
 *   isotropic steel also matches Johnson's A = (1-2nu)(1+nu)/E, B = C = 2(1-nu^2)/(pi E).
 * - METHOD_GOODMAN: c solves K(sqrt(1-c^2))/K(c) = bq/mu with bq = A/(pi B) (docs/theory.md
 *   (G1)); the reference comes from gsl_root_fsolver_brent on the GSL complete elliptic
 *   integrals: |c - c_ref| < 1e-12 and 1 - c (orthoslip_solution_slip_width) to relative 1e-10.
 *   The root is sought in s = min(c, sqrt(1-c^2)) <= 1/sqrt(2) through
 *   g(s) = K(sqrt(1-s^2))/K(s) = RF(0, s^2, 1)/K(s), so that both c and 1 - c = s^2/(1+c)
 *   (when s = sqrt(1-c^2)) keep full relative accuracy, down to c ~ 1e-23 and 1 - c ~ 1e-95. */
#include <math.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_ellint.h>

#include "check.h"
#include "elastic.h"

/* ln g(e^u) - ln target, decreasing in u. */
typedef struct {
    double log_target;
} ratio_equation;

static double log_ratio_residual(double u, void *params)
{
    const ratio_equation *eq = (const ratio_equation *)params;
    double s = exp(u);
    double k_comp = gsl_sf_ellint_RF(0.0, s * s, 1.0, GSL_PREC_DOUBLE); /* K(sqrt(1-s^2)) */
    double k = gsl_sf_ellint_Kcomp(s, GSL_PREC_DOUBLE);
    return log(k_comp / k) - eq->log_target;
}

/* The root s of g(s) = target, 1e-150 < s < 0.8 (g(1/sqrt 2) = 1). */
static double solve_ratio(double target)
{
    ratio_equation eq;
    gsl_function f;
    gsl_root_fsolver *solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    double lo = log(1e-150), hi = log(0.8), u = 0.0;
    int iter;
    eq.log_target = log(target);
    f.function = log_ratio_residual;
    f.params = &eq;
    CHECK(gsl_root_fsolver_set(solver, &f, lo, hi) == GSL_SUCCESS);
    for (iter = 0; iter < 200; iter++) {
        CHECK(gsl_root_fsolver_iterate(solver) == GSL_SUCCESS);
        u = gsl_root_fsolver_root(solver);
        lo = gsl_root_fsolver_x_lower(solver);
        hi = gsl_root_fsolver_x_upper(solver);
        if (gsl_root_test_interval(lo, hi, 0.0, 1e-15) == GSL_SUCCESS) break;
    }
    CHECK(iter < 200);
    gsl_root_fsolver_free(solver);
    return exp(u);
}

/* Goodman's c and 1 - c for bq/mu = r. */
static void goodman_reference(double r, double *c, double *one_minus_c)
{
    if (r >= 1.0) {
        *c = solve_ratio(r);
        *one_minus_c = 1.0 - *c;
    } else {
        double s = solve_ratio(1.0 / r); /* s = sqrt(1 - c^2) */
        *c = sqrt((1.0 - s) * (1.0 + s));
        *one_minus_c = s * s / (1.0 + *c);
    }
}

static double rel_diff(double got, double want)
{
    return fabs(got - want) / fabs(want);
}

static void check_constants(const test_material *m, double *worst)
{
    reference_constants r = reference_constants_of(m);
    orthoslip_material *mat = test_material_new(m);
    double a, b, c, e, nu, delta, kappa;
    size_t i;
    CHECK_OK(orthoslip_material_green(mat, &a, &b, &c));
    CHECK_OK(orthoslip_material_effective(mat, &e, &nu, &delta, &kappa));
    const double got[7] = {a, b, c, e, nu, delta, kappa};
    const double want[7] = {r.a, r.b, r.c, r.e, r.nu, r.delta, r.kappa};
    for (i = 0; i < 7; i++) {
        double d = rel_diff(got[i], want[i]);
        if (d > *worst) *worst = d;
        CHECK_LE(d, 1e-12);
    }
    orthoslip_material_free(mat);

    /* The same material built from its effective constants has the same A, B, C. */
    CHECK_OK(orthoslip_material_new_effective(r.e, r.nu, r.delta, r.kappa, &mat));
    CHECK_OK(orthoslip_material_green(mat, &a, &b, &c));
    CHECK_LE(rel_diff(a, r.a), 1e-12);
    CHECK_LE(rel_diff(b, r.b), 1e-12);
    CHECK_LE(rel_diff(c, r.c), 1e-12);
    orthoslip_material_free(mat);
}

/* Johnson eq. 2.25 for isotropic plane strain. */
static void check_isotropic(double e, double nu)
{
    test_material m;
    orthoslip_material *mat;
    double a, b, c, b_iso = 2.0 * (1.0 - nu * nu) / (TEST_PI * e);
    m.name = "isotropic";
    m.plane_strain = 1;
    m.e11 = m.e22 = m.e33 = e;
    m.g12 = e / (2.0 * (1.0 + nu));
    m.nu12 = m.nu13 = m.nu23 = nu;
    mat = test_material_new(&m);
    CHECK_OK(orthoslip_material_green(mat, &a, &b, &c));
    CHECK_LE(rel_diff(a, (1.0 - 2.0 * nu) * (1.0 + nu) / e), 1e-12);
    CHECK_LE(rel_diff(b, b_iso), 1e-12);
    CHECK_LE(rel_diff(c, b_iso), 1e-12);
    orthoslip_material_free(mat);
}

int main(void)
{
    static const double frictions[] = {0.02, 0.1, 0.3, 0.6, 1.0, 3.0, 20.0};
    size_t n_mat, i, j, cases = 0;
    const test_material *mats = test_materials(&n_mat);
    double worst_const = 0.0, worst_c = 0.0, worst_w = 0.0, smallest_c = 1.0, smallest_w = 1.0;
    gsl_set_error_handler_off();

    check_isotropic(210e9, 0.3);
    check_isotropic(70e9, 0.33);
    check_isotropic(1.0, -0.5);
    for (i = 0; i < n_mat; i++) {
        reference_constants r = reference_constants_of(&mats[i]);
        double bq = r.a / (TEST_PI * r.b);
        check_constants(&mats[i], &worst_const);
        for (j = 0; j < sizeof frictions / sizeof frictions[0]; j++) {
            double mu = frictions[j], c_ref, w_ref, c, w, err;
            orthoslip_contact *k = test_contact_new(&mats[i], mu, ORTHOSLIP_METHOD_GOODMAN);
            orthoslip_solution *s = NULL;
            orthoslip_method used;
            goodman_reference(bq / mu, &c_ref, &w_ref);
            CHECK_OK(orthoslip_contact_solve(k, &s));
            CHECK_OK(orthoslip_solution_stick_half_width(s, &c));
            CHECK_OK(orthoslip_solution_slip_width(s, &w));
            CHECK_OK(orthoslip_solution_method(s, &used));
            CHECK_OK(orthoslip_solution_error_estimate(s, &err));
            CHECK(used == ORTHOSLIP_METHOD_GOODMAN);
            CHECK(err >= 0.0); /* +INFINITY: no bound known */
            if (fabs(c - c_ref) > 1e-12 || rel_diff(w, w_ref) > 1e-10)
                fprintf(stderr, "%s, mu = %g: c = %.17g (ref %.17g), 1 - c = %.17g (ref %.17g)\n",
                        mats[i].name, mu, c, c_ref, w, w_ref);
            CHECK_LE(fabs(c - c_ref), 1e-12);
            CHECK_LE(rel_diff(w, w_ref), 1e-10);
            if (fabs(c - c_ref) > worst_c) worst_c = fabs(c - c_ref);
            if (rel_diff(w, w_ref) > worst_w) worst_w = rel_diff(w, w_ref);
            if (c_ref < smallest_c) smallest_c = c_ref;
            if (w_ref < smallest_w) smallest_w = w_ref;
            cases++;
            orthoslip_solution_free(s);
            orthoslip_contact_free(k);
        }
    }
    printf("goodman_c: %zu cases (c_ref from %.2e to 1 - %.2e): max |c - c_ref| = %.3e, "
           "max rel. error of 1 - c = %.3e; max rel. error of A, B, C, E, nu, delta, kappa = "
           "%.3e\n",
           cases, smallest_c, smallest_w, worst_c, worst_w, worst_const);
    return 0;
}
