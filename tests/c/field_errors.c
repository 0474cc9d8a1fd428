/* Bad inputs to the field functions (valid C11 and C++17): NULL pointers get
 * ORTHOSLIP_ERROR_NULL_POINTER (also when n = 0), NaN or infinite coordinates and y > 0 get
 * ORTHOSLIP_ERROR_INVALID_ARGUMENT with a message naming the function and the point, and
 * nothing is written on failure (also when only a later point is bad); n = 0 with valid
 * pointers is fine; inputs may alias outputs; the punch edge on the surface is infinite. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "elastic.h"

#define SENTINEL 12345.0

/* sxx, syy, sxy at two points, the second one (x1, y1) possibly bad: status want, and the
 * outputs untouched unless it is OK. */
static void stresses_case(const orthoslip_solution *s, double x1, double y1,
                          orthoslip_status want, const char *fragment)
{
    double x[2] = {0.0, x1}, y[2] = {-0.5, y1}, out[3][2];
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 2; j++) out[i][j] = SENTINEL;
    CHECK_STATUS(orthoslip_solution_stresses(s, x, y, 2, out[0], out[1], out[2]), want);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 2; j++) CHECK((out[i][j] == SENTINEL) == (want != ORTHOSLIP_OK));
    if (want != ORTHOSLIP_OK) CHECK_MESSAGE("orthoslip_solution_stresses", fragment);
}

int main(void)
{
    size_t n_mat;
    const test_material *mats = test_materials(&n_mat);
    orthoslip_contact *contact = test_contact_new(&mats[0], 0.3, ORTHOSLIP_METHOD_GOODMAN);
    orthoslip_solution *s = NULL;
    double x = 0.2, y = -0.1, a = SENTINEL, b = SENTINEL, c = SENTINEL, k = SENTINEL,
           g = SENTINEL, u = SENTINEL;
    CHECK_OK(orthoslip_contact_solve(contact, &s));

    /* NULL pointers, also with n = 0; nothing written */
    CHECK_STATUS(orthoslip_solution_stresses(NULL, &x, &y, 1, &a, &b, &c),
                 ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK_STATUS(orthoslip_solution_stresses(s, NULL, &y, 1, &a, &b, &c),
                 ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK_STATUS(orthoslip_solution_stresses(s, &x, NULL, 0, &a, &b, &c),
                 ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK_STATUS(orthoslip_solution_stresses(s, &x, &y, 1, NULL, &b, &c),
                 ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK_STATUS(orthoslip_solution_stresses(s, &x, &y, 1, &a, NULL, &c),
                 ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK_STATUS(orthoslip_solution_stresses(s, &x, &y, 1, &a, &b, NULL),
                 ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK_MESSAGE("orthoslip_solution_stresses", "sxy");
    CHECK(a == SENTINEL && b == SENTINEL && c == SENTINEL);
    CHECK_STATUS(orthoslip_solution_edge_intensity(NULL, &k, &g), ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK_STATUS(orthoslip_solution_edge_intensity(s, NULL, &g), ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK_STATUS(orthoslip_solution_edge_intensity(s, &k, NULL), ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK(k == SENTINEL && g == SENTINEL);
    CHECK_STATUS(orthoslip_solution_slip(NULL, &x, 1, &u), ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK_STATUS(orthoslip_solution_slip(s, NULL, 0, &u), ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK_STATUS(orthoslip_solution_slip(s, &x, 1, NULL), ORTHOSLIP_ERROR_NULL_POINTER);
    CHECK(u == SENTINEL);

    /* n = 0 with valid pointers: OK, nothing written */
    CHECK_OK(orthoslip_solution_stresses(s, &x, &y, 0, &a, &b, &c));
    CHECK_OK(orthoslip_solution_slip(s, &x, 0, &u));
    CHECK(a == SENTINEL && u == SENTINEL);

    /* bad coordinates: nothing written, not even for the good first point */
    stresses_case(s, NAN, -0.5, ORTHOSLIP_ERROR_INVALID_ARGUMENT, "x[1]");
    stresses_case(s, 0.3, NAN, ORTHOSLIP_ERROR_INVALID_ARGUMENT, "y[1]");
    stresses_case(s, INFINITY, -0.5, ORTHOSLIP_ERROR_INVALID_ARGUMENT, "x[1]");
    stresses_case(s, 0.3, -INFINITY, ORTHOSLIP_ERROR_INVALID_ARGUMENT, "y[1]");
    stresses_case(s, 0.3, 1e-300, ORTHOSLIP_ERROR_INVALID_ARGUMENT, "outside the solid");
    stresses_case(s, 0.3, 0.0, ORTHOSLIP_OK, "");
    stresses_case(s, 0.3, -0.0, ORTHOSLIP_OK, "");
    {
        double xs[2] = {0.5, NAN}, us[2] = {SENTINEL, SENTINEL};
        CHECK_STATUS(orthoslip_solution_slip(s, xs, 2, us), ORTHOSLIP_ERROR_INVALID_ARGUMENT);
        CHECK_MESSAGE("orthoslip_solution_slip", "x[1]");
        xs[1] = -INFINITY;
        CHECK_STATUS(orthoslip_solution_slip(s, xs, 2, us), ORTHOSLIP_ERROR_INVALID_ARGUMENT);
        CHECK(us[0] == SENTINEL && us[1] == SENTINEL);
    }

    /* aliasing: x as sxx and y as syy give what separate buffers give */
    {
        double xs[2] = {0.4, 1.2}, ys[2] = {-0.3, -0.05}, ref[3][2], xa[2], ya[2], sxy[2];
        memcpy(xa, xs, sizeof xs);
        memcpy(ya, ys, sizeof ys);
        CHECK_OK(orthoslip_solution_stresses(s, xs, ys, 2, ref[0], ref[1], ref[2]));
        CHECK_OK(orthoslip_solution_stresses(s, xa, ya, 2, xa, ya, sxy));
        CHECK(xa[0] == ref[0][0] && xa[1] == ref[0][1] && ya[0] == ref[1][0] &&
              ya[1] == ref[1][1] && sxy[1] == ref[2][1]);
        CHECK_OK(orthoslip_solution_slip(s, xs, 2, xs));
        CHECK(xs[0] < 0.0);
    }

    /* the punch edge itself: infinite, never NaN */
    x = 1.0;
    y = 0.0;
    CHECK_OK(orthoslip_solution_stresses(s, &x, &y, 1, &a, &b, &c));
    CHECK(a == -INFINITY && b == -INFINITY && c == INFINITY);
    CHECK_OK(orthoslip_solution_edge_intensity(s, &k, &g));
    CHECK(k > 0.0 && g == 0.5);

    orthoslip_solution_free(s);
    orthoslip_contact_free(contact);
    printf("field_errors: ok\n");
    return 0;
}
