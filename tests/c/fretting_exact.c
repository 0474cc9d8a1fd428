/* ORTHOSLIP_CYCLE_METHOD_EXACT through the load-path API (valid C11 and C++17), checked
 * against facts the library does not use:
 * - equilibrium: int p = 1 and int q = Q/P by GSL's adaptive quadrature (QAGS, which copes
 *   with the edges' integrable singularities) of the returned exact tractions, split at the
 *   stick set's ends;
 * - the zones: q = -mu p where the solid slipped in +x (zone +1), q = +mu p where it slipped
 *   in -x (zone -1), |q| <= mu p on the stick set (zone 0);
 * - mirror symmetry under Q -> -Q: [c1, c2] -> [-c2, -c1], p(x) -> p(-x), q(x) -> -q(-x);
 * - the grid LCP history (ORTHOSLIP_CYCLE_METHOD_LCP_HISTORY) at 50 and 100 panels per
 *   half-width approaches the exact c2, moment and punch displacement u as the grid refines;
 * - the dissipation along the path is positive, with a finite estimate, and the same for -Q;
 * - what the exact path does not answer is refused with a status, a message naming the
 *   exact method and the LCP history, nothing written and the history unchanged: a fretting
 *   run and the unloading at strong coupling (the corner's outer model answers only to
 *   tolerances above its corner zone's width, 8e-5 here: docs/theory_tangential.md
 *   section 21).
 * Quick mode (the C++ build) leaves out the finer grid.
 * Scene: the isotropic form b* = 0.9 (nu = -0.8), mu = 1, Q = 0.3 mu P, where the trailing
 * edge zone is 0.078 wide (docs/theory_tangential.md section 12). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include "check.h"

#define SENTINEL 12345.0
#define MU 1.0
#define LOAD 0.3

/* The scene solved to tol (the stick set's ends) and traction_tol (the tractions). */
static orthoslip_contact *contact_new(double tol, double traction_tol)
{
    orthoslip_material *m = NULL;
    orthoslip_contact *k = NULL;
    CHECK_OK(orthoslip_material_new_effective(1.0, -0.8, 1.0, 1.0, &m));
    CHECK_OK(orthoslip_contact_new(m, &k));
    CHECK_OK(orthoslip_contact_set_friction(k, MU));
    CHECK_OK(orthoslip_contact_set_tolerance(k, tol));
    CHECK_OK(orthoslip_contact_set_traction_tolerance(k, traction_tol));
    orthoslip_material_free(m);
    return k;
}

static orthoslip_history *history_new(const orthoslip_contact *k, orthoslip_cycle_method method,
                                      size_t panels)
{
    orthoslip_cycle_options *o = NULL;
    orthoslip_history *h = NULL;
    CHECK_OK(orthoslip_cycle_options_new(&o));
    CHECK_OK(orthoslip_cycle_options_set_method(o, method));
    CHECK_OK(orthoslip_cycle_options_set_panels(o, panels));
    CHECK_OK(orthoslip_history_new_with_options(k, o, &h));
    orthoslip_cycle_options_free(o);
    return h;
}

typedef struct {
    const orthoslip_history *h;
    int q;
} integrand;

static double traction(double x, void *params)
{
    const integrand *in = (const integrand *)params;
    double p, q;
    int zone;
    CHECK_OK(orthoslip_history_tractions(in->h, &x, 1, &p, &q, &zone));
    return in->q ? q : p;
}

/* int p (q = 0) or int q (q = 1) over [-1, 1], split at c1 and c2. */
static double integral(const orthoslip_history *h, int q, double c1, double c2)
{
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(1000);
    integrand in = {h, q};
    gsl_function f = {traction, &in};
    double ends[4] = {-1.0, c1, c2, 1.0}, total = 0.0, v, err;
    int i;
    for (i = 0; i < 3; i++) {
        CHECK(gsl_integration_qags(&f, ends[i], ends[i + 1], 1e-13, 1e-11, 1000, ws, &v, &err) ==
              GSL_SUCCESS);
        total += v;
    }
    gsl_integration_workspace_free(ws);
    return total;
}

/* Everything the history reports of its state, for the unchanged-on-failure check. */
static void look(const orthoslip_history *h, double out[16])
{
    double x[4] = {-0.999, -0.4, 0.3, 0.999};
    int zone[4], i;
    CHECK_OK(orthoslip_history_state(h, &out[0], &out[1], &out[2]));
    CHECK_OK(orthoslip_history_stick_zone(h, &out[3], &out[4], &out[5]));
    CHECK_OK(orthoslip_history_traction_error_estimate(h, &out[6]));
    CHECK_OK(orthoslip_history_tractions(h, x, 4, &out[7], &out[11], zone));
    for (i = 0; i < 4; i++) out[7 + i] += zone[i];
    out[15] = 0.0;
}

int main(void)
{
    orthoslip_contact *k = contact_new(1e-10, 1e-8);
    /* looser tolerances for the refused unloading: its three-zone ladder stops sooner (0.5 s,
     * not 8 s), and the outer model's one step refuses in 1 s */
    orthoslip_contact *loose = contact_new(1e-6, 1e-4);
    orthoslip_history *refused = history_new(loose, ORTHOSLIP_CYCLE_METHOD_EXACT, 100);
    orthoslip_history *h = history_new(k, ORTHOSLIP_CYCLE_METHOD_EXACT, 100);
    orthoslip_history *mirror = history_new(k, ORTHOSLIP_CYCLE_METHOD_EXACT, 100);
    orthoslip_cycle_options *o = NULL;
    orthoslip_cycles *cy = (orthoslip_cycles *)&o; /* not NULL: must be set to NULL */
    orthoslip_solution *s = NULL;
    orthoslip_method used;
    double qp, u, moment, c1, c2, err, terr, d1, d2, w = SENTINEL, werr = SENTINEL;
    double before[16], after[16], prev_c2 = INFINITY, prev_m = INFINITY, prev_u = INFINITY;
    double qpm, um, mm;
    double x[7] = {-1.0, -0.97, -0.5, 0.0, 0.4, 0.9, 1.0}, p[7], q[7], pm[7], qm[7];
    int zone[7], zm[7], i;
    size_t n;
    gsl_set_error_handler_off();

    /* the normal load: the symmetric stick zone, no dissipation */
    CHECK_OK(orthoslip_history_stick_zone(h, &c1, &c2, &err));
    CHECK(c1 < 0.0 && c1 == -c2 && err < 1e-10);
    CHECK_OK(orthoslip_history_dissipated_energy(h, &w, &werr));
    CHECK(w == 0.0 && werr == 0.0);

    /* monotonic loading to Q = 0.3 mu P, and to -Q */
    CHECK_OK(orthoslip_history_load(h, LOAD));
    CHECK_OK(orthoslip_history_load(mirror, -LOAD));
    CHECK_OK(orthoslip_history_state(h, &qp, &u, &moment));
    CHECK(qp == LOAD && isfinite(u) && u > 0.0 && moment < 0.0);
    CHECK_OK(orthoslip_history_state(mirror, &qpm, &um, &mm));
    CHECK(qpm == -LOAD && fabs(um + u) <= 1e-12 * u && mm == -moment);
    CHECK_OK(orthoslip_history_stick_zone(h, &c1, &c2, &err));
    CHECK_OK(orthoslip_history_traction_error_estimate(h, &terr));
    printf("exact: c1 = %.10f, c2 = %.10f (estimate %.1e), moment %.8e, tractions %.1e\n", c1,
           c2, err, moment, terr);
    CHECK(c1 > -0.95 && c1 < -0.9 && c2 > -0.25 && c2 < -0.15);
    CHECK_LE(err, 1e-10);
    CHECK_LE(terr, 1e-8);

    /* equilibrium by GSL */
    CHECK_LE(fabs(integral(h, 0, c1, c2) - 1.0), 1e-8);
    CHECK_LE(fabs(integral(h, 1, c1, c2) - LOAD), 1e-8);

    /* zones, edges and mirror */
    CHECK_OK(orthoslip_history_tractions(h, x, 7, p, q, zone));
    CHECK_OK(orthoslip_history_stick_zone(mirror, &d1, &d2, &err));
    CHECK(d1 == -c2 && d2 == -c1);
    for (i = 0; i < 7; i++) {
        double xm = -x[i];
        CHECK_OK(orthoslip_history_tractions(mirror, &xm, 1, &pm[i], &qm[i], &zm[i]));
        if (fabs(x[i]) == 1.0) {
            CHECK(isinf(p[i]) && p[i] > 0.0 && isinf(q[i]));
            continue;
        }
        CHECK(fabs(p[i] - pm[i]) <= 1e-12 * p[i] && fabs(q[i] + qm[i]) <= 1e-12 * p[i]);
        CHECK(zone[i] == -zm[i]);
        if (x[i] < c1) CHECK(zone[i] == 1 && fabs(q[i] + MU * p[i]) <= 1e-12 * p[i]);
        else if (x[i] > c2) CHECK(zone[i] == -1 && fabs(q[i] - MU * p[i]) <= 1e-12 * p[i]);
        else CHECK(zone[i] == 0 && fabs(q[i]) <= MU * p[i]);
    }
    CHECK(q[0] < 0.0 && q[6] > 0.0);

    /* the grid approaches the exact c2 and moment as it refines (quick mode: one grid) */
    for (n = 50; n <= (test_quick() ? 50 : 100); n *= 2) {
        orthoslip_history *g = history_new(k, ORTHOSLIP_CYCLE_METHOD_LCP_HISTORY, n);
        double gq, gu, gm, g1, g2, ge;
        CHECK_OK(orthoslip_history_load(g, LOAD));
        CHECK_OK(orthoslip_history_state(g, &gq, &gu, &gm));
        CHECK_OK(orthoslip_history_stick_zone(g, &g1, &g2, &ge));
        printf("grid n = %zu: |dc2| = %.2e, |dmoment| = %.2e, u = %.8f (exact %.8f)\n", n,
               fabs(g2 - c2), fabs(gm - moment), gu, u);
        CHECK(fabs(g2 - c2) < prev_c2 && fabs(gm - moment) < prev_m && fabs(gu - u) < prev_u);
        prev_c2 = fabs(g2 - c2);
        prev_m = fabs(gm - moment);
        prev_u = fabs(gu - u);
        orthoslip_history_free(g);
    }
    CHECK_LE(prev_c2, 0.02);

    /* the state as a solution: the same tractions and stick set, method COUPLED */
    CHECK_OK(orthoslip_history_solution(h, &s));
    CHECK_OK(orthoslip_solution_method(s, &used));
    CHECK(used == ORTHOSLIP_METHOD_COUPLED);
    CHECK_OK(orthoslip_solution_stick_zone(s, &d1, &d2));
    CHECK(d1 == c1 && d2 == c2);
    CHECK_OK(orthoslip_solution_tractions(s, &x[2], 1, &pm[0], &qm[0]));
    CHECK(pm[0] == p[2] && qm[0] == q[2]);
    orthoslip_solution_free(s);

    /* the dissipation along the path (one load step), and its mirror */
    CHECK_OK(orthoslip_history_dissipated_energy(h, &w, &werr));
    CHECK_OK(orthoslip_history_dissipated_energy(mirror, &d1, &d2));
    printf("exact: W = %.8e P^2/E (estimate %.1e), mirror %.8e\n", w, werr, d1);
    CHECK(w > 0.0 && isfinite(werr) && fabs(d1 - w) <= 1e-10 * w);

    /* refused: a fretting run at its first unloading step and the strong coupling's
     * unloading (the corner zone the outer model leaves out exceeds the tolerance), with the
     * three-zone pattern's status; nothing written, handles NULL, the history unchanged */
    CHECK_OK(orthoslip_cycle_options_new(&o));
    CHECK_OK(orthoslip_cycle_options_set_method(o, ORTHOSLIP_CYCLE_METHOD_EXACT));
    {
        orthoslip_status st = orthoslip_contact_solve_cycles_with_options(k, o, LOAD, 5, &cy);
        CHECK(st == ORTHOSLIP_ERROR_NO_ADMISSIBLE_SOLUTION || st == ORTHOSLIP_ERROR_NO_CONVERGENCE);
    }
    CHECK(cy == NULL);
    CHECK_MESSAGE("orthoslip_contact_solve_cycles_with_options", "ORTHOSLIP_CYCLE_METHOD_EXACT");
    CHECK_MESSAGE("orthoslip_contact_solve_cycles_with_options", "cycle 0, unloading");
    orthoslip_cycle_options_free(o);
    CHECK_OK(orthoslip_history_load(refused, LOAD));
    look(refused, before);
    {
        /* the first unloading step (0.9 Q*): the outer model's march is one step */
        orthoslip_status st = orthoslip_history_load(refused, 0.9 * LOAD);
        CHECK(st == ORTHOSLIP_ERROR_NO_ADMISSIBLE_SOLUTION || st == ORTHOSLIP_ERROR_NO_CONVERGENCE);
        CHECK_MESSAGE("orthoslip_history_load", "ORTHOSLIP_CYCLE_METHOD_LCP_HISTORY");
    }
    look(refused, after);
    CHECK(memcmp(before, after, sizeof before) == 0);

    orthoslip_history_free(refused);
    orthoslip_history_free(mirror);
    orthoslip_history_free(h);
    orthoslip_contact_free(loose);
    orthoslip_contact_free(k);
    printf("fretting_exact: ok\n");
    return 0;
}
