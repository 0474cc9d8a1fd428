/* GSL quadrature of traction profiles on (-1, 1) (valid C11 and C++17): integrals and
 * principal values PV int_{-1}^{1} f(t) / (x - t) dt of a field f = p or q that behaves like
 * (1 - |t|)^(-g) at the punch edges and is non-smooth at the stick-zone edges t = +-c.
 * The interval is split at +-c, at the edge pieces [-1, -1+e], [1-e, 1] (gsl_integration_qaws
 * with the weight (t+1)^(-g) resp. (1-t)^(-g); qaws' alpha applies at the LEFT end) and, for a
 * principal value, at [x-h, x+h]; the remaining pieces use gsl_integration_qag (no
 * extrapolation: qags' epsilon algorithm was misled by the near-singularity 1 - c ~ 3e-8 away
 * from a piece's end). Every piece ends at the non-smooth points, never straddles them.
 *
 * The principal value on [x-h, x+h] is int_0^h (f(x-s) - f(x+s)) / s ds by a fixed
 * Gauss-Legendre rule (gsl_integration_glfixed), HILBERT_PV_NODES points and twice as many,
 * their difference counted as the quadrature error. h is at most half the distance from x to
 * the nearest non-smooth point, so the integrand is analytic in a disc of radius 2h around
 * s = 0 and the rule converges like 5.8^(-2n). An adaptive rule (gsl_integration_qawc) is not
 * used there: it subdivides towards s = 0 to meet its tolerance and so magnifies a white
 * rounding noise of the profile (relative size eps) by about 1e5 at 1e-12 (a noise of 1e-13
 * of p added to an exact profile gave residuals of 1.06e-8); the fixed rule magnifies it by
 * sum w_i / s_i (h = 1), 7.6 at 24 points and 8.9 at 48. */
#ifndef ORTHOSLIP_TEST_HILBERT_H
#define ORTHOSLIP_TEST_HILBERT_H

#include <math.h>
#include <stddef.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#define HILBERT_LIMIT 1000
#define HILBERT_EPSABS 1e-14
#define HILBERT_EPSREL 1e-12
#define HILBERT_EDGE_OFFSET 1e-12
#define HILBERT_PV_NODES 24

typedef enum { FIELD_P = 0, FIELD_Q = 1 } field_component;

/* A traction profile: eval writes p(x), q(x) for -1 < x < 1. */
typedef struct {
    void (*eval)(const void *ctx, double x, double *p, double *q);
    const void *ctx;
    double c; /* stick half-width, 0 <= c < 1 */
    double g; /* edge exponent, 0 < g < 1 */
} traction_field;

/* Quadrature bookkeeping: sum of GSL's error estimates, and how many calls did not report
 * GSL_SUCCESS (their results are still used; the residual checks judge them). */
typedef struct {
    double abserr;
    int failures, last_failure;
    gsl_integration_workspace *work;
} hilbert_quad;

static inline hilbert_quad hilbert_quad_new(void)
{
    hilbert_quad h;
    h.abserr = 0.0;
    h.failures = h.last_failure = 0;
    h.work = gsl_integration_workspace_alloc(HILBERT_LIMIT);
    return h;
}

static inline void hilbert_quad_free(hilbert_quad *h)
{
    gsl_integration_workspace_free(h->work);
}

static inline double field_value(const traction_field *f, field_component which, double x)
{
    double p, q;
    f->eval(f->ctx, x, &p, &q);
    return which == FIELD_P ? p : q;
}

/* The integrand f(t) * w(t) / (x - t) (x ignored when has_pole == 0), with w(t) = (t+1)^g,
 * (1-t)^g or 1 cancelling the qaws weight. */
typedef struct {
    const traction_field *field;
    field_component which;
    double x;
    int has_pole;
    int edge; /* -1: times (t+1)^g, +1: times (1-t)^g, 0: plain */
} hilbert_integrand;

/* qaws also samples the end points, where only the weighted product is finite: the point
 * HILBERT_EDGE_OFFSET inside stands for them (edge -1: t = -1, +1: t = 1, 0: none). */
static inline double edge_point(int edge, double t)
{
    if (edge < 0 && t + 1.0 < HILBERT_EDGE_OFFSET) return -1.0 + HILBERT_EDGE_OFFSET;
    if (edge > 0 && 1.0 - t < HILBERT_EDGE_OFFSET) return 1.0 - HILBERT_EDGE_OFFSET;
    return t;
}

/* The factor (t+1)^g (edge -1) or (1-t)^g (edge +1) that cancels qaws' weight, 1 otherwise. */
static inline double edge_factor(int edge, double g, double t)
{
    if (edge < 0) return pow(t + 1.0, g);
    if (edge > 0) return pow(1.0 - t, g);
    return 1.0;
}

static inline double hilbert_integrand_eval(double t, void *params)
{
    const hilbert_integrand *in = (const hilbert_integrand *)params;
    double v;
    t = edge_point(in->edge, t);
    v = field_value(in->field, in->which, t) * edge_factor(in->edge, in->field->g, t);
    if (in->has_pole) v /= in->x - t;
    return v;
}

static inline void hilbert_account(hilbert_quad *h, int status, double abserr)
{
    h->abserr += abserr;
    if (status != GSL_SUCCESS) {
        h->failures++;
        h->last_failure = status;
    }
}

/* int_a^b of fn: gsl_integration_qaws with the weight (t - a)^(-g) when edge < 0 (a = -1) or
 * (b - t)^(-g) when edge > 0 (b = 1), gsl_integration_qag when edge = 0. */
static inline double quad_piece(hilbert_quad *h, gsl_function *fn, int edge, double g, double a,
                                double b)
{
    double result = 0.0, abserr = 0.0;
    int status;
    if (edge != 0) {
        double alpha = edge < 0 ? -g : 0.0, beta = edge > 0 ? -g : 0.0;
        gsl_integration_qaws_table *table = gsl_integration_qaws_table_alloc(alpha, beta, 0, 0);
        status = gsl_integration_qaws(fn, a, b, table, HILBERT_EPSABS, HILBERT_EPSREL,
                                      HILBERT_LIMIT, h->work, &result, &abserr);
        gsl_integration_qaws_table_free(table);
    } else {
        status = gsl_integration_qag(fn, a, b, HILBERT_EPSABS, HILBERT_EPSREL, HILBERT_LIMIT,
                                     GSL_INTEG_GAUSS21, h->work, &result, &abserr);
    }
    hilbert_account(h, status, abserr);
    return result;
}

/* int_a^b of the integrand with edge = -1 (a = -1), +1 (b = 1) or 0. */
static inline double hilbert_piece(hilbert_quad *h, hilbert_integrand *in, double a, double b)
{
    gsl_function fn;
    fn.function = hilbert_integrand_eval;
    fn.params = in;
    return quad_piece(h, &fn, in->edge, in->field->g, a, b);
}

/* int_0^h (f(x-s) - f(x+s)) / s ds by n-point Gauss-Legendre. */
static inline double symmetric_rule(const traction_field *f, field_component which, double x,
                                    double h, size_t n)
{
    gsl_integration_glfixed_table *gl = gsl_integration_glfixed_table_alloc(n);
    double sum = 0.0, s, w;
    size_t i;
    for (i = 0; i < n; i++) {
        gsl_integration_glfixed_point(0.0, h, i, &s, &w, gl);
        sum += w * (field_value(f, which, x - s) - field_value(f, which, x + s)) / s;
    }
    gsl_integration_glfixed_table_free(gl);
    return sum;
}

/* PV int_{x-h}^{x+h} f(t) / (x - t) dt, f analytic within 2h of x: the symmetric rule at
 * HILBERT_PV_NODES and twice as many points, the difference counted as its error. */
static inline double symmetric_principal_value(hilbert_quad *h, const traction_field *f,
                                               field_component which, double x, double half)
{
    double coarse = symmetric_rule(f, which, x, half, HILBERT_PV_NODES);
    double fine = symmetric_rule(f, which, x, half, 2 * HILBERT_PV_NODES);
    hilbert_account(h, GSL_SUCCESS, fabs(fine - coarse));
    return fine;
}

/* Sorted break points -1 < -1+e <= -c <= c <= 1-e < 1 with e = (1 - max(c, |x|))/2 (so that x
 * lies in no edge piece); writes 4 points. */
static inline void hilbert_breaks(const traction_field *f, double x, double br[4])
{
    double far = f->c > fabs(x) ? f->c : fabs(x);
    double e = 0.5 * (1.0 - far);
    br[0] = -1.0 + e;
    br[1] = -f->c;
    br[2] = f->c;
    br[3] = 1.0 - e;
}

/* Sum over the pieces; with a pole at x (|x| < 1, x != +-c), the piece around x is split
 * into [lo, x-h], the symmetric rule on [x-h, x+h], [x+h, hi]. */
static inline double hilbert_sum(hilbert_quad *h, const traction_field *f,
                                 field_component which, int has_pole, double x)
{
    hilbert_integrand in;
    double br[4], sum = 0.0;
    size_t i;
    in.field = f;
    in.which = which;
    in.x = x;
    in.has_pole = has_pole;
    hilbert_breaks(f, has_pole ? x : 0.0, br);
    in.edge = -1;
    sum += hilbert_piece(h, &in, -1.0, br[0]);
    in.edge = 1;
    sum += hilbert_piece(h, &in, br[3], 1.0);
    in.edge = 0;
    for (i = 0; i < 3; i++) {
        double lo = br[i], hi = br[i + 1];
        if (!(hi > lo)) continue;
        if (has_pole && lo < x && x < hi) {
            double half = 0.5 * fmin(x - lo, hi - x);
            sum += hilbert_piece(h, &in, lo, x - half);
            sum += hilbert_piece(h, &in, x + half, hi);
            sum += symmetric_principal_value(h, f, which, x, half);
        } else {
            sum += hilbert_piece(h, &in, lo, hi);
        }
    }
    return sum;
}

/* int_{-1}^{1} f(t) dt. */
static inline double field_integral(hilbert_quad *h, const traction_field *f,
                                    field_component which)
{
    return hilbert_sum(h, f, which, 0, 0.0);
}

/* PV int_{-1}^{1} f(t) / (x - t) dt for |x| < 1, x != +-c. */
static inline double field_principal_value(hilbert_quad *h, const traction_field *f,
                                           field_component which, double x)
{
    return hilbert_sum(h, f, which, 1, x);
}

#endif
