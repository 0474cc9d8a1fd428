/* orthoslip_history_solution: a load-path state through the solution getters (valid C11 and
 * C++17), checked against facts the library does not use:
 * - the stresses inside the solid of an isotropic scene against Flamant's line-load kernels
 *   integrated by GSL over the solution's own tractions, without symmetry (Johnson, Contact
 *   Mechanics, eqs. 2.19-2.21, y pointing out of the solid, depth Y = -y > 0, r = x - t):
 *     sxx = -(2/pi) int (p r^2 Y + q r^3) / (r^2 + Y^2)^2 dt,
 *     syy = -(2/pi) int (p Y^3 + q r Y^2) / (r^2 + Y^2)^2 dt,
 *     sxy =  (2/pi) int (p r Y^2 + q r^2 Y) / (r^2 + Y^2)^2 dt,
 *   split at the grid midpoints and 0 (where the interpolated tractions have kinks), the end
 *   pieces by QAWS with the edge weight (1 -+ t)^(-g), g = 1/2 - arctan(b* mu) / pi;
 * - equilibrium: int p = 1, int q = Q/P (within the traction error estimate);
 * - the surface conditions syy(x, 0) = -p(x), sxy(x, 0) = q(x) between the midpoints;
 * - mirror symmetry under Q -> -Q: p(x) -> p(-x), q(x) -> -q(-x), (sxx, syy, sxy)(x, y) ->
 *   (sxx, syy, -sxy)(-x, y); the stick set [c1, c2] -> [-c2, -c1];
 * - the getters without meaning for an asymmetric state refused with
 *   ORTHOSLIP_ERROR_INVALID_ARGUMENT, a message and nothing written; NULL arguments refused
 *   with *out set to NULL; the solution outlives its history. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include "check.h"

#define SENTINEL 12345.0
#define PI 3.14159265358979323846
#define PANELS 40
#define LOAD 0.2
#define MU 0.5
#define NU 0.4 /* isotropic form: b* = (1 - nu) / 2 */

typedef struct {
    const orthoslip_solution *s;
    double x, depth, g;
    int what; /* 0..2: sxx, syy, sxy at (x, -depth); 3: p; 4: q */
    int edge; /* -1: times (1 + t)^g, +1: times (1 - t)^g, 0: plain */
} integrand;

static double eval(double t, void *params)
{
    const integrand *in = (const integrand *)params;
    double p, q, r, y = in->depth, d, v;
    /* the edge pieces' factors (1 -+ t)^g are 0 at the punch edges, where p is infinite:
     * there the (constant) regular part from next to the edge */
    if (in->edge != 0 && fabs(t) >= 1.0 - 1e-15) t = copysign(1.0 - 1e-15, t);
    r = in->x - t;
    CHECK_OK(orthoslip_solution_tractions(in->s, &t, 1, &p, &q));
    if (in->edge != 0) {
        double f = pow(in->edge > 0 ? 1.0 - t : 1.0 + t, in->g);
        p *= f;
        q *= f;
    }
    if (in->what == 3) return p;
    if (in->what == 4) return q;
    d = (r * r + y * y) * (r * r + y * y);
    switch (in->what) {
    case 0: v = -(p * r * r * y + q * r * r * r); break;
    case 1: v = -(p * y * y * y + q * r * y * y); break;
    default: v = p * r * y * y + q * r * r * y; break;
    }
    return v * 2.0 / (PI * d);
}

/* int over [-1, 1] of the integrand, piece by piece. */
static double integral(integrand *in, gsl_integration_workspace *ws,
                       gsl_integration_qaws_table *left, gsl_integration_qaws_table *right)
{
    double breaks[2 * PANELS + 3], total = 0.0, v, err;
    double h = 1.0 / PANELS;
    int i, m = 0;
    gsl_function fn;
    fn.function = eval;
    fn.params = in;
    breaks[m++] = -1.0;
    for (i = 0; i < 2 * PANELS; i++) {
        if (i == PANELS) breaks[m++] = 0.0;
        breaks[m++] = -1.0 + (i + 0.5) * h;
    }
    breaks[m++] = 1.0;
    for (i = 0; i + 1 < m; i++) {
        double a = breaks[i], b = breaks[i + 1];
        if (i == 0) {
            in->edge = -1;
            CHECK(gsl_integration_qaws(&fn, a, b, left, 1e-14, 1e-12, 200, ws, &v, &err) == 0);
        } else if (i + 2 == m) {
            in->edge = 1;
            CHECK(gsl_integration_qaws(&fn, a, b, right, 1e-14, 1e-12, 200, ws, &v, &err) == 0);
        } else {
            in->edge = 0;
            CHECK(gsl_integration_qag(&fn, a, b, 1e-14, 1e-12, 200, GSL_INTEG_GAUSS21, ws, &v,
                                      &err) == 0);
        }
        total += v;
    }
    return total;
}

static orthoslip_history *loaded(const orthoslip_contact *k, double q_over_p)
{
    orthoslip_cycle_options *o = NULL;
    orthoslip_history *h = NULL;
    CHECK_OK(orthoslip_cycle_options_new(&o));
    CHECK_OK(orthoslip_cycle_options_set_panels(o, PANELS));
    CHECK_OK(orthoslip_cycle_options_set_steps(o, 4));
    CHECK_OK(orthoslip_history_new_with_options(k, o, &h));
    orthoslip_cycle_options_free(o);
    CHECK_OK(orthoslip_history_load(h, q_over_p));
    return h;
}

#ifdef __cplusplus
/* The C++ build also checks the RAII wrapper (c_examples/orthoslip.hpp): history::solution()
 * gives the C call's numbers, and the refused getters throw with the status. */
#include "orthoslip.hpp"

static void cxx_wrapper(void)
{
    const auto mat = orthoslip::material::effective(1.0, NU, 1.0, 1.0);
    orthoslip::contact k(mat);
    k.friction(MU);
    orthoslip::cycle_options o;
    o.panels(16).steps(2);
    auto h = k.history(o);
    h.load(LOAD);
    const auto s = h.solution();
    const auto z = s.stick_zone();
    const auto hz = h.stick_zone();
    CHECK(z.c1 == hz.c1 && z.c2 == hz.c2 && z.error == hz.error);
    orthoslip_solution *raw = NULL;
    double x = 0.3, y = -0.2, p, q, a, b, c;
    CHECK_OK(orthoslip_history_solution(h.get(), &raw));
    CHECK_OK(orthoslip_solution_tractions(raw, &x, 1, &p, &q));
    CHECK_OK(orthoslip_solution_stresses(raw, &x, &y, 1, &a, &b, &c));
    orthoslip_solution_free(raw);
    const auto t = s.at({x});
    const auto st = s.stresses({x}, {y});
    CHECK(t.p[0] == p && t.q[0] == q && st.sxx[0] == a && st.syy[0] == b && st.sxy[0] == c);
    int thrown = 0;
    try {
        (void)s.stick_half_width();
    } catch (const orthoslip::error &ex) {
        thrown = ex.status() == ORTHOSLIP_ERROR_INVALID_ARGUMENT;
    }
    CHECK(thrown);
}
#endif

int main(void)
{
    orthoslip_material *mat = NULL;
    orthoslip_contact *k = NULL;
    orthoslip_history *h, *hm;
    orthoslip_solution *s = NULL, *sm = NULL;
    orthoslip_method used;
    double b = 0.5 * (1.0 - NU), g = 0.5 - atan(b * MU) / PI;
    double c1, c2, d1, d2, e, e2, v, ip, iq, worst_flamant = 0.0, worst_surface = 0.0,
                                            worst_mirror = 0.0;
    double xs[] = {-1.3, -0.93, -0.61, -0.2, 0.07, 0.38, 0.77, 0.96, 1.25};
    double depths[] = {0.04, 0.3, 1.5};
    int quick = test_quick(), i, j, c, nx = quick ? 3 : 9, nd = quick ? 1 : 3;
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(200);
    gsl_integration_qaws_table *left = gsl_integration_qaws_table_alloc(-g, 0.0, 0, 0);
    gsl_integration_qaws_table *right = gsl_integration_qaws_table_alloc(0.0, -g, 0, 0);
    integrand in;
    gsl_set_error_handler_off();

    CHECK_OK(orthoslip_material_new_effective(1.0, NU, 1.0, 1.0, &mat));
    CHECK_OK(orthoslip_contact_new(mat, &k));
    CHECK_OK(orthoslip_contact_set_friction(k, MU));
    h = loaded(k, LOAD);
    hm = loaded(k, -LOAD);
    CHECK_OK(orthoslip_history_solution(h, &s));
    CHECK_OK(orthoslip_history_solution(hm, &sm));
    CHECK(s != NULL && sm != NULL);

    /* the stick set and the estimates are the history's */
    CHECK_OK(orthoslip_solution_method(s, &used));
    CHECK(used == ORTHOSLIP_METHOD_LCP);
    CHECK_OK(orthoslip_solution_stick_zone(s, &c1, &c2));
    CHECK_OK(orthoslip_history_stick_zone(h, &d1, &d2, &e));
    CHECK(c1 == d1 && c2 == d2 && -1.0 <= c1 && c1 < c2 && c2 < 1.0);
    CHECK_OK(orthoslip_solution_error_estimate(s, &v));
    CHECK(v == e);
    CHECK_OK(orthoslip_solution_stick_zone(sm, &d1, &d2));
    CHECK_LE(fabs(c1 + d2) + fabs(c2 + d1), 1e-10);
    CHECK_OK(orthoslip_solution_traction_error_estimate(s, &e));
    CHECK_OK(orthoslip_history_traction_error_estimate(h, &e2));
    CHECK(e == e2 && e > 0.0 && isfinite(e));

    /* equilibrium from the solution's tractions */
    in.s = s;
    in.g = g;
    in.x = 0.0;
    in.depth = 1.0;
    in.what = 3;
    ip = integral(&in, ws, left, right);
    in.what = 4;
    iq = integral(&in, ws, left, right);
    printf("history_solution: Q/P = %g: int p - 1 = %.2e, int q - Q/P = %.2e, "
           "traction estimate %.2e\n",
           LOAD, ip - 1.0, iq - LOAD, e);
    CHECK_LE(fabs(ip - 1.0) + fabs(iq - LOAD), e);

    /* Flamant at depth, the surface conditions, the mirror image */
    for (i = 0; i < nx; i++) {
        for (j = 0; j < nd; j++) {
            double x = xs[i], y = -depths[j], st[3], mt[3], mx = -x;
            CHECK_OK(orthoslip_solution_stresses(s, &x, &y, 1, st, st + 1, st + 2));
            CHECK_OK(orthoslip_solution_stresses(sm, &mx, &y, 1, mt, mt + 1, mt + 2));
            for (c = 0; c < 3; c++) {
                in.x = x;
                in.depth = depths[j];
                in.what = c;
                v = integral(&in, ws, left, right);
                if (fabs(st[c] - v) > worst_flamant) worst_flamant = fabs(st[c] - v);
                v = c == 2 ? -mt[c] : mt[c];
                if (fabs(st[c] - v) > worst_mirror) worst_mirror = fabs(st[c] - v);
            }
        }
    }
    for (i = 0; i < 2 * PANELS; i += quick ? 7 : 1) {
        double x = -1.0 + (i + 0.5) / PANELS + 0.3 / PANELS, y = 0.0, mx = -x, p, q, pm, qm,
               st[3];
        if (x >= 1.0) continue;
        CHECK_OK(orthoslip_solution_tractions(s, &x, 1, &p, &q));
        CHECK_OK(orthoslip_solution_tractions(sm, &mx, 1, &pm, &qm));
        CHECK_OK(orthoslip_solution_stresses(s, &x, &y, 1, st, st + 1, st + 2));
        v = fabs(st[1] + p) > fabs(st[2] - q) ? fabs(st[1] + p) : fabs(st[2] - q);
        if (v > worst_surface) worst_surface = v;
        v = fabs(p - pm) > fabs(q + qm) ? fabs(p - pm) : fabs(q + qm);
        if (v > worst_mirror) worst_mirror = v;
    }
    printf("history_solution: stresses against Flamant %.2e, surface conditions %.2e, "
           "mirror Q -> -Q %.2e\n",
           worst_flamant, worst_surface, worst_mirror);
    CHECK_LE(worst_flamant, 1e-11);
    CHECK_LE(worst_surface, 1e-12);
    CHECK_LE(worst_mirror, 1e-10);

    /* refused: no single c, edge intensity or slip function without symmetry */
    v = SENTINEL;
    e = SENTINEL;
    CHECK_STATUS(orthoslip_solution_stick_half_width(s, &v), ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_MESSAGE("orthoslip_solution_stick_half_width", "symmetric");
    CHECK_STATUS(orthoslip_solution_slip_width(s, &v), ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_MESSAGE("orthoslip_solution_slip_width", "symmetric");
    CHECK_STATUS(orthoslip_solution_edge_intensity(s, &v, &e), ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_MESSAGE("orthoslip_solution_edge_intensity", "symmetric");
    {
        double x = 0.5;
        CHECK_STATUS(orthoslip_solution_slip(s, &x, 1, &v), ORTHOSLIP_ERROR_INVALID_ARGUMENT);
        CHECK_MESSAGE("orthoslip_solution_slip", "symmetric");
    }
    CHECK(v == SENTINEL && e == SENTINEL);
    {
        /* bad points as for any solution */
        double x = 0.2, y = 0.1, nan_x = NAN, a = SENTINEL, bb = SENTINEL, cc = SENTINEL;
        CHECK_STATUS(orthoslip_solution_stresses(s, &x, &y, 1, &a, &bb, &cc),
                     ORTHOSLIP_ERROR_INVALID_ARGUMENT);
        CHECK_STATUS(orthoslip_solution_tractions(s, &nan_x, 1, &a, &bb),
                     ORTHOSLIP_ERROR_INVALID_ARGUMENT);
        CHECK(a == SENTINEL && bb == SENTINEL && cc == SENTINEL);
    }

    /* NULL arguments: *out NULL after the failure */
    {
        orthoslip_solution *out = s;
        CHECK_STATUS(orthoslip_history_solution(NULL, &out), ORTHOSLIP_ERROR_NULL_POINTER);
        CHECK(out == NULL);
        CHECK_MESSAGE("orthoslip_history_solution", "`h`");
        CHECK_STATUS(orthoslip_history_solution(h, NULL), ORTHOSLIP_ERROR_NULL_POINTER);
        CHECK_MESSAGE("orthoslip_history_solution", "`out`");
    }

    /* the solution keeps its state: the history loaded further, then freed */
    {
        double x = 0.3, p0, q0, p1, q1;
        orthoslip_solution *later = NULL;
        CHECK_OK(orthoslip_solution_tractions(s, &x, 1, &p0, &q0));
        CHECK_OK(orthoslip_history_load(h, 0.0));
        CHECK_OK(orthoslip_history_solution(h, &later));
        orthoslip_history_free(h);
        CHECK_OK(orthoslip_solution_tractions(s, &x, 1, &p1, &q1));
        CHECK(p0 == p1 && q0 == q1);
        CHECK_OK(orthoslip_solution_tractions(later, &x, 1, &p1, &q1));
        CHECK(q1 != q0);
        orthoslip_solution_free(later);
    }

    orthoslip_solution_free(s);
    orthoslip_solution_free(sm);
    orthoslip_history_free(hm);
    orthoslip_contact_free(k);
    orthoslip_material_free(mat);
    gsl_integration_qaws_table_free(left);
    gsl_integration_qaws_table_free(right);
    gsl_integration_workspace_free(ws);
#ifdef __cplusplus
    cxx_wrapper();
#endif
    printf("history_solution: all checks passed\n");
    return 0;
}
