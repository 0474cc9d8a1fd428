/* The tangential load and fretting functions (valid C11 and C++17), checked against facts
 * the library does not use:
 * - the uncoupled limit b* -> 0 (docs/theory_tangential.md (T10)): full stick until gross
 *   sliding, q = (Q/P) / (pi sqrt(1 - x^2)), no dissipation, shakedown at once;
 * - the energy balance: the loop's area, computed here by the trapezoidal rule from the
 *   returned loop, plus the work of P, minus the change of elastic energy, is the dissipation
 *   (of a cycle that ends where it started: the area is the dissipation);
 * - mirror symmetry under Q -> -Q: [c1, c2] -> [-c2, -c1], q(x) -> -q(-x), p(x) -> p(-x);
 * - bad input refused with a status, a message, NULL handles and nothing written; a refused
 *   load step leaves the history unchanged. */
#include <math.h>
#include <string.h>

#include "check.h"

#define SENTINEL 12345.0
#define PI 3.14159265358979323846

/* A contact on the effective constants (E, nu, delta, kappa) with friction mu. */
static orthoslip_contact *contact_new(double e, double nu, double delta, double kappa,
                                      double mu)
{
    orthoslip_material *m = NULL;
    orthoslip_contact *k = NULL;
    CHECK_OK(orthoslip_material_new_effective(e, nu, delta, kappa, &m));
    CHECK_OK(orthoslip_contact_new(m, &k));
    CHECK_OK(orthoslip_contact_set_friction(k, mu));
    orthoslip_material_free(m);
    return k;
}

static orthoslip_cycle_options *options_new(size_t panels, size_t steps)
{
    orthoslip_cycle_options *o = NULL;
    CHECK_OK(orthoslip_cycle_options_new(&o));
    CHECK_OK(orthoslip_cycle_options_set_panels(o, panels));
    CHECK_OK(orthoslip_cycle_options_set_steps(o, steps));
    return o;
}

/* Uncoupled limit: nu -> 1 makes A = (1 - nu)/E, hence bp, bq, vanish (b* = 5e-7). */
static void uncoupled(size_t panels)
{
    const double mu = 0.3, amp = 0.25;
    orthoslip_contact *k = contact_new(1.0, 1.0 - 1e-6, 1.0, 1.0, mu);
    orthoslip_cycle_options *o = options_new(panels, 3);
    orthoslip_cycles *cy = NULL;
    orthoslip_history *h = NULL;
    orthoslip_cycle_state state;
    double x[5] = {-0.8, -0.4, 0.01, 0.45, 0.85}, p[5], q[5], c1, c2, err, w, werr;
    int zone[5], steady = 0, i;
    size_t n = 0;

    /* a load path to Q = 0.25 P < mu P: all stick, q = (Q/P) p with p the frictionless one */
    CHECK_OK(orthoslip_history_new_with_options(k, o, &h));
    CHECK_OK(orthoslip_history_load(h, amp));
    CHECK_OK(orthoslip_history_stick_zone(h, &c1, &c2, &err));
    CHECK(c1 == -1.0 && c2 == 1.0);
    CHECK_OK(orthoslip_history_tractions(h, x, 5, p, q, zone));
    for (i = 0; i < 5; i++) {
        double p0 = 1.0 / (PI * sqrt(1.0 - x[i] * x[i]));
        CHECK(zone[i] == 0);
        /* first order in the panel width (the discrete frictionless pressure) */
        CHECK_LE(fabs(p[i] - p0), 2.0 / (double)panels);
        CHECK_LE(fabs(q[i] - amp * p0), 2.0 * amp / (double)panels);
    }
    CHECK_OK(orthoslip_history_dissipated_energy(h, &w, &werr));
    CHECK_LE(w, 1e-9);
    /* still all stick just below gross sliding, Q = 0.299 P (mu = 0.3) */
    CHECK_OK(orthoslip_history_load(h, 0.299));
    CHECK_OK(orthoslip_history_stick_zone(h, &c1, &c2, &err));
    CHECK(c1 == -1.0 && c2 == 1.0);
    CHECK_OK(orthoslip_history_tractions(h, x, 5, p, q, zone));
    for (i = 0; i < 5; i++) CHECK(zone[i] == 0);
    CHECK_OK(orthoslip_history_dissipated_energy(h, &w, &werr));
    CHECK_LE(w, 1e-9);
    orthoslip_history_free(h);

    /* cycles: nothing slips, shakedown in the first cycle */
    CHECK_OK(orthoslip_contact_solve_cycles_with_options(k, o, amp, 5, &cy));
    CHECK_OK(orthoslip_cycles_count(cy, &n, &steady));
    CHECK(n == 1 && steady == 1);
    CHECK_OK(orthoslip_cycles_state(cy, &state));
    CHECK(state == ORTHOSLIP_CYCLE_SHAKEDOWN);
    CHECK_OK(orthoslip_cycles_dissipated_energy(cy, 0, &w));
    CHECK_OK(orthoslip_cycles_dissipated_energy_error(cy, 0, &werr));
    CHECK_LE(w, 1e-9);
    CHECK_LE(werr, 1e-9);
    CHECK_OK(orthoslip_cycles_first_loading_energy(cy, &w, &werr));
    CHECK_LE(w, 1e-9);
    orthoslip_cycles_free(cy);
    orthoslip_cycle_options_free(o);
    orthoslip_contact_free(k);
}

/* The loop's area by the trapezoidal rule. */
static double loop_area(const orthoslip_cycles *cy, size_t cycle)
{
    size_t len = 0, i;
    double qp[1024], u[1024], area = 0.0;
    CHECK_OK(orthoslip_cycles_loop_length(cy, cycle, &len));
    CHECK(len >= 2 && len <= 1024);
    CHECK_STATUS(orthoslip_cycles_loop(cy, cycle, len + 1, qp, u),
                 ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_OK(orthoslip_cycles_loop(cy, cycle, len, qp, u));
    for (i = 1; i < len; i++) area += 0.5 * (qp[i - 1] + qp[i]) * (u[i] - u[i - 1]);
    return area;
}

/* Energy balance, on a cycle that slips steadily (isotropic form b* = 0.5, mu = 0.5,
 * Q* = 0.9 mu P; theory_tangential section 7) and on the ply's first cycle. */
static void energy_balance(size_t panels, size_t steps)
{
    orthoslip_contact *k = contact_new(1.0, 0.0, 1.0, 1.0, 0.5);
    orthoslip_cycle_options *o = options_new(panels, steps);
    orthoslip_cycles *cy = NULL;
    orthoslip_cycle_state state;
    size_t n = 0, last;
    int steady = 0;
    double w, werr, area, lw, nw, de, res, w1;


    CHECK_OK(orthoslip_contact_solve_cycles_with_options(k, o, 0.45, 8, &cy));
    CHECK_OK(orthoslip_cycles_count(cy, &n, &steady));
    CHECK_OK(orthoslip_cycles_state(cy, &state));
    CHECK(steady == 1 && state == ORTHOSLIP_CYCLE_STEADY_SLIP && n >= 1);
    last = n - 1;
    CHECK_OK(orthoslip_cycles_dissipated_energy(cy, last, &w));
    CHECK_OK(orthoslip_cycles_dissipated_energy_error(cy, last, &werr));
    area = loop_area(cy, last);
    CHECK_OK(orthoslip_cycles_energy_balance(cy, last, &lw, &nw, &de, &res));
    CHECK_LE(fabs(area - lw), 1e-14);
    CHECK_LE(fabs(res), 1e-14);
    /* a closed cycle: no net work of P, no change of elastic energy; area = dissipation */
    CHECK_LE(fabs(nw) + fabs(de), 1e-8);
    CHECK(w > 1e-3);
    CHECK_LE(fabs(area - w), werr);
    {
        double ue = -1.0, we = -1.0;
        CHECK_OK(orthoslip_cycles_loop_error(cy, last, &ue, &we));
        CHECK(ue > 0.0 && we > 0.0 && we < w);
        CHECK_STATUS(orthoslip_cycles_loop_error(cy, n, &ue, &we),
                     ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    }
    printf("steady slip cycle %zu: W = %.6e +- %.1e P^2/E, loop area %.6e\n", last, w, werr,
           area);
    orthoslip_cycles_free(cy);
    orthoslip_contact_free(k);

    /* the ply at 0.6 mu P: the first cycle is not closed (P works, the elastic energy
     * changes), the second one has shaken down. The balance holds exactly with the mid-step
     * dissipation, which differs from the reported (end-of-step) one by a discretisation
     * error in the load step: the gap shrinks (measured: 1.8e-5 to 1.1e-6 P^2/E from 4 to
     * 8 steps per quarter at 40 panels). */
    {
        orthoslip_material *m = NULL;
        CHECK_OK(orthoslip_material_new_plane_stress(181e9, 10.3e9, 7.17e9, 0.28, &m));
        CHECK_OK(orthoslip_contact_new(m, &k));
        orthoslip_material_free(m);
    }
    CHECK_OK(orthoslip_contact_set_friction(k, 0.3));
    {
        double gap[2];
        int r;
        for (r = 0; r < 2; r++) {
            CHECK_OK(orthoslip_cycle_options_set_steps(o, steps << r));
            CHECK_OK(orthoslip_contact_solve_cycles_with_options(k, o, 0.18, 4, &cy));
            CHECK_OK(orthoslip_cycles_count(cy, &n, &steady));
            CHECK_OK(orthoslip_cycles_state(cy, &state));
            CHECK(n == 2 && state == ORTHOSLIP_CYCLE_SHAKEDOWN);
            CHECK_OK(orthoslip_cycles_dissipated_energy(cy, 0, &w1));
            CHECK_OK(orthoslip_cycles_dissipated_energy_error(cy, 0, &werr));
            area = loop_area(cy, 0);
            CHECK_OK(orthoslip_cycles_energy_balance(cy, 0, &lw, &nw, &de, &res));
            CHECK_LE(fabs(area - lw), 1e-14);
            CHECK(fabs(nw) > 1e-4 && fabs(de) > 1e-4);
            gap[r] = fabs(area + nw - de - w1);
            CHECK_OK(orthoslip_cycles_dissipated_energy(cy, 1, &w));
            CHECK_LE(w, 1e-12);
            CHECK_LE(fabs(loop_area(cy, 1)), 1e-12);
            printf("ply first cycle, %zu steps: W = %.6e +- %.1e P^2/E, "
                   "area + P work - dPi = %.6e\n",
                   steps << r, w1, werr, area + nw - de);
            orthoslip_cycles_free(cy);
        }
        CHECK(gap[1] < 0.5 * gap[0]);
    }
    orthoslip_cycle_options_free(o);
    orthoslip_contact_free(k);
}

/* Q -> -Q mirrors the path (at points off the panel boundaries, whose panel is the one on
 * their right). */
static void mirror(size_t panels)
{
    orthoslip_contact *k = contact_new(1.0, 0.2, 1.3, 1.1, 0.4);
    orthoslip_cycle_options *o = options_new(panels, 3);
    orthoslip_history *up = NULL, *down = NULL;
    double x[4] = {-0.77, -0.31, 0.21, 0.62}, mx[4], p[4], q[4], pm[4], qm[4];
    double a1, a2, b1, b2, e, qa, ua, ma, qb, ub, mb;
    int za[4], zb[4], i;
    for (i = 0; i < 4; i++) mx[i] = -x[i];
    CHECK_OK(orthoslip_history_new_with_options(k, o, &up));
    CHECK_OK(orthoslip_history_new_with_options(k, o, &down));
    CHECK_OK(orthoslip_history_load(up, 0.2));
    CHECK_OK(orthoslip_history_load(down, -0.2));
    CHECK_OK(orthoslip_history_stick_zone(up, &a1, &a2, &e));
    CHECK_OK(orthoslip_history_stick_zone(down, &b1, &b2, &e));
    CHECK_LE(fabs(a1 + b2) + fabs(a2 + b1), 1e-10);
    CHECK(a1 == -1.0 && a2 < 1.0);
    CHECK_OK(orthoslip_history_tractions(up, x, 4, p, q, za));
    CHECK_OK(orthoslip_history_tractions(down, mx, 4, pm, qm, zb));
    for (i = 0; i < 4; i++) {
        CHECK_LE(fabs(p[i] - pm[i]), 1e-10);
        CHECK_LE(fabs(q[i] + qm[i]), 1e-10);
        CHECK(za[i] == -zb[i]);
    }
    CHECK_OK(orthoslip_history_state(up, &qa, &ua, &ma));
    CHECK_OK(orthoslip_history_state(down, &qb, &ub, &mb));
    CHECK(qa == 0.2 && qb == -0.2);
    CHECK_LE(fabs(ua + ub), 1e-12);
    CHECK_LE(fabs(ma + mb), 1e-12);
    orthoslip_history_free(up);
    orthoslip_history_free(down);
    orthoslip_cycle_options_free(o);
    orthoslip_contact_free(k);
}

static void bad_input(void)
{
    orthoslip_contact *k = contact_new(1.0, 0.2, 1.3, 1.1, 0.3);
    orthoslip_contact *k0 = contact_new(1.0, 0.2, 1.3, 1.1, 0.0);
    orthoslip_cycle_options *o = options_new(8, 2);
    orthoslip_cycles *cy = (orthoslip_cycles *)&o; /* not NULL: must be set to NULL */
    orthoslip_history *h = (orthoslip_history *)&o;
    const double bad[] = {NAN, INFINITY, -INFINITY, -0.1, 0.0, 0.3, 0.5};
    double v = SENTINEL, v2 = SENTINEL, x[2] = {0.0, 1.5}, out[2] = {SENTINEL, SENTINEL},
           out2[2] = {SENTINEL, SENTINEL}, q0, u0, m0, q1, u1, m1;
    int zone[2] = {7, 7}, steady = 7;
    size_t i, n = 99;

    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        cy = (orthoslip_cycles *)&o;
        CHECK_STATUS(orthoslip_contact_solve_cycles_with_options(k, o, bad[i], 2, &cy),
                     ORTHOSLIP_ERROR_INVALID_ARGUMENT);
        CHECK(cy == NULL);
        CHECK_MESSAGE("orthoslip_contact_solve_cycles_with_options", "amplitude");
    }
    CHECK_STATUS(orthoslip_contact_solve_cycles_with_options(k, o, 0.3, 2, &cy),
                 ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_MESSAGE("orthoslip_contact_solve_cycles", "gross sliding");
    CHECK_STATUS(orthoslip_contact_solve_cycles_with_options(k0, o, 0.1, 2, &cy),
                 ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_MESSAGE("orthoslip_contact_solve_cycles", "mu > 0");
    CHECK_STATUS(orthoslip_contact_solve_cycles(k, 0.1, 0, &cy),
                 ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_STATUS(orthoslip_contact_solve_cycles(k, 0.1, 1001, &cy),
                 ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_MESSAGE("orthoslip_contact_solve_cycles", "cycle limit");
    CHECK(cy == NULL);
    CHECK_STATUS(orthoslip_contact_solve_cycles(NULL, 0.1, 2, &cy),
                 ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK(cy == NULL);
    CHECK_STATUS(orthoslip_contact_solve_cycles_with_options(k, NULL, 0.1, 2, &cy),
                 ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK_STATUS(orthoslip_contact_solve_cycles(k, 0.1, 2, NULL),
                 ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK_STATUS(orthoslip_history_new(k0, &h), ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK(h == NULL);
    CHECK_STATUS(orthoslip_history_new(NULL, &h), ORTHOSLIP_ERROR_NULL_POINTER);

    /* option setters: out of range refused, options unchanged */
    CHECK_STATUS(orthoslip_cycle_options_set_panels(o, 7), ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_STATUS(orthoslip_cycle_options_set_panels(o, (size_t)-1),
                 ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_STATUS(orthoslip_cycle_options_set_steps(o, 1), ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_STATUS(orthoslip_cycle_options_set_repeat_tolerance(o, NAN),
                 ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_STATUS(orthoslip_cycle_options_set_repeat_tolerance(o, -1.0),
                 ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_STATUS(orthoslip_cycle_options_set_method(o, (orthoslip_cycle_method)2),
                 ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_OK(orthoslip_cycle_options_set_method(o, ORTHOSLIP_CYCLE_METHOD_LCP_HISTORY));
    CHECK_STATUS(orthoslip_cycle_options_set_panels(NULL, 10), ORTHOSLIP_ERROR_NULL_POINTER);

    /* a history: refused loads leave it unchanged */
    CHECK_OK(orthoslip_history_new_with_options(k, o, &h));
    CHECK_OK(orthoslip_history_load(h, 0.1));
    CHECK_OK(orthoslip_history_state(h, &q0, &u0, &m0));
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        if (fabs(bad[i]) < 0.3) continue;
        CHECK_STATUS(orthoslip_history_load(h, bad[i]), ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    }
    CHECK_MESSAGE("orthoslip_history_load", "load");
    CHECK_OK(orthoslip_history_state(h, &q1, &u1, &m1));
    CHECK(q0 == q1 && u0 == u1 && m0 == m1);
    CHECK_STATUS(orthoslip_history_load(NULL, 0.1), ORTHOSLIP_ERROR_NULL_POINTER);
    /* points off the contact: nothing written */
    CHECK_STATUS(orthoslip_history_tractions(h, x, 2, out, out2, zone),
                 ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_MESSAGE("orthoslip_history_tractions", "x[1]");
    CHECK(out[0] == SENTINEL && out2[0] == SENTINEL && zone[0] == 7);
    x[1] = NAN;
    CHECK_STATUS(orthoslip_history_tractions(h, x, 2, out, out2, zone),
                 ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_STATUS(orthoslip_history_tractions(h, x, 0, out, NULL, zone),
                 ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK_OK(orthoslip_history_tractions(h, x, 0, out, out2, zone));
    CHECK_STATUS(orthoslip_history_stick_zone(h, &v, NULL, &v2),
                 ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK(v == SENTINEL);
    orthoslip_history_free(h);

    /* a run: indices out of range, points off the contact */
    CHECK_OK(orthoslip_contact_solve_cycles_with_options(k, o, 0.1, 2, &cy));
    CHECK_OK(orthoslip_cycles_count(cy, &n, &steady));
    CHECK(n >= 1 && n <= 2);
    CHECK_STATUS(orthoslip_cycles_dissipated_energy(cy, n, &v),
                 ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_MESSAGE("orthoslip_cycles_dissipated_energy", "cycle");
    CHECK(v == SENTINEL);
    x[1] = -1.0001;
    CHECK_STATUS(orthoslip_cycles_slip_amplitude(cy, 0, x, 2, out),
                 ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_STATUS(orthoslip_cycles_ruiz(cy, 0, x, 2, out, out2),
                 ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK(out[0] == SENTINEL && out2[0] == SENTINEL);
    CHECK_STATUS(orthoslip_cycles_step(cy, 0, 8, &v, &v, &v, &v),
                 ORTHOSLIP_ERROR_INVALID_ARGUMENT);
    CHECK_STATUS(orthoslip_cycles_count(cy, &n, NULL), ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK_STATUS(orthoslip_cycles_count(NULL, &n, &steady), ORTHOSLIP_ERROR_NULL_POINTER);
    orthoslip_cycles_free(cy);
    orthoslip_cycles_free(NULL);
    orthoslip_history_free(NULL);
    orthoslip_cycle_options_free(NULL);
    orthoslip_cycle_options_free(o);
    orthoslip_contact_free(k);
    orthoslip_contact_free(k0);
}

/* The default run of the signature, the per-cycle outputs and their consistency:
 * the Ruiz parameters are the products of their factors, the peaks are the largest panel
 * values, the steps' stick sets include the stick sets at -Q* and +Q*. */
static void outputs(size_t panels, size_t steps)
{
    orthoslip_material *m = NULL;
    orthoslip_contact *k = NULL;
    orthoslip_cycle_options *o = options_new(panels, steps);
    orthoslip_cycles *cy = NULL;
    orthoslip_cycle_method used;
    double x[2 * 64], amp[2 * 64], f1[2 * 64], f2[2 * 64], tau[2 * 64], sxx[2 * 64];
    double f1m, xf1, f2m, xf2, err[4], cm1, cm2, cp1, cp2, ce, qp, u, c1, c2, top = 0.0;
    double p[3], q[3], xs[3] = {-0.99, 0.0, 0.99};
    int zone[3], steady;
    size_t i, n, nx = 2 * panels;
    CHECK(panels <= 64);
    CHECK_OK(orthoslip_material_new_plane_stress(181e9, 10.3e9, 7.17e9, 0.28, &m));
    CHECK_OK(orthoslip_contact_new(m, &k));
    orthoslip_material_free(m);
    CHECK_OK(orthoslip_contact_set_friction(k, 0.3));
    CHECK_OK(orthoslip_contact_solve_cycles_with_options(k, o, 0.18, 3, &cy));
    CHECK_OK(orthoslip_cycles_method(cy, &used));
    CHECK(used == ORTHOSLIP_CYCLE_METHOD_LCP_HISTORY);
    CHECK_OK(orthoslip_cycles_count(cy, &n, &steady));
    CHECK(n == 2 && steady == 1);
    for (i = 0; i < nx; i++) x[i] = -1.0 + (i + 0.5) / (double)panels;
    CHECK_OK(orthoslip_cycles_slip_amplitude(cy, 0, x, nx, amp));
    CHECK_OK(orthoslip_cycles_ruiz(cy, 0, x, nx, f1, f2));
    CHECK_OK(orthoslip_cycles_stress_peaks(cy, 0, x, nx, tau, sxx));
    for (i = 0; i < nx; i++) {
        CHECK(amp[i] >= 0.0 && tau[i] > 0.0);
        CHECK(f1[i] == tau[i] * amp[i]);
        CHECK(f2[i] == (sxx[i] > 0.0 ? sxx[i] : 0.0) * f1[i]);
        if (f1[i] > top) top = f1[i];
    }
    CHECK_OK(orthoslip_cycles_ruiz_peaks(cy, 0, &f1m, &xf1, &f2m, &xf2, err));
    CHECK(f1m == top && f1m > 0.0 && err[0] >= 0.0);
    /* the first unloading slips at its leading edge x = -1 */
    CHECK(xf1 < -0.9 && amp[0] > 0.0);
    CHECK_OK(orthoslip_cycles_stick_zones(cy, 0, &cm1, &cm2, &cp1, &cp2, &ce));
    CHECK(cm1 > -1.0 && cm2 == 1.0 && cp1 == -1.0 && cp2 == 1.0 && ce < 0.1);
    CHECK_OK(orthoslip_cycles_step(cy, 0, 2 * steps - 1, &qp, &u, &c1, &c2));
    CHECK(qp == -0.18 && c1 == cm1 && c2 == cm2);
    CHECK_OK(orthoslip_cycles_step_tractions(cy, 0, 2 * steps - 1, xs, 3, p, q, zone));
    /* at -Q* the new leading edge slips in +x (q = -mu p), the centre sticks */
    CHECK(zone[0] == 1 && zone[1] == 0 && zone[2] == 0);
    CHECK_LE(fabs(q[0] + 0.3 * p[0]), 1e-10);
    /* the second cycle: no slip anywhere, no Ruiz peak */
    CHECK_OK(orthoslip_cycles_ruiz_peaks(cy, 1, &f1m, &xf1, &f2m, &xf2, err));
    CHECK(f1m == 0.0 && isnan(xf1) && f2m == 0.0);
    orthoslip_cycles_free(cy);
    orthoslip_cycle_options_free(o);
    orthoslip_contact_free(k);
}

#ifdef __cplusplus
/* The C++ build also checks the RAII wrapper (c_examples/orthoslip.hpp): the same numbers as
 * the C calls, and bad input thrown as orthoslip::error with the status. */
#include "orthoslip.hpp"

static void cxx_wrapper(size_t panels, size_t steps)
{
    const auto ply = orthoslip::material::plane_stress(181e9, 10.3e9, 7.17e9, 0.28);
    orthoslip::contact k(ply);
    k.friction(0.3);
    orthoslip::cycle_options o;
    o.panels(panels).steps(steps);
    const auto cy = k.solve_cycles(0.18, 4, o);
    CHECK(cy.count() == 2 && cy.state() == ORTHOSLIP_CYCLE_SHAKEDOWN);
    orthoslip_cycles *raw = NULL;
    double w = 0.0, err = 0.0, amp = 0.0, f1 = 0.0, f2 = 0.0, x = -0.99;
    CHECK_OK(orthoslip_contact_solve_cycles_with_options(k.get(), o.get(), 0.18, 4, &raw));
    CHECK_OK(orthoslip_cycles_dissipated_energy(raw, 0, &w));
    CHECK_OK(orthoslip_cycles_dissipated_energy_error(raw, 0, &err));
    CHECK_OK(orthoslip_cycles_slip_amplitude(raw, 0, &x, 1, &amp));
    CHECK_OK(orthoslip_cycles_ruiz(raw, 0, &x, 1, &f1, &f2));
    const auto e = cy.dissipated_energy(0);
    CHECK(e.value == w && e.error == err);
    CHECK(cy.slip_amplitude(0, {x})[0] == amp);
    const auto r = cy.ruiz(0, {x});
    CHECK(r.first[0] == f1 && r.second[0] == f2);
    const auto loop = cy.loop(0);
    CHECK(loop.q_over_p.size() == 4 * steps + 1 && loop.q_over_p.front() == 0.18);
    const auto zones = cy.stick_zones(0);
    CHECK(zones.first.c2 == 1.0 && zones.second.c1 == -1.0);
    orthoslip_cycles_free(raw);

    auto h = k.history(o);
    h.load(0.1);
    const auto z = h.stick_zone();
    CHECK(z.c1 == -1.0 && z.c2 < 1.0 && z.error >= 0.0);
    const auto t = h.at({-0.5, 0.5});
    /* the trailing side sticks, the leading zone slips in -x with q = +mu p */
    CHECK(t.p.size() == 2 && t.zone[0] == 0 && t.zone[1] == -1);
    CHECK_LE(fabs(t.q[1] - 0.3 * t.p[1]), 1e-10);
    CHECK(h.dissipated_energy().value > 0.0);
    int thrown = 0;
    try {
        h.load(0.3); /* gross sliding */
    } catch (const orthoslip::error &ex) {
        thrown = ex.status() == ORTHOSLIP_ERROR_INVALID_ARGUMENT;
    }
    CHECK(thrown);
    thrown = 0;
    try {
        (void)k.solve_cycles(-0.1, 4, o);
    } catch (const orthoslip::error &ex) {
        thrown = ex.status() == ORTHOSLIP_ERROR_INVALID_ARGUMENT;
    }
    CHECK(thrown);
}
#endif

int main(void)
{
    size_t panels = test_quick() ? 16 : 40, steps = test_quick() ? 2 : 4;
    uncoupled(panels);
    energy_balance(panels, steps);
    mirror(panels);
    bad_input();
    outputs(test_quick() ? 16 : 32, steps);
#ifdef __cplusplus
    cxx_wrapper(test_quick() ? 16 : 32, steps);
#endif
    printf("fretting: ok\n");
    return 0;
}
