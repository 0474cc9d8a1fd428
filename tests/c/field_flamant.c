/* The stresses inside the solid (orthoslip_solution_stresses) of isotropic scenes against
 * Flamant's line-load kernels integrated by GSL over the library's own tractions (valid C11
 * and C++17). With r = x - t and the depth Y = -y > 0 (Johnson, Contact Mechanics, eqs.
 * 2.19-2.21, turned to y pointing out of the solid), a pressure p and a shear q (on the solid,
 * +x) at t give
 *   sxx = -(2/pi) int (p r^2 Y + q r^3) / (r^2 + Y^2)^2 dt,
 *   syy = -(2/pi) int (p Y^3 + q r Y^2) / (r^2 + Y^2)^2 dt,
 *   sxy =  (2/pi) int (p r Y^2 + q r^2 Y) / (r^2 + Y^2)^2 dt.
 * The tractions' edge singularity (1 - |t|)^(-g) is GSL QAWS's weight on the edge pieces; the
 * rest is split at +-c and around x and integrated by QAG. GOODMAN, SPENCE and COUPLED, to
 * 1e-8 of p(0) (LCP's tractions, interpolated between its 200-3200 grid midpoints, have a
 * kink at each, more than QAG's interval limit can resolve to that accuracy; tests/field.rs
 * checks its field by resultants, equilibrium and surface limits). */
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
    const traction_field *field;
    double x, depth;
    int component; /* 0: sxx, 1: syy, 2: sxy */
    int edge;      /* -1: times (t+1)^g, +1: times (1-t)^g, 0: plain */
} flamant_integrand;

static double flamant_eval(double t, void *params)
{
    const flamant_integrand *in = (const flamant_integrand *)params;
    double p, q, r, y = in->depth, d, v;
    t = edge_point(in->edge, t);
    in->field->eval(in->field->ctx, t, &p, &q);
    r = in->x - t;
    d = (r * r + y * y) * (r * r + y * y);
    switch (in->component) {
    case 0: v = -(p * r * r * y + q * r * r * r); break;
    case 1: v = -(p * y * y * y + q * r * y * y); break;
    default: v = p * r * y * y + q * r * r * y; break;
    }
    return v * 2.0 / (TEST_PI * d) * edge_factor(in->edge, in->field->g, t);
}

static double flamant_piece(hilbert_quad *h, flamant_integrand *in, double a, double b)
{
    gsl_function fn;
    fn.function = flamant_eval;
    fn.params = in;
    return quad_piece(h, &fn, in->edge, in->field->g, a, b);
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* One stress component at (x, -depth): edge pieces of width e = (1 - max(c, |x|))/2 (or
 * (1 - c)/2 for points beyond the punch), interior pieces split at +-c and at x and
 * x +- 4 depth when inside. */
static double flamant_stress(hilbert_quad *h, const traction_field *f, double x, double depth,
                             int component)
{
    flamant_integrand in;
    double far = fabs(x) < 1.0 && fabs(x) > f->c ? fabs(x) : f->c;
    double e = 0.5 * (1.0 - far), br[7], sum = 0.0;
    size_t n = 0, i;
    in.field = f;
    in.x = x;
    in.depth = depth;
    in.component = component;
    br[n++] = -1.0 + e;
    br[n++] = 1.0 - e;
    if (f->c > 0.0) {
        br[n++] = -f->c;
        br[n++] = f->c;
    }
    {
        double around[3] = {x - 4.0 * depth, x, x + 4.0 * depth};
        for (i = 0; i < 3; i++)
            if (around[i] > -1.0 + e && around[i] < 1.0 - e) br[n++] = around[i];
    }
    qsort(br, n, sizeof br[0], compare_doubles);
    in.edge = -1;
    sum += flamant_piece(h, &in, -1.0, br[0]);
    in.edge = 1;
    sum += flamant_piece(h, &in, br[n - 1], 1.0);
    in.edge = 0;
    for (i = 0; i + 1 < n; i++)
        if (br[i + 1] > br[i]) sum += flamant_piece(h, &in, br[i], br[i + 1]);
    return sum;
}

int main(void)
{
    static const orthoslip_method methods[] = {ORTHOSLIP_METHOD_GOODMAN, ORTHOSLIP_METHOD_SPENCE,
                                               ORTHOSLIP_METHOD_COUPLED};
    static const char *names[] = {"GOODMAN", "SPENCE", "COUPLED"};
    /* isotropic test materials: steel in plane strain and the auxetic one */
    static const test_material steel = {"steel, plane strain", 1, 210e9, 210e9, 210e9,
                                        210e9 / 2.6, 0.3, 0.3, 0.3};
    static const test_material auxetic = {"auxetic isotropic (nu = -0.5), plane stress", 0,
                                          1e9, 1e9, 0.0, 1e9, -0.5, 0.0, 0.0};
    const test_material *mats[] = {&steel, &auxetic};
    const size_t n_mat = test_quick() ? 1 : 2, n_method = test_quick() ? 2 : 3;
    double worst = 0.0;
    int points = 0, failures = 0;
    size_t i, j, k;
    gsl_set_error_handler_off();
    for (i = 0; i < n_mat; i++) {
        reference_constants rc = reference_constants_of(mats[i]);
        double bp = rc.a / (TEST_PI * rc.c), mu = 0.3;
        CHECK(rc.delta == 1.0 || fabs(rc.delta - 1.0) < 1e-15);
        for (j = 0; j < n_method; j++) {
            orthoslip_contact *contact = test_contact_new(mats[i], mu, methods[j]);
            orthoslip_solution *s = NULL;
            hilbert_quad h = hilbert_quad_new();
            traction_field f;
            double p0, q0, x0 = 0.0;
            /* COUPLED's tractions carry its wrong-c modes |x - c|^(g-1) at the size of its
               error, which the field leaves out: solve tightly enough for them to vanish */
            CHECK_OK(orthoslip_contact_set_tolerance(contact, 1e-12));
            CHECK_OK(orthoslip_contact_set_traction_tolerance(contact, 1e-8)); /* the field's target */
            CHECK_OK(orthoslip_contact_solve(contact, &s));
            f = solution_field(s, methods[j], bp, mu);
            CHECK_OK(orthoslip_solution_tractions(s, &x0, 1, &p0, &q0));
            {
                const double c = f.c;
                const double xs[] = {0.0,   0.5 * c, c,     0.5 * (1.0 + c), 0.95, 1.0, -1.0,
                                     1.3,   -0.4,    2.0,   0.3,             c,    0.999};
                const double ys[] = {-1e-3, -1e-2, -1e-3, -1e-2, -1e-2, -0.05, -0.1,
                                     -0.2,  -0.7,  -1.5,  -1e-6, -1e-6, -1e-6};
                const size_t n_pts = test_quick() ? 3 : sizeof xs / sizeof xs[0];
                for (k = 0; k < n_pts; k++) {
                    double x = xs[k], y = ys[k];
                    double st[3], ref[3], gap = 0.0;
                    int comp;
                    CHECK_OK(orthoslip_solution_stresses(s, &x, &y, 1, &st[0], &st[1], &st[2]));
                    for (comp = 0; comp < 3; comp++) {
                        ref[comp] = flamant_stress(&h, &f, x, -y, comp);
                        gap = fmax(gap, fabs(st[comp] - ref[comp]) / p0);
                    }
                    if (!(gap <= TOLERANCE))
                        fprintf(stderr, "%s %s (%g, %g): (%.17g, %.17g, %.17g) vs GSL (%.17g, "
                                "%.17g, %.17g)\n", mats[i]->name, names[j], x, y, st[0], st[1],
                                st[2], ref[0], ref[1], ref[2]);
                    CHECK_LE(gap, TOLERANCE);
                    worst = fmax(worst, gap);
                    points++;
                }
            }
            failures += h.failures;
            hilbert_quad_free(&h);
            orthoslip_solution_free(s);
            orthoslip_contact_free(contact);
        }
    }
    printf("field_flamant: %d points, max |stress - Flamant by GSL| / p(0) = %.2e; %d GSL calls "
           "without GSL_SUCCESS\n", points, worst, failures);
    return 0;
}
