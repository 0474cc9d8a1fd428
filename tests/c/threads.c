/* Thread safety of the C ABI: 8 threads solve the same contacts (different materials,
 * frictions and every method that solves) at once, many times, and each result equals the
 * serial one bitwise (c, 1 - c and the tractions); each thread also solves on contacts of its
 * own. The last-error message is per thread: a new thread has none, and while all threads
 * hold different errors (provoked between two barriers) each reads back its own.
 * Contacts use tolerance 1e-2 to keep the iterative methods cheap (this is not an accuracy
 * test). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <pthread.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "check.h"
#include "elastic.h"

#define N_THREADS 8
#define N_X 33
#define N_KINDS 8
#define MAX_JOBS 64

typedef struct {
    const test_material *material;
    double mu;
    orthoslip_method method;
    orthoslip_contact *contact; /* shared by all threads */
    double c, w, p[N_X], q[N_X];
} job;

static job jobs[MAX_JOBS];
static size_t n_jobs;
static double xs[N_X];
static char expected[N_KINDS][512];
static pthread_barrier_t barrier;
static int rounds;

/* Solves k and compares with the serial result of j bitwise. */
static void solve_and_compare(const orthoslip_contact *k, const job *j)
{
    orthoslip_solution *s = NULL;
    double c, w, p[N_X], q[N_X];
    CHECK_OK(orthoslip_contact_solve(k, &s));
    CHECK_OK(orthoslip_solution_stick_half_width(s, &c));
    CHECK_OK(orthoslip_solution_slip_width(s, &w));
    CHECK_OK(orthoslip_solution_tractions(s, xs, N_X, p, q));
    CHECK(memcmp(&c, &j->c, sizeof c) == 0 && memcmp(&w, &j->w, sizeof w) == 0);
    CHECK(memcmp(p, j->p, sizeof p) == 0 && memcmp(q, j->q, sizeof q) == 0);
    orthoslip_solution_free(s);
}

/* Provokes an error of the given kind on scratch contact k (each kind a different message). */
static void provoke(int kind, orthoslip_contact *k)
{
    orthoslip_material *m = NULL;
    orthoslip_solution *s = NULL;
    double v = 0.0, x = 0.5;
    switch (kind) {
    case 0:
        CHECK_STATUS(orthoslip_contact_set_friction(k, -1.0), ORTHOSLIP_ERROR_INVALID_ARGUMENT);
        break;
    case 1:
        CHECK_STATUS(orthoslip_contact_set_tolerance(k, 2.0), ORTHOSLIP_ERROR_INVALID_ARGUMENT);
        break;
    case 2:
        CHECK_STATUS(orthoslip_material_new_plane_stress(-1.0, 1.0, 1.0, 0.3, &m),
                     ORTHOSLIP_ERROR_INVALID_ARGUMENT);
        break;
    case 3:
        CHECK_STATUS(orthoslip_solution_tractions(NULL, &x, 1, &v, &v),
                     ORTHOSLIP_ERROR_NULL_POINTER);
        break;
    case 4: CHECK_STATUS(orthoslip_contact_solve(NULL, &s), ORTHOSLIP_ERROR_NULL_POINTER); break;
    case 5:
        CHECK_STATUS(orthoslip_contact_set_method(k, (orthoslip_method)7),
                     ORTHOSLIP_ERROR_INVALID_ARGUMENT);
        break;
    case 6:
        CHECK_STATUS(orthoslip_material_new_plane_stress(1.0, 1.0, 1.0, 1.5, &m),
                     ORTHOSLIP_ERROR_INADMISSIBLE_MATERIAL);
        break;
    default:
        CHECK_STATUS(orthoslip_material_green(NULL, &v, &v, &v), ORTHOSLIP_ERROR_NULL_POINTER);
        break;
    }
}

static void read_message(char *buf, size_t len)
{
    size_t n = orthoslip_last_error_message(buf, len);
    CHECK(n > 0 && n < len);
}

/* A contact with the test tolerance 1e-2. */
static orthoslip_contact *contact_for(const job *j)
{
    orthoslip_contact *k = test_contact_new(j->material, j->mu, j->method);
    CHECK_OK(orthoslip_contact_set_tolerance(k, 1e-2));
    /* c only: LCP's first-order tractions would need N = 1600 (traction_tolerance.c tests them) */
    CHECK_OK(orthoslip_contact_set_traction_tolerance(k, INFINITY));
    return k;
}

static void *worker(void *arg)
{
    size_t tid = *(const size_t *)arg, i;
    const job *own = &jobs[tid % n_jobs];
    orthoslip_contact *k = contact_for(own);
    char msg[512];
    int round;
    /* Every shared job per round, each thread starting elsewhere; quick mode: the jobs split
     * between the threads. */
    size_t per_round = test_quick() ? (n_jobs + N_THREADS - 1) / N_THREADS : n_jobs;
    size_t stride = test_quick() ? per_round : 1;
    CHECK(orthoslip_last_error_message(NULL, 0) == 0);
    for (round = 0; round < rounds; round++) {
        int kind = (int)((tid + (size_t)round) % N_KINDS);
        for (i = 0; i < per_round; i++) {
            const job *j = &jobs[(tid * stride + i) % n_jobs];
            solve_and_compare(j->contact, j);
        }
        solve_and_compare(k, own);
        provoke(kind, k);
        pthread_barrier_wait(&barrier); /* every thread holds its own error now */
        read_message(msg, sizeof msg);
        if (strcmp(msg, expected[kind]) != 0) {
            fprintf(stderr, "thread %zu, kind %d: read \"%s\", expected \"%s\"\n", tid, kind, msg,
                    expected[kind]);
            check_fail(__FILE__, __LINE__, "own last error message");
        }
        pthread_barrier_wait(&barrier);
    }
    orthoslip_contact_free(k);
    return NULL;
}

int main(void)
{
    static const orthoslip_method methods[] = {
        ORTHOSLIP_METHOD_GOODMAN, ORTHOSLIP_METHOD_SPENCE, ORTHOSLIP_METHOD_COUPLED,
        ORTHOSLIP_METHOD_LCP, ORTHOSLIP_METHOD_AUTO};
    static const double frictions[] = {0.1, 0.5};
    size_t n_mat, i, j, l, tids[N_THREADS];
    const test_material *mats = test_materials(&n_mat);
    pthread_t threads[N_THREADS];
    orthoslip_contact *scratch;
    gsl_set_error_handler_off();
    rounds = test_quick() ? 1 : 2;
    for (i = 0; i < N_X; i++) xs[i] = -0.99 + 1.98 * (double)i / (N_X - 1);

    /* Serial reference results, for every method that solves. */
    for (l = 0; l < sizeof methods / sizeof methods[0]; l++) {
        for (i = 0; i < n_mat; i++) {
            for (j = 0; j < (test_quick() ? 1 : sizeof frictions / sizeof frictions[0]); j++) {
                job *jb = &jobs[n_jobs];
                orthoslip_solution *s = NULL;
                CHECK(n_jobs < MAX_JOBS);
                jb->material = &mats[i];
                jb->mu = frictions[j];
                jb->method = methods[l];
                jb->contact = contact_for(jb);
                if (orthoslip_contact_solve(jb->contact, &s) != ORTHOSLIP_OK) {
                    CHECK(methods[l] != ORTHOSLIP_METHOD_GOODMAN);
                    orthoslip_contact_free(jb->contact);
                    continue;
                }
                CHECK_OK(orthoslip_solution_stick_half_width(s, &jb->c));
                CHECK_OK(orthoslip_solution_slip_width(s, &jb->w));
                CHECK_OK(orthoslip_solution_tractions(s, xs, N_X, jb->p, jb->q));
                orthoslip_solution_free(s);
                n_jobs++;
            }
        }
    }

    /* Serial messages of the error kinds, pairwise different. */
    scratch = test_contact_new(&mats[0], 0.3, ORTHOSLIP_METHOD_GOODMAN);
    for (i = 0; i < N_KINDS; i++) {
        provoke((int)i, scratch);
        read_message(expected[i], sizeof expected[i]);
        for (j = 0; j < i; j++) CHECK(strcmp(expected[i], expected[j]) != 0);
    }
    orthoslip_contact_free(scratch);

    CHECK(pthread_barrier_init(&barrier, NULL, N_THREADS) == 0);
    for (i = 0; i < N_THREADS; i++) {
        tids[i] = i;
        CHECK(pthread_create(&threads[i], NULL, worker, &tids[i]) == 0);
    }
    for (i = 0; i < N_THREADS; i++) CHECK(pthread_join(threads[i], NULL) == 0);
    pthread_barrier_destroy(&barrier);
    for (i = 0; i < n_jobs; i++) orthoslip_contact_free(jobs[i].contact);
    printf("threads: %d threads x %d rounds x %zu shared jobs (+1 own) matched the serial "
           "results bitwise; per-thread error messages held\n",
           N_THREADS, rounds, n_jobs);
    return 0;
}
