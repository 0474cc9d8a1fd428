/* Checks of a solved contact against the boundary-value problem of docs/theory.md §3
 * (paper eqs. (9)-(11)), by GSL quadrature of the library's own p and q (valid C11 and C++17):
 * - (E1) C PV int p(t)/(x-t) dt - A q(x) = 0 on |x| < 1 (paper eq. (10)), relative to the
 *   largest of the two terms and A mu p(x), the bound of the second (both terms vanish at
 *   x = 0, and in a stick zone of c ~ 1e-5 they are ~1e-6 of their size elsewhere, below the
 *   absolute accuracy of the quadrature);
 * - (E2) B PV int q(t)/(x-t) dt + A p(x) = 0 on |x| < c (paper eq. (11)), relative to A p(x);
 * - int p = 1, int q = 0;
 * - friction: p > 0, p even, q odd, |q| <= mu p on the stick zone, q = mu p sgn x on the slip
 *   zones (so q > 0 for x > c);
 * - slip direction: J(x) = int_c^x (bq p + H[q]) dt >= 0 for c < x < 1, H[q] = PV/pi.
 * A, B, C are the closed forms of elastic.h, not the library's. */
#ifndef ORTHOSLIP_TEST_RESIDUALS_H
#define ORTHOSLIP_TEST_RESIDUALS_H

#include <math.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include "check.h"
#include "elastic.h"
#include "hilbert.h"

enum {
    RESIDUAL_E1 = 1,
    RESIDUAL_E2 = 2,
    RESIDUAL_INTEGRALS = 4,
    RESIDUAL_FRICTION = 8,
    RESIDUAL_SLIP_DIRECTION = 16
};

#define RESIDUAL_TOLERANCE 1e-8

/* Largest deviations met over all cases. */
typedef struct {
    double e1, e2, int_p, int_q, stick_ratio, slip_direction_min;
    int cases, quad_failures, last_quad_failure;
} residual_summary;

/* Maxima start as NaN (reported as n/a when not checked); update with raise(). */
static inline residual_summary residual_summary_new(void)
{
    residual_summary s;
    s.e1 = s.e2 = s.int_p = s.int_q = s.stick_ratio = NAN;
    s.slip_direction_min = NAN;
    s.cases = s.quad_failures = s.last_quad_failure = 0;
    return s;
}

/* *max = max(*max, v), replacing the initial NaN. */
static inline void raise_to(double *max, double v)
{
    if (!(*max >= v)) *max = v;
}

static inline void solution_tractions_at(const void *ctx, double x, double *p, double *q)
{
    CHECK_OK(orthoslip_solution_tractions((const orthoslip_solution *)ctx, &x, 1, p, q));
}

/* The traction profile of solution s (by method, friction mu, bp = A/(pi C)): its tractions,
 * its stick edge and its edge exponent, 1/2 for Goodman, else 1/2 - arctan(bp mu)/pi. */
static inline traction_field solution_field(const orthoslip_solution *s, orthoslip_method method,
                                            double bp, double mu)
{
    traction_field f;
    f.eval = solution_tractions_at;
    f.ctx = s;
    CHECK_OK(orthoslip_solution_stick_half_width(s, &f.c));
    f.g = method == ORTHOSLIP_METHOD_GOODMAN ? 0.5 : 0.5 - atan(bp * mu) / TEST_PI;
    return f;
}

/* Points per half of a zone: 10 (20 per zone), 2 in quick mode. */
static inline int residual_points(void)
{
    return test_quick() ? 2 : 10;
}

/* The k-th of 2n points inside (lo, hi) mirrored to both signs: +-(lo + (hi-lo)(j+1/2)/n). */
static inline double zone_point(double lo, double hi, int k, int n)
{
    double x = lo + (hi - lo) * ((k % n) + 0.5) / n;
    return k < n ? x : -x;
}

static inline void check_e2(hilbert_quad *h, const traction_field *f,
                            const reference_constants *k, residual_summary *sum)
{
    int i, n = residual_points();
    for (i = 0; i < 2 * n; i++) {
        double x = zone_point(0.0, f->c, i, n);
        double p = field_value(f, FIELD_P, x);
        double pv = field_principal_value(h, f, FIELD_Q, x);
        double r = fabs(k->b * pv + k->a * p) / fabs(k->a * p);
        raise_to(&sum->e2, r);
        CHECK_LE(r, RESIDUAL_TOLERANCE);
    }
}

static inline void check_e1(hilbert_quad *h, const traction_field *f,
                            const reference_constants *k, double mu, residual_summary *sum)
{
    int i, zone, n = residual_points();
    for (zone = 0; zone < 2; zone++) {
        for (i = 0; i < 2 * n; i++) {
            double x = zone == 0 ? zone_point(0.0, f->c, i, n) : zone_point(f->c, 1.0, i, n);
            double p, q, term_p, term_q, size, r;
            f->eval(f->ctx, x, &p, &q);
            term_p = k->c * field_principal_value(h, f, FIELD_P, x);
            term_q = k->a * q;
            size = fmax(fmax(fabs(term_p), fabs(term_q)), k->a * mu * p);
            r = fabs(term_p - term_q) / size;
            raise_to(&sum->e1, r);
            CHECK_LE(r, RESIDUAL_TOLERANCE);
        }
    }
}

static inline void check_integrals(hilbert_quad *h, const traction_field *f, double mu,
                                   residual_summary *sum)
{
    double dp = fabs(field_integral(h, f, FIELD_P) - 1.0);
    double dq = fabs(field_integral(h, f, FIELD_Q));
    raise_to(&sum->int_p, dp);
    raise_to(&sum->int_q, dq);
    CHECK_LE(dp, 1e-10);
    CHECK_LE(dq, 1e-10 * mu + 1e-15);
}

/* Pointwise friction law and symmetry at the points of a uniform grid, the stick-zone points
 * of check_e2 and +-c(1 -+ 1e-3) (close to the stick edges, but not so close that the solver's
 * error in c, e.g. 5e-9 for c = 5e-5, decides the sign of mu p - |q|). */
static inline void check_friction(const traction_field *f, double mu, residual_summary *sum)
{
    const int n_grid = 400, n_zone = residual_points();
    int i;
    for (i = 0; i < n_grid + 2 * n_zone + 4; i++) {
        double x, p, q, pm, qm, sx;
        if (i < n_grid)
            x = -1.0 + 2.0 * (i + 0.5) / n_grid;
        else if (i < n_grid + 2 * n_zone)
            x = zone_point(0.0, f->c, i - n_grid, n_zone);
        else
            x = f->c * (i % 2 ? 1.0 + 1e-3 : 1.0 - 1e-3) * (i % 4 < 2 ? 1.0 : -1.0);
        if (!(fabs(x) < 1.0) || x == 0.0) continue;
        sx = x > 0 ? 1.0 : -1.0;
        f->eval(f->ctx, x, &p, &q);
        f->eval(f->ctx, -x, &pm, &qm);
        CHECK(p > 0.0 && isfinite(p) && isfinite(q));
        CHECK_LE(fabs(pm - p), 1e-12 * p);
        CHECK_LE(fabs(qm + q), 1e-12 * (fabs(q) + mu * p));
        if (fabs(x) < f->c) {
            raise_to(&sum->stick_ratio, fabs(q) / (mu * p));
            CHECK_LE(fabs(q), mu * p * (1.0 + 1e-10));
        } else if (fabs(x) > f->c) {
            CHECK_LE(fabs(q - mu * p * sx), 1e-12 * mu * p);
            if (x > 0.0 && mu > 0.0) CHECK(q > 0.0);
        }
    }
}

/* bq p(t) + H[q](t) for c < t < 1. */
static inline double slip_rate(hilbert_quad *h, const traction_field *f, double bq, double t)
{
    return bq * field_value(f, FIELD_P, t) + field_principal_value(h, f, FIELD_Q, t) / TEST_PI;
}

/* J(x_j) >= 0 at x_j = c + 0.95 (1-c) (j/m)^2, j = 1..m, by 8-point Gauss-Legendre panels
 * (graded towards c, where the integrand behaves like (t - c)^g). */
static inline void check_slip_direction(hilbert_quad *h, const traction_field *f, double bq,
                                        residual_summary *sum)
{
    const int m = residual_points() < 10 ? 2 : 8;
    gsl_integration_glfixed_table *gl = gsl_integration_glfixed_table_alloc(8);
    double j_sum = 0.0, j_abs = 0.0, prev = f->c;
    int j;
    size_t node;
    for (j = 1; j <= m; j++) {
        double s = (double)j / m, next = f->c + 0.95 * (1.0 - f->c) * s * s;
        for (node = 0; node < 8; node++) {
            double t, w, v;
            gsl_integration_glfixed_point(prev, next, node, &t, &w, gl);
            v = slip_rate(h, f, bq, t);
            j_sum += w * v;
            j_abs += w * fabs(v);
        }
        double ratio = j_sum / j_abs;
        if (!(sum->slip_direction_min <= ratio)) sum->slip_direction_min = ratio;
        CHECK_LE(-1e-10 * j_abs, j_sum);
        prev = next;
    }
    gsl_integration_glfixed_table_free(gl);
}

/* Solves material m with friction mu by method and runs the checks in mask; g is the edge
 * exponent of the method's p (1/2 for Goodman, else 1/2 - arctan(bp mu)/pi). */
static inline void check_residuals(const test_material *m, double mu, orthoslip_method method,
                                   int mask, residual_summary *sum)
{
    reference_constants k = reference_constants_of(m);
    orthoslip_contact *contact = test_contact_new(m, mu, method);
    orthoslip_solution *s = NULL;
    hilbert_quad h = hilbert_quad_new();
    traction_field f;
    double bp = k.a / (TEST_PI * k.c), bq = k.a / (TEST_PI * k.b);
    /* The project's accuracy target: c to 1e-10, tractions to 1e-8 (the closed forms ignore
     * the tolerances). */
    CHECK_OK(orthoslip_contact_set_tolerance(contact, 1e-10));
    CHECK_OK(orthoslip_contact_set_traction_tolerance(contact, 1e-8));
    CHECK_OK(orthoslip_contact_solve(contact, &s));
    f = solution_field(s, method, bp, mu);
    printf("  %s, mu = %g: c = %.6f\n", m->name, mu, f.c);
    fflush(stdout);
    if (mask & RESIDUAL_INTEGRALS) check_integrals(&h, &f, mu, sum);
    if (mask & RESIDUAL_FRICTION) check_friction(&f, mu, sum);
    if (mask & RESIDUAL_E2) check_e2(&h, &f, &k, sum);
    if (mask & RESIDUAL_E1) check_e1(&h, &f, &k, mu, sum);
    if (mask & RESIDUAL_SLIP_DIRECTION) check_slip_direction(&h, &f, bq, sum);
    sum->quad_failures += h.failures;
    if (h.failures) sum->last_quad_failure = h.last_failure;
    sum->cases++;
    hilbert_quad_free(&h);
    orthoslip_solution_free(s);
    orthoslip_contact_free(contact);
}

/* The whole program: every test material with mu = 0.1, 0.3 and 1 (quick mode: 0.3) by
 * method, checks in mask; prints the largest deviations. */
static inline int residual_program(const char *program, orthoslip_method method, int mask)
{
    static const double frictions[] = {0.1, 0.3, 1.0};
    const size_t first = test_quick() ? 1 : 0;
    const size_t last = test_quick() ? 2 : sizeof frictions / sizeof frictions[0];
    size_t n_mat, i, j;
    const test_material *mats = test_materials(&n_mat);
    residual_summary s = residual_summary_new();
    gsl_set_error_handler_off();
    for (i = 0; i < n_mat; i++)
        for (j = first; j < last; j++)
            check_residuals(&mats[i], frictions[j], method, mask, &s);
    printf("%s: %d cases: max rel. residual (E1) %.3e, (E2) %.3e; max |int p - 1| %.3e, "
           "|int q| %.3e; max |q|/(mu p) on stick %.6f; min J/int|.| on slip %.3e (nan: not "
           "checked); "
           "%d GSL calls without GSL_SUCCESS (last: %s)\n",
           program, s.cases, s.e1, s.e2, s.int_p, s.int_q, s.stick_ratio, s.slip_direction_min,
           s.quad_failures, gsl_strerror(s.last_quad_failure));
    return 0;
}

#endif
