/* One scene through the C API, for comparing the Python package with C bit for bit:
 *
 *   solve_scene stress E11 E22 G12 NU12 | strain E11 E22 E33 G12 NU12 NU13 NU23 |
 *               effective E NU DELTA KAPPA   MU METHOD TOL [X ...]
 *
 * METHOD is the orthoslip_method value. Prints `c`, `one_minus_c`, `error_estimate` and, per
 * X, `x p q` as hexadecimal floats (exact), and `method` as an integer. On a failed call it
 * prints `status NAME` and `message TEXT` and exits with 1. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "orthoslip.h"

static int failed(orthoslip_status status) {
    char message[1024];
    orthoslip_last_error_message(message, sizeof message);
    printf("status %s\nmessage %s\n", orthoslip_status_string(status), message);
    return 1;
}

int main(int argc, char **argv) {
    static const struct {
        const char *name;
        int count;
    } kinds[] = {{"stress", 4}, {"strain", 7}, {"effective", 4}};
    int kind = -1;
    for (int i = 0; i < 3 && argc > 1; ++i) {
        if (strcmp(argv[1], kinds[i].name) == 0) kind = i;
    }
    if (kind < 0 || argc < 2 + kinds[kind].count + 3) {
        fprintf(stderr, "usage: solve_scene stress|strain|effective CONSTANTS... MU METHOD TOL [X...]\n");
        return 2;
    }
    double k[7];
    int arg = 2;
    for (int i = 0; i < kinds[kind].count; ++i) k[i] = strtod(argv[arg++], NULL);
    const double mu = strtod(argv[arg++], NULL);
    const int method = atoi(argv[arg++]);
    const double tol = strtod(argv[arg++], NULL);

    orthoslip_material *m = NULL;
    orthoslip_contact *contact = NULL;
    orthoslip_solution *s = NULL;
    orthoslip_status st;
    if (kind == 0) st = orthoslip_material_new_plane_stress(k[0], k[1], k[2], k[3], &m);
    else if (kind == 1) st = orthoslip_material_new_plane_strain(k[0], k[1], k[2], k[3], k[4], k[5], k[6], &m);
    else st = orthoslip_material_new_effective(k[0], k[1], k[2], k[3], &m);
    if (st == ORTHOSLIP_OK) st = orthoslip_contact_new(m, &contact);
    if (st == ORTHOSLIP_OK) st = orthoslip_contact_set_friction(contact, mu);
    if (st == ORTHOSLIP_OK) st = orthoslip_contact_set_method(contact, (orthoslip_method)method);
    if (st == ORTHOSLIP_OK) st = orthoslip_contact_set_tolerance(contact, tol);
    if (st == ORTHOSLIP_OK) st = orthoslip_contact_solve(contact, &s);
    int code = 0;
    if (st != ORTHOSLIP_OK) {
        code = failed(st);
    } else {
        double c, w, err;
        orthoslip_method used;
        orthoslip_solution_stick_half_width(s, &c);
        orthoslip_solution_slip_width(s, &w);
        orthoslip_solution_error_estimate(s, &err);
        orthoslip_solution_method(s, &used);
        printf("c %a\none_minus_c %a\nerror_estimate %a\nmethod %d\n", c, w, err, (int)used);
        for (; arg < argc && code == 0; ++arg) {
            const double x = strtod(argv[arg], NULL);
            double p, q;
            st = orthoslip_solution_tractions(s, &x, 1, &p, &q);
            if (st == ORTHOSLIP_OK) printf("x %a %a %a\n", x, p, q);
            else code = failed(st);
        }
    }
    orthoslip_solution_free(s);
    orthoslip_contact_free(contact);
    orthoslip_material_free(m);
    return code;
}
