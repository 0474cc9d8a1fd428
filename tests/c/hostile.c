/* Hostile input through the C ABI (issue 26, point 4): random materials (all three
 * constructors), frictions, tolerances, methods (also values outside orthoslip_method) and
 * evaluation points, drawn with a fixed seed, with NaN, infinities, zeros, negative,
 * subnormal and huge values among them. Every call must end either with ORTHOSLIP_OK and
 * finite admissible answers, or with another status and a message naming the function;
 * handle out-parameters are NULL after a failure, and NULL out-parameters are refused.
 *
 * Environment (set by tests/c_programs.rs):
 *   ORTHOSLIP_HOSTILE_DRAWS    number of draws (default 300);
 *   ORTHOSLIP_HOSTILE_SEED     seed (default 26);
 *   ORTHOSLIP_HOSTILE_FULL     set: tolerances next to 0 for every method (slow tier); unset:
 *                              COUPLED, LCP and AUTO get valid tolerances from 1e-6 up (and
 *                              every invalid one), the closed forms the whole range;
 *   ORTHOSLIP_HOSTILE_MAX_SECONDS  bound on one solve's wall time (default 120).
 * ORTHOSLIP_TEST_QUICK (valgrind) caps the draws at 12 and the friction at cheap values.
 * Prints what it tried and found; exits 1 on any violation. */

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>
#include <time.h>

#include "check.h"

static uint64_t rng_state;

/* splitmix64: the same sequence on every platform. */
static uint64_t next_u64(void)
{
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static double uniform(double lo, double hi)
{
    return lo + (hi - lo) * ((double)(next_u64() >> 11) * 0x1.0p-53);
}

static int chance(double prob)
{
    return uniform(0.0, 1.0) < prob;
}

static size_t below(size_t n)
{
    return (size_t)(next_u64() % n);
}

static double log_uniform(double lo, double hi)
{
    return exp(uniform(log(lo), log(hi)));
}

/* Values no caller should send, and the edges of the double range. */
static const double SPECIAL[] = {
    NAN,         INFINITY,      -INFINITY, 0.0,         -0.0,     -1.0,     DBL_TRUE_MIN,
    -DBL_TRUE_MIN, DBL_MIN,     1e-300,    1e-150,      1e-16,    0.5,      1.0,
    1e16,        1e150,         1e300,     DBL_MAX,     -DBL_MAX, 1.0 - DBL_EPSILON / 2,
    1.0 + DBL_EPSILON,
};
#define N_SPECIAL (sizeof SPECIAL / sizeof SPECIAL[0])

static double special(void)
{
    return SPECIAL[below(N_SPECIAL)];
}

/* `plausible`, or with probability `prob` a special value. */
static double hostile(double plausible, double prob)
{
    return chance(prob) ? special() : plausible;
}

/* Tolerances: invalid ones, ones next to 0 and 1, and ordinary ones. */
static double tolerance(int near_zero)
{
    static const double INVALID[] = {NAN, INFINITY, -INFINITY, 0.0, -0.0, -1e-3, 1.0, 2.0};
    static const double TINY[] = {DBL_TRUE_MIN, DBL_MIN, 1e-300, 1e-100, 1e-16, 1e-13};
    static const double NEAR_ONE[] = {1.0 - DBL_EPSILON / 2, 1.0 - 1e-12, 0.999, 0.9};
    double u = uniform(0.0, 1.0);
    if (u < 0.15) return INVALID[below(sizeof INVALID / sizeof INVALID[0])];
    if (u < 0.25) return NEAR_ONE[below(sizeof NEAR_ONE / sizeof NEAR_ONE[0])];
    if (u < 0.35 && near_zero) return TINY[below(sizeof TINY / sizeof TINY[0])];
    return near_zero ? log_uniform(1e-12, 0.5) : log_uniform(1e-6, 0.5);
}

struct counts {
    long draws, materials_ok, contacts, solves, solves_ok, points, field_calls, refusals;
    long status[9];
    long used[5];
    double slowest;
    long violations;
};

static struct counts n;

#define VIOLATION(...)                                                                       \
    do {                                                                                     \
        n.violations++;                                                                      \
        fprintf(stderr, "draw %ld: ", n.draws);                                              \
        fprintf(stderr, __VA_ARGS__);                                                        \
        fprintf(stderr, "\n");                                                               \
    } while (0)

/* A status from `function`: OK, or a refusal whose message names the function. */
static int ok_or_refused(orthoslip_status st, const char *function)
{
    if ((int)st >= 0 && (int)st < 9) n.status[(int)st]++;
    if (st == ORTHOSLIP_OK) return 1;
    n.refusals++;
    if ((int)st < 1 || (int)st > 8) VIOLATION("%s returned unknown status %d", function, (int)st);
    if (st == ORTHOSLIP_ERROR_INTERNAL || st == ORTHOSLIP_ERROR_PANIC)
        VIOLATION("%s returned %s", function, orthoslip_status_string(st));
    char msg[512];
    size_t len = orthoslip_last_error_message(msg, sizeof msg);
    if (len == 0 || strncmp(msg, function, strlen(function)) != 0)
        VIOLATION("%s returned %s with message \"%s\"", function, orthoslip_status_string(st),
                  len ? msg : "");
    return 0;
}

static double now(void)
{
    struct timespec t;
    timespec_get(&t, TIME_UTC);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static orthoslip_material *draw_material(char *what, size_t size)
{
    orthoslip_material *m = (orthoslip_material *)&n; /* not NULL: must be reset on failure */
    orthoslip_status st;
    const char *function;
    /* one scale for the moduli: ordinary, or next to the ends of the double range */
    static const double SCALES[] = {1.0, 1e9, 1e-300, 1e300, DBL_TRUE_MIN, 1e-310, 1e307};
    double scale = chance(0.3) ? SCALES[below(sizeof SCALES / sizeof SCALES[0])] : 1.0;
    double p = 0.06; /* per value: a special one */
    switch (below(3)) {
    case 0: {
        double e = hostile(scale * log_uniform(1e-3, 1e12), p);
        double nu = hostile(chance(0.2) ? (chance(0.5) ? -1.0 + 1e-12 : 1.0 - 1e-12)
                                        : uniform(-1.0, 1.0),
                            p);
        double delta = hostile(log_uniform(1e-4, 1e4), p);
        double kappa = hostile(-nu + log_uniform(1e-12, 1e3), p);
        snprintf(what, size, "effective(%.17g, %.17g, %.17g, %.17g)", e, nu, delta, kappa);
        function = "orthoslip_material_new_effective";
        st = orthoslip_material_new_effective(e, nu, delta, kappa, &m);
        break;
    }
    case 1: {
        double e11 = hostile(scale * log_uniform(1e-3, 1e12), p);
        double e22 = hostile(e11 * log_uniform(1e-4, 1e4), p);
        double g12 = hostile(e11 * log_uniform(1e-4, 1e2), p);
        double lim = sqrt(fabs(e11 / e22));
        double nu12 = hostile(uniform(-1.02, 1.02) * (isfinite(lim) ? lim : 1.0), p);
        snprintf(what, size, "plane_stress(%.17g, %.17g, %.17g, %.17g)", e11, e22, g12, nu12);
        function = "orthoslip_material_new_plane_stress";
        st = orthoslip_material_new_plane_stress(e11, e22, g12, nu12, &m);
        break;
    }
    default: {
        double e11 = hostile(scale * log_uniform(1e-3, 1e12), p);
        double e22 = hostile(e11 * log_uniform(1e-3, 1e3), p);
        double e33 = hostile(e11 * log_uniform(1e-3, 1e3), p);
        double g12 = hostile(e11 * log_uniform(1e-4, 1e2), p);
        double nu12 = hostile(uniform(-0.6, 0.6), p);
        double nu13 = hostile(uniform(-0.6, 0.6), p);
        double nu23 = hostile(uniform(-0.6, 0.6), p);
        snprintf(what, size, "plane_strain(%.17g, %.17g, %.17g, %.17g, %.17g, %.17g, %.17g)",
                 e11, e22, e33, g12, nu12, nu13, nu23);
        function = "orthoslip_material_new_plane_strain";
        st = orthoslip_material_new_plane_strain(e11, e22, e33, g12, nu12, nu13, nu23, &m);
        break;
    }
    }
    if (!ok_or_refused(st, function)) {
        if (m != NULL) VIOLATION("%s: %s failed but left *out non-NULL", what, function);
        return NULL;
    }
    if (m == NULL) VIOLATION("%s: OK with a NULL material", what);
    double c[4], g[3];
    if (ok_or_refused(orthoslip_material_effective(m, &c[0], &c[1], &c[2], &c[3]),
                      "orthoslip_material_effective") &&
        ok_or_refused(orthoslip_material_green(m, &g[0], &g[1], &g[2]),
                      "orthoslip_material_green")) {
        for (int i = 0; i < 4; i++)
            if (!isfinite(c[i])) VIOLATION("%s: effective constant %d = %g", what, i, c[i]);
        for (int i = 0; i < 3; i++)
            if (!isfinite(g[i]) || g[i] < 0) VIOLATION("%s: Green constant %d = %g", what, i, g[i]);
    } else {
        VIOLATION("%s: a query of a live material failed", what);
    }
    n.materials_ok++;
    return m;
}

/* Evaluation points next to +-c, +-1 and 0, exactly at them, beyond them, and hostile. */
static size_t draw_points(double c, double w, double *x, size_t cap)
{
    double base[] = {0.0,
                     -0.0,
                     c,
                     -c,
                     nextafter(c, 2.0),
                     nextafter(c, -1.0),
                     c * (1 - 1e-15),
                     c + w * 1e-15,
                     c + w * 1e-300,
                     1.0,
                     -1.0,
                     nextafter(1.0, 0.0),
                     nextafter(-1.0, 0.0),
                     nextafter(1.0, 2.0),
                     1.0 - 1e-15,
                     1.0 - w * 1e-300,
                     DBL_TRUE_MIN,
                     -DBL_TRUE_MIN,
                     DBL_MIN,
                     1e-300,
                     1.5,
                     -2.0,
                     1e300,
                     -DBL_MAX,
                     uniform(-1.0, 1.0),
                     uniform(-1.0, 1.0),
                     uniform(-1.2, 1.2),
                     0.5};
    size_t k = 0;
    for (size_t i = 0; i < sizeof base / sizeof base[0] && k < cap; i++)
        if (isfinite(base[i])) x[k++] = base[i];
    return k;
}

static const char *method_name(int m)
{
    static const char *NAMES[] = {"AUTO", "GOODMAN", "SPENCE", "COUPLED", "LCP"};
    return m >= 0 && m < 5 ? NAMES[m] : "invalid";
}

static void check_solution(const orthoslip_solution *s, int method, double mu, double beta,
                           const char *scene)
{
    const char *what = scene;
    double c = NAN, w = NAN, ec = NAN, et = NAN;
    orthoslip_method used = (orthoslip_method)-1;
    if (!ok_or_refused(orthoslip_solution_stick_half_width(s, &c), "orthoslip_solution_stick_half_width") ||
        !ok_or_refused(orthoslip_solution_slip_width(s, &w), "orthoslip_solution_slip_width") ||
        !ok_or_refused(orthoslip_solution_error_estimate(s, &ec), "orthoslip_solution_error_estimate") ||
        !ok_or_refused(orthoslip_solution_traction_error_estimate(s, &et),
                       "orthoslip_solution_traction_error_estimate") ||
        !ok_or_refused(orthoslip_solution_method(s, &used), "orthoslip_solution_method")) {
        VIOLATION("%s: a query of a live solution failed", what);
        return;
    }
    if ((int)used < 1 || (int)used > 4 || (method != 0 && (int)used != method))
        VIOLATION("%s: method %s reported as %d", what, method_name(method), (int)used);
    else
        n.used[(int)used]++;
    char as[1200];
    snprintf(as, sizeof as, "%s (as %s)", scene, method_name((int)used));
    what = as;
    int closed_form = used == ORTHOSLIP_METHOD_GOODMAN || used == ORTHOSLIP_METHOD_SPENCE;
    if (!(c >= 0 && c <= 1 && w >= 0 && w <= 1 && fabs(c + w - 1.0) <= 4e-15))
        VIOLATION("%s: c = %.17g, 1 - c = %.17g", what, c, w);
    if (!(ec >= 0 && (isfinite(ec) || closed_form)))
        VIOLATION("%s: error estimate on c %g", what, ec);
    if (!(et >= 0 && (isfinite(et) || closed_form)))
        VIOLATION("%s: traction error estimate %g", what, et);

    double x[32], p[32], q[32], pm[32], qm[32], xm[32];
    size_t k = draw_points(c, w, x, 32);
    for (size_t i = 0; i < k; i++) xm[i] = -x[i];
    n.points += (long)k;
    if (!ok_or_refused(orthoslip_solution_tractions(s, x, k, p, q), "orthoslip_solution_tractions") ||
        !ok_or_refused(orthoslip_solution_tractions(s, xm, k, pm, qm), "orthoslip_solution_tractions")) {
        VIOLATION("%s: tractions at finite points refused", what);
        return;
    }
    for (size_t i = 0; i < k; i++) {
        double ax = fabs(x[i]);
        int bad;
        if (ax > 1)
            bad = !(p[i] == 0 && q[i] == 0);
        else if (ax == 1)
            bad = !(p[i] == INFINITY && (mu == 0 ? q[i] == 0 : fabs(q[i]) == INFINITY));
        else
            /* finite, p >= 0 (then p even and q odd); Coulomb's |q| <= mu p holds only to
             * the solution's accuracy next to the stick edge, not checked here */
            bad = !(isfinite(p[i]) && isfinite(q[i]) && p[i] >= 0);
        if (!bad) bad = !(pm[i] == p[i] && qm[i] == -q[i]);
        if (bad)
            VIOLATION("%s: at x = %.17g (c = %.17g): p = %.17g, q = %.17g; at -x: %.17g, %.17g",
                      what, x[i], c, p[i], q[i], pm[i], qm[i]);
    }

    /* hostile points are refused, nothing written */
    double bad_x[3] = {0.5, NAN, 0.25}, bp[3] = {7, 7, 7}, bq[3] = {7, 7, 7};
    bad_x[1] = chance(0.5) ? NAN : (chance(0.5) ? INFINITY : -INFINITY);
    if (ok_or_refused(orthoslip_solution_tractions(s, bad_x, 3, bp, bq), "orthoslip_solution_tractions"))
        VIOLATION("%s: tractions at x = %g accepted", what, bad_x[1]);
    if (bp[0] != 7 || bq[0] != 7) VIOLATION("%s: a refused call wrote its outputs", what);
    /* NULL out-parameters are refused */
    if (ok_or_refused(orthoslip_solution_tractions(s, x, k, NULL, q), "orthoslip_solution_tractions") ||
        ok_or_refused(orthoslip_solution_stick_half_width(s, NULL),
                      "orthoslip_solution_stick_half_width") ||
        ok_or_refused(orthoslip_solution_error_estimate(s, NULL),
                      "orthoslip_solution_error_estimate"))
        VIOLATION("%s: a NULL out-parameter accepted", what);

    /* the field: edge intensity, stresses below the surface, slip */
    double ek = NAN, eg = NAN;
    n.field_calls++;
    if (ok_or_refused(orthoslip_solution_edge_intensity(s, &ek, &eg),
                      "orthoslip_solution_edge_intensity") &&
        !(isfinite(ek) && ek >= 0 && eg >= 0 && eg <= 0.5))
        VIOLATION("%s: edge intensity k = %g, g = %g", what, ek, eg);
    /* stresses on and below the surface at the traction points, down to the largest depth */
    static const double DEPTHS[] = {0.0, -DBL_TRUE_MIN, -1e-300, -1e-3, -1.0, -1e160, -DBL_MAX};
    for (size_t j = 0; j < sizeof DEPTHS / sizeof DEPTHS[0]; j++) {
        double sy[32], sxx[32], syy[32], sxy[32];
        for (size_t i = 0; i < k; i++) sy[i] = DEPTHS[j];
        if (!ok_or_refused(orthoslip_solution_stresses(s, x, sy, k, sxx, syy, sxy),
                           "orthoslip_solution_stresses")) {
            VIOLATION("%s: stresses at depth %g refused", what, DEPTHS[j]);
            continue;
        }
        for (size_t i = 0; i < k; i++) {
            /* infinite only at the punch edges themselves (on the surface: y = 0 and the
             * depths that take the surface values, below 1e-150 and below 1e-150 / beta) */
            int edge = (sy[i] > -1e-150 || -sy[i] * beta < 1e-150) && fabs(x[i]) == 1;
            if (isnan(sxx[i]) || isnan(syy[i]) || isnan(sxy[i]) ||
                (!edge && !(isfinite(sxx[i]) && isfinite(syy[i]) && isfinite(sxy[i]))))
                VIOLATION("%s: stresses at (%.17g, %g): %g %g %g", what, x[i], sy[i], sxx[i],
                          syy[i], sxy[i]);
        }
    }
    double up[1] = {DBL_TRUE_MIN}, sxx[1], syy[1], sxy[1];
    if (ok_or_refused(orthoslip_solution_stresses(s, x, up, 1, sxx, syy, sxy),
                      "orthoslip_solution_stresses"))
        VIOLATION("%s: stresses at y > 0 accepted", what);
    double slip[32];
    if (ok_or_refused(orthoslip_solution_slip(s, x, k, slip), "orthoslip_solution_slip")) {
        for (size_t i = 0; i < k; i++)
            if (isnan(slip[i])) VIOLATION("%s: slip at %.17g is NaN", what, x[i]);
    } else {
        VIOLATION("%s: slip at finite points refused", what);
    }
}

int main(void)
{
    const char *env = getenv("ORTHOSLIP_HOSTILE_DRAWS");
    long draws = env ? atol(env) : 300;
    env = getenv("ORTHOSLIP_HOSTILE_SEED");
    rng_state = env ? (uint64_t)strtoull(env, NULL, 10) : 26;
    int full = getenv("ORTHOSLIP_HOSTILE_FULL") != NULL;
    env = getenv("ORTHOSLIP_HOSTILE_MAX_SECONDS");
    double max_seconds = env ? atof(env) : 120.0;
    if (test_quick() && draws > 12) draws = 12;
    setvbuf(stdout, NULL, _IOLBF, 0); /* progress lines (slow solves) as they happen */

    char what[512], scene[1024];
    for (n.draws = 0; n.draws < draws; n.draws++) {
        orthoslip_material *m = draw_material(what, sizeof what);
        if (m == NULL) continue;
        orthoslip_contact *k = (orthoslip_contact *)&n;
        CHECK(!ok_or_refused(orthoslip_contact_new(m, NULL), "orthoslip_contact_new"));
        CHECK_OK(orthoslip_contact_new(m, &k));
        /* the characteristic roots' largest real part, which scales the depths that take
         * the surface values (orthoslip_solution_stresses) */
        double eff[4];
        CHECK_OK(orthoslip_material_effective(m, &eff[0], &eff[1], &eff[2], &eff[3]));
        double beta = eff[2] * (sqrt(0.5 * (1 + eff[3])) + (eff[3] > 1 ? sqrt(0.5 * (eff[3] - 1)) : 0));
        orthoslip_material_free(m);
        n.contacts++;

        /* friction: special values (the smallest subnormal among them), zero, or anything
         * from 1e-8 to 1e9 */
        double mu = chance(0.25) ? special() : (chance(0.1) ? 0.0 : log_uniform(1e-8, 1e9));
        if (chance(0.1)) mu = DBL_TRUE_MIN * (double)(1 + below(1000));
        if (test_quick() && isfinite(mu) && mu > 10) mu = 10; /* valgrind: cheap frictions */
        double mu_set = 0.0;
        if (ok_or_refused(orthoslip_contact_set_friction(k, mu), "orthoslip_contact_set_friction"))
            mu_set = mu;

        static const int INVALID_METHODS[] = {-1, 5, 7, 99};
        int method = chance(0.9) ? (int)below(5) : INVALID_METHODS[below(4)];
        int method_set = 0;
        if (ok_or_refused(orthoslip_contact_set_method(k, (orthoslip_method)method),
                          "orthoslip_contact_set_method"))
            method_set = method;
        else if (method >= 0 && method < 5)
            VIOLATION("method %d refused", method);

        int costly = method_set == 0 || method_set == 3 || method_set == 4;
        double tol = tolerance(full || !costly);
        if (test_quick() && isfinite(tol) && tol > 0 && tol < 1e-6) tol = 1e-6;
        double tol_set = 1e-8;
        if (ok_or_refused(orthoslip_contact_set_tolerance(k, tol), "orthoslip_contact_set_tolerance"))
            tol_set = tol;
        double ttol = NAN;
        if (chance(0.4)) {
            ttol = chance(0.3) ? (chance(0.5) ? INFINITY : special()) : tolerance(full || !costly);
            if (!full && costly && ttol > 0 && ttol < 1e-6) ttol = 1e-6;
            if (!ok_or_refused(orthoslip_contact_set_traction_tolerance(k, ttol),
                               "orthoslip_contact_set_traction_tolerance"))
                ttol = NAN;
        }
        snprintf(scene, sizeof scene, "%s, mu = %.17g, %s, tol = %.17g, traction tol = %.17g",
                 what, mu_set, method_name(method_set), tol_set, ttol);

        orthoslip_solution *s = (orthoslip_solution *)&n;
        double t0 = now();
        orthoslip_status st = orthoslip_contact_solve(k, &s);
        double dt = now() - t0;
        n.solves++;
        if (dt > n.slowest) n.slowest = dt;
        if (dt > max_seconds) VIOLATION("%s: the solve took %.1f s", scene, dt);
        if (dt > 5) printf("slow solve (%.1f s, %s): %s\n", dt, orthoslip_status_string(st), scene);
        if (ok_or_refused(st, "orthoslip_contact_solve")) {
            n.solves_ok++;
            check_solution(s, method_set, mu_set, beta, scene);
            orthoslip_solution_free(s);
        } else if (s != NULL) {
            VIOLATION("%s: solve failed but left *out non-NULL", scene);
        }
        orthoslip_contact_free(k);
    }

    printf("hostile: %ld draws, %ld materials accepted, %ld solves (%ld OK: GOODMAN %ld, "
           "SPENCE %ld, COUPLED %ld, LCP %ld), %ld traction points, %ld field checks, "
           "%ld refusals; slowest solve %.2f s\n",
           n.draws, n.materials_ok, n.solves, n.solves_ok, n.used[1], n.used[2], n.used[3],
           n.used[4], n.points, n.field_calls, n.refusals, n.slowest);
    printf("hostile: statuses:");
    for (int i = 0; i < 9; i++)
        if (n.status[i]) printf(" %s %ld", orthoslip_status_string((orthoslip_status)i), n.status[i]);
    printf("\nhostile: %ld violations\n", n.violations);
    return n.violations ? 1 : 0;
}
