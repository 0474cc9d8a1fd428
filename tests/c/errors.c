/* Every error path of the C ABI: the documented status, a non-empty last-error message set by
 * that very call, handle out-parameters set to NULL and other out-parameters untouched;
 * orthoslip_last_error_message's length and truncation rules; orthoslip_status_string and
 * orthoslip_version; mu = 0 (c = 0, q = 0) is valid. */
#include <math.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "check.h"
#include "elastic.h"

#define SENTINEL (-123.456)

static char handle_storage;
#define SENTINEL_HANDLE(T) ((T *)(void *)&handle_storage)

/* Before each expected failure another call fails first (one of two, so that a call can be
 * told apart from at least one of them): the message read afterwards must be the new one. */
static char baseline[1024];

static void set_baseline(int which)
{
    if (which == 0)
        CHECK_STATUS(orthoslip_contact_set_tolerance(NULL, -1.0), ORTHOSLIP_ERROR_NULL_POINTER);
    else
        CHECK_STATUS(orthoslip_solution_slip_width(NULL, NULL), ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK(orthoslip_last_error_message(baseline, sizeof baseline) < sizeof baseline);
}

/* The last call failed: its message is non-empty and read back consistently; returns whether
 * it differs from the baseline. */
static int fresh_message(const char *file, int line)
{
    size_t n = orthoslip_last_error_message(NULL, 0);
    char *full = (char *)malloc(n + 1);
    int fresh;
    if (n == 0 || full == NULL) check_fail(file, line, "non-empty last error message");
    if (orthoslip_last_error_message(full, n + 1) != n || strlen(full) != n)
        check_fail(file, line, "last error message length");
    fresh = strcmp(full, baseline) != 0;
    free(full);
    return fresh;
}

/* expr fails with status want and sets its own message. */
#define EXPECT_FAIL(expr, want)                                                              \
    do {                                                                                     \
        int pass_;                                                                           \
        for (pass_ = 0; pass_ < 2; pass_++) {                                                \
            set_baseline(pass_);                                                             \
            CHECK_STATUS(expr, want);                                                        \
            if (fresh_message(__FILE__, __LINE__)) break;                                    \
        }                                                                                    \
        if (pass_ == 2) check_fail(__FILE__, __LINE__, "the failing call set its message");  \
    } while (0)

#define NULLP ORTHOSLIP_ERROR_NULL_POINTER
#define INVALID ORTHOSLIP_ERROR_INVALID_ARGUMENT
#define INADMISSIBLE ORTHOSLIP_ERROR_INADMISSIBLE_MATERIAL

static const double non_finite[3] = {NAN, INFINITY, -INFINITY};

static orthoslip_status plane_stress(const double v[4], orthoslip_material **out)
{
    return orthoslip_material_new_plane_stress(v[0], v[1], v[2], v[3], out);
}

static orthoslip_status plane_strain(const double v[7], orthoslip_material **out)
{
    return orthoslip_material_new_plane_strain(v[0], v[1], v[2], v[3], v[4], v[5], v[6], out);
}

static orthoslip_status effective(const double v[4], orthoslip_material **out)
{
    return orthoslip_material_new_effective(v[0], v[1], v[2], v[3], out);
}

typedef orthoslip_status (*constructor)(const double *, orthoslip_material **);

/* Constructor ctor with values v fails with want; *out goes from a sentinel to NULL. */
static void expect_constructor_fails(constructor ctor, const double *v, orthoslip_status want,
                                     int line)
{
    orthoslip_material *m = SENTINEL_HANDLE(orthoslip_material);
    orthoslip_status got = ctor(v, &m);
    if (got != want) {
        fprintf(stderr, "errors.c:%d: got %s, expected %s\n", line,
                orthoslip_status_string(got), orthoslip_status_string(want));
        check_fail(__FILE__, line, "constructor status");
    }
    if (m != NULL) check_fail(__FILE__, line, "*out set to NULL");
    EXPECT_FAIL(ctor(v, &m), want);
}

/* Each argument i of ctor (n values, valid set v) made non-finite, and for i < moduli made
 * 0 and -1, gives INVALID_ARGUMENT; out = NULL gives NULL_POINTER. */
static void check_constructor(constructor ctor, const double *v, size_t n, size_t moduli)
{
    double w[7];
    size_t i, j;
    orthoslip_material *m = NULL;
    CHECK_OK(ctor(v, &m));
    CHECK(m != NULL);
    orthoslip_material_free(m);
    EXPECT_FAIL(ctor(v, NULL), NULLP);
    for (i = 0; i < n; i++) {
        memcpy(w, v, n * sizeof *w);
        for (j = 0; j < 3; j++) {
            w[i] = non_finite[j];
            expect_constructor_fails(ctor, w, INVALID, __LINE__);
        }
        if (i < moduli) {
            w[i] = 0.0;
            expect_constructor_fails(ctor, w, INVALID, __LINE__);
            w[i] = -1.0;
            expect_constructor_fails(ctor, w, INVALID, __LINE__);
        }
    }
}

static void check_materials(void)
{
    const double stress[4] = {181e9, 10.3e9, 7.17e9, 0.28};
    const double strain[7] = {181e9, 10.3e9, 10.3e9, 7.17e9, 0.28, 0.28, 0.4};
    const double eff[4] = {43e9, 0.07, 2.0, 2.9};
    double v[7];
    orthoslip_material *m = NULL;

    check_constructor(plane_stress, stress, 4, 3);
    check_constructor(plane_strain, strain, 7, 4);
    check_constructor(effective, eff, 4, 1);

    /* Plane stress is admissible iff nu12^2 < E11/E22 (= 1 here, 17.57 for the ply). */
    v[0] = v[1] = v[2] = 1.0;
    v[3] = 1.5;
    expect_constructor_fails(plane_stress, v, INADMISSIBLE, __LINE__);
    v[3] = -1.0;
    expect_constructor_fails(plane_stress, v, INADMISSIBLE, __LINE__);
    memcpy(v, stress, sizeof stress);
    v[3] = 4.3;
    expect_constructor_fails(plane_stress, v, INADMISSIBLE, __LINE__);
    v[3] = -4.1;
    CHECK_OK(plane_stress(v, &m));
    orthoslip_material_free(m);

    /* Plane strain: isotropic nu = 0.5 (incompressible) and 0.6 are not positive definite;
     * nu13^2 < E11/E33 is needed. */
    v[0] = v[1] = v[2] = 1.0;
    v[3] = 1.0 / 3.0;
    v[4] = v[5] = v[6] = 0.5;
    expect_constructor_fails(plane_strain, v, INADMISSIBLE, __LINE__);
    v[4] = v[5] = v[6] = 0.6;
    expect_constructor_fails(plane_strain, v, INADMISSIBLE, __LINE__);
    memcpy(v, strain, sizeof strain);
    v[5] = 4.3;
    expect_constructor_fails(plane_strain, v, INADMISSIBLE, __LINE__);

    /* Effective constants: delta > 0, -1 < nu < 1, kappa > -nu. */
    memcpy(v, eff, sizeof eff);
    v[2] = 0.0;
    expect_constructor_fails(effective, v, INVALID, __LINE__);
    v[2] = -1.0;
    expect_constructor_fails(effective, v, INVALID, __LINE__);
    memcpy(v, eff, sizeof eff);
    v[1] = 1.0;
    expect_constructor_fails(effective, v, INADMISSIBLE, __LINE__);
    v[1] = -1.5;
    expect_constructor_fails(effective, v, INADMISSIBLE, __LINE__);
    v[1] = 0.3;
    v[3] = -0.3;
    expect_constructor_fails(effective, v, INADMISSIBLE, __LINE__);

    orthoslip_material_free(NULL);
}

/* material_effective and material_green: NULL in any position, nothing written. */
static void check_material_queries(const orthoslip_material *m)
{
    double o[4];
    size_t i, j;
    for (i = 0; i < 5; i++) {
        double *p[4];
        const orthoslip_material *mm = i == 4 ? NULL : m;
        for (j = 0; j < 4; j++) {
            o[j] = SENTINEL;
            p[j] = i == j ? NULL : &o[j];
        }
        EXPECT_FAIL(orthoslip_material_effective(mm, p[0], p[1], p[2], p[3]), NULLP);
        for (j = 0; j < 4; j++) CHECK(o[j] == SENTINEL);
        if (i == 3) continue;
        EXPECT_FAIL(orthoslip_material_green(mm, p[0], p[1], p[2]), NULLP);
        for (j = 0; j < 3; j++) CHECK(o[j] == SENTINEL);
    }
}

static void check_contact_setters(orthoslip_contact *k)
{
    static const double bad_mu[] = {-0.1, -1e-300, NAN, INFINITY, -INFINITY};
    static const double bad_tol[] = {0.0, -1e-8, 1.0, 1.5, NAN, INFINITY, -INFINITY};
    size_t i;
    orthoslip_solution *s = NULL;
    orthoslip_method used;

    EXPECT_FAIL(orthoslip_contact_set_friction(NULL, 0.3), NULLP);
    EXPECT_FAIL(orthoslip_contact_set_method(NULL, ORTHOSLIP_METHOD_GOODMAN), NULLP);
    EXPECT_FAIL(orthoslip_contact_set_tolerance(NULL, 1e-8), NULLP);
    for (i = 0; i < sizeof bad_mu / sizeof bad_mu[0]; i++)
        EXPECT_FAIL(orthoslip_contact_set_friction(k, bad_mu[i]), INVALID);
    for (i = 0; i < sizeof bad_tol / sizeof bad_tol[0]; i++)
        EXPECT_FAIL(orthoslip_contact_set_tolerance(k, bad_tol[i]), INVALID);

    /* Invalid method values leave the contact's method unchanged. In C++ an unscoped enum
     * only holds the values of its bit range (0..7 here). */
    CHECK_OK(orthoslip_contact_set_method(k, ORTHOSLIP_METHOD_GOODMAN));
    EXPECT_FAIL(orthoslip_contact_set_method(k, (orthoslip_method)5), INVALID);
    EXPECT_FAIL(orthoslip_contact_set_method(k, (orthoslip_method)7), INVALID);
#ifndef __cplusplus
    EXPECT_FAIL(orthoslip_contact_set_method(k, (orthoslip_method)99), INVALID);
    EXPECT_FAIL(orthoslip_contact_set_method(k, (orthoslip_method)-1), INVALID);
#endif
    CHECK_OK(orthoslip_contact_solve(k, &s));
    CHECK_OK(orthoslip_solution_method(s, &used));
    CHECK(used == ORTHOSLIP_METHOD_GOODMAN);
    orthoslip_solution_free(s);

    s = SENTINEL_HANDLE(orthoslip_solution);
    EXPECT_FAIL(orthoslip_contact_solve(NULL, &s), NULLP);
    CHECK(s == NULL);
    EXPECT_FAIL(orthoslip_contact_solve(k, NULL), NULLP);
    orthoslip_contact_free(NULL);
}

/* Each method solves, or fails cleanly (not yet available; or, for the iterative methods at
 * tolerance 1e-4, tolerance not met). Tolerance 1e-2 keeps the iterative methods cheap; 1e-4
 * (LCP's first-order convergence: seconds) only outside quick mode. */
static void check_methods(orthoslip_contact *k)
{
    static const orthoslip_method methods[] = {ORTHOSLIP_METHOD_AUTO, ORTHOSLIP_METHOD_SPENCE,
                                               ORTHOSLIP_METHOD_COUPLED, ORTHOSLIP_METHOD_LCP};
    size_t i, n_tol = test_quick() ? 1 : 2;
    for (i = 0; i < n_tol * (sizeof methods / sizeof methods[0]); i++) {
        size_t mi = i % (sizeof methods / sizeof methods[0]);
        double tol = i < sizeof methods / sizeof methods[0] ? 1e-2 : 1e-4;
        orthoslip_solution *s = SENTINEL_HANDLE(orthoslip_solution);
        orthoslip_status st;
        CHECK_OK(orthoslip_contact_set_method(k, methods[mi]));
        CHECK_OK(orthoslip_contact_set_tolerance(k, tol));
        /* c only: LCP's first-order tractions would need N = 1600 (traction_tolerance.c tests them) */
        CHECK_OK(orthoslip_contact_set_traction_tolerance(k, INFINITY));
        st = orthoslip_contact_solve(k, &s);
        if (st == ORTHOSLIP_OK) {
            orthoslip_method used;
            double c;
            CHECK(s != NULL);
            CHECK_OK(orthoslip_solution_method(s, &used));
            CHECK(used != ORTHOSLIP_METHOD_AUTO);
            CHECK(methods[mi] == ORTHOSLIP_METHOD_AUTO || used == methods[mi]);
            CHECK_OK(orthoslip_solution_stick_half_width(s, &c));
            CHECK(c > 0.0 && c < 1.0);
            orthoslip_solution_free(s);
        } else {
            CHECK(s == NULL);
            EXPECT_FAIL(orthoslip_contact_solve(k, &s), st);
        }
        printf("errors: method %d, tolerance %g: %s\n", (int)methods[mi], tol,
               orthoslip_status_string(st));
    }
    CHECK_OK(orthoslip_contact_set_method(k, ORTHOSLIP_METHOD_GOODMAN));
    CHECK_OK(orthoslip_contact_set_tolerance(k, 1e-8));
}

static void check_solution_queries(const orthoslip_solution *s)
{
    double v = SENTINEL, x[3] = {0.1, 0.5, 0.2}, p[3], q[3];
    orthoslip_method used = (orthoslip_method)ORTHOSLIP_METHOD_LCP;
    size_t i, j;
    EXPECT_FAIL(orthoslip_solution_stick_half_width(NULL, &v), NULLP);
    EXPECT_FAIL(orthoslip_solution_stick_half_width(s, NULL), NULLP);
    EXPECT_FAIL(orthoslip_solution_slip_width(NULL, &v), NULLP);
    EXPECT_FAIL(orthoslip_solution_slip_width(s, NULL), NULLP);
    EXPECT_FAIL(orthoslip_solution_error_estimate(NULL, &v), NULLP);
    EXPECT_FAIL(orthoslip_solution_error_estimate(s, NULL), NULLP);
    CHECK(v == SENTINEL);
    EXPECT_FAIL(orthoslip_solution_method(NULL, &used), NULLP);
    EXPECT_FAIL(orthoslip_solution_method(s, NULL), NULLP);
    CHECK(used == ORTHOSLIP_METHOD_LCP);

    /* tractions: any NULL pointer, also with n = 0; a non-finite x anywhere; nothing
     * written. */
    for (i = 0; i < 2; i++) {
        size_t n = i == 0 ? 3 : 0;
        for (j = 0; j < 3; j++) p[j] = q[j] = SENTINEL;
        EXPECT_FAIL(orthoslip_solution_tractions(NULL, x, n, p, q), NULLP);
        EXPECT_FAIL(orthoslip_solution_tractions(s, NULL, n, p, q), NULLP);
        EXPECT_FAIL(orthoslip_solution_tractions(s, x, n, NULL, q), NULLP);
        EXPECT_FAIL(orthoslip_solution_tractions(s, x, n, p, NULL), NULLP);
        for (j = 0; j < 3; j++) CHECK(p[j] == SENTINEL && q[j] == SENTINEL);
    }
    for (i = 0; i < 3; i++) {
        x[1] = non_finite[i];
        EXPECT_FAIL(orthoslip_solution_tractions(s, x, 3, p, q), INVALID);
        for (j = 0; j < 3; j++) CHECK(p[j] == SENTINEL && q[j] == SENTINEL);
    }
    CHECK_OK(orthoslip_solution_tractions(s, x, 0, p, q));
    for (j = 0; j < 3; j++) CHECK(p[j] == SENTINEL && q[j] == SENTINEL);
    orthoslip_solution_free(NULL);
}

/* mu = 0 is valid: no stick zone, no shear traction. */
static void check_frictionless(orthoslip_contact *k)
{
    double x[5] = {-1.0, -0.5, 0.0, 0.7, 1.0}, p[5], q[5], c = SENTINEL, w = SENTINEL;
    orthoslip_solution *s = NULL;
    size_t i;
    CHECK_OK(orthoslip_contact_set_friction(k, 0.0));
    CHECK_OK(orthoslip_contact_solve(k, &s));
    CHECK_OK(orthoslip_solution_stick_half_width(s, &c));
    CHECK_OK(orthoslip_solution_slip_width(s, &w));
    CHECK(c == 0.0 && w == 1.0);
    CHECK_OK(orthoslip_solution_tractions(s, x, 5, p, q));
    for (i = 0; i < 5; i++) CHECK(p[i] > 0.0 && q[i] == 0.0);
    CHECK(isinf(p[0]) && isinf(p[4]));
    orthoslip_solution_free(s);
    CHECK_OK(orthoslip_contact_set_friction(k, 0.3));
}

static void check_message_buffer(void)
{
    char full[1024], small[8], one = 'x', none = 'y';
    size_t n;
    CHECK_STATUS(orthoslip_material_new_plane_stress(-1.0, 1.0, 1.0, 0.3, NULL), NULLP);
    n = orthoslip_last_error_message(NULL, 0);
    CHECK(n > sizeof small && n < sizeof full);
    CHECK(orthoslip_last_error_message(full, sizeof full) == n && strlen(full) == n);
    CHECK(orthoslip_last_error_message(small, sizeof small) == n);
    CHECK(small[sizeof small - 1] == '\0' && strncmp(small, full, sizeof small - 1) == 0);
    CHECK(orthoslip_last_error_message(&one, 1) == n && one == '\0');
    CHECK(orthoslip_last_error_message(&none, 0) == n && none == 'y');

    /* Successful calls leave the message unchanged. */
    {
        char again[1024];
        orthoslip_material *m = NULL;
        CHECK_OK(orthoslip_material_new_plane_stress(1.0, 1.0, 1.0, 0.3, &m));
        orthoslip_material_free(m);
        CHECK(orthoslip_last_error_message(again, sizeof again) == n);
        CHECK(strcmp(again, full) == 0);
    }
}

static void check_strings(void)
{
    /* The ABI is append-only: each status keeps its number (its index here) and its name. */
    static const struct {
        orthoslip_status status;
        const char *name;
    } statuses[] = {
        {ORTHOSLIP_OK, "ORTHOSLIP_OK"},
        {ORTHOSLIP_ERROR_NULL_POINTER, "ORTHOSLIP_ERROR_NULL_POINTER"},
        {ORTHOSLIP_ERROR_INVALID_ARGUMENT, "ORTHOSLIP_ERROR_INVALID_ARGUMENT"},
        {ORTHOSLIP_ERROR_INADMISSIBLE_MATERIAL, "ORTHOSLIP_ERROR_INADMISSIBLE_MATERIAL"},
        {ORTHOSLIP_ERROR_NO_CONVERGENCE, "ORTHOSLIP_ERROR_NO_CONVERGENCE"},
        {ORTHOSLIP_ERROR_TOLERANCE_NOT_MET, "ORTHOSLIP_ERROR_TOLERANCE_NOT_MET"},
        {ORTHOSLIP_ERROR_INTERNAL, "ORTHOSLIP_ERROR_INTERNAL"},
        {ORTHOSLIP_ERROR_PANIC, "ORTHOSLIP_ERROR_PANIC"},
        {ORTHOSLIP_ERROR_NO_ADMISSIBLE_SOLUTION, "ORTHOSLIP_ERROR_NO_ADMISSIBLE_SOLUTION"},
    };
    const char *v = orthoslip_version();
    unsigned major, minor, patch;
    char end;
    int i;
    for (i = 0; i < (int)(sizeof statuses / sizeof statuses[0]); i++) {
        const char *s = orthoslip_status_string((orthoslip_status)i);
        CHECK((int)statuses[i].status == i);
        CHECK(s != NULL && strcmp(s, statuses[i].name) == 0);
    }
#ifndef __cplusplus
    CHECK(strcmp(orthoslip_status_string((orthoslip_status)99), "ORTHOSLIP_STATUS_UNKNOWN") == 0);
    CHECK(strcmp(orthoslip_status_string((orthoslip_status)9), "ORTHOSLIP_STATUS_UNKNOWN") == 0);
#endif
    CHECK(v != NULL);
    CHECK(sscanf(v, "%u.%u.%u%c", &major, &minor, &patch, &end) == 3);
    printf("errors: orthoslip %s\n", v);
}

int main(void)
{
    size_t n_mat;
    const test_material *mats = test_materials(&n_mat);
    orthoslip_material *m = test_material_new(&mats[0]);
    orthoslip_contact *k = NULL;
    orthoslip_solution *s = NULL;
    gsl_set_error_handler_off();

    check_strings();
    check_message_buffer();
    check_materials();
    check_material_queries(m);

    k = SENTINEL_HANDLE(orthoslip_contact);
    EXPECT_FAIL(orthoslip_contact_new(NULL, &k), NULLP);
    CHECK(k == NULL);
    EXPECT_FAIL(orthoslip_contact_new(m, NULL), NULLP);
    CHECK_OK(orthoslip_contact_new(m, &k));
    orthoslip_material_free(m);
    CHECK_OK(orthoslip_contact_set_friction(k, 0.3));
    check_contact_setters(k);
    check_methods(k);
    check_frictionless(k);

    CHECK_OK(orthoslip_contact_solve(k, &s));
    check_solution_queries(s);
    orthoslip_solution_free(s);
    orthoslip_contact_free(k);
    printf("errors: all error paths checked\n");
    return 0;
}
