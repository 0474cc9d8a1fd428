/* Test materials and the reference Green's constants of docs/theory.md (M7), computed here
 * from the engineering constants independently of the library (valid C11 and C++17). */
#ifndef ORTHOSLIP_TEST_ELASTIC_H
#define ORTHOSLIP_TEST_ELASTIC_H

#include <math.h>
#include <stddef.h>

#include "check.h"

#define TEST_PI 3.14159265358979323846

typedef struct {
    const char *name;
    int plane_strain; /* 0: plane stress (e33, nu13, nu23 unused) */
    double e11, e22, e33, g12, nu12, nu13, nu23;
} test_material;

/* Effective constants (E, nu, delta, kappa) and Green's constants A, B, C. */
typedef struct {
    double e, nu, delta, kappa, a, b, c;
} reference_constants;

/* The materials every program runs: the default carbon/epoxy ply, isotropic steel in plane
 * strain, the ply turned by 90 degrees (delta < 1), a ply in plane strain, a material with
 * complex characteristic roots (kappa < 1) and an auxetic isotropic one (nu = -0.5).
 * Quick mode (valgrind): the first two. */
static inline const test_material *test_materials(size_t *count)
{
    static const test_material list[] = {
        {"carbon/epoxy ply, plane stress", 0, 181e9, 10.3e9, 0.0, 7.17e9, 0.28, 0.0, 0.0},
        {"steel, plane strain", 1, 210e9, 210e9, 210e9, 210e9 / 2.6, 0.3, 0.3, 0.3},
        {"ply turned 90 degrees, plane stress", 0, 10.3e9, 181e9, 0.0, 7.17e9,
         0.28 * 10.3 / 181.0, 0.0, 0.0},
        {"carbon/epoxy ply, plane strain", 1, 181e9, 10.3e9, 10.3e9, 7.17e9, 0.28, 0.28, 0.4},
        {"stiff-shear orthotropic (kappa < 1), plane stress", 0, 100e9, 50e9, 0.0, 80e9, 0.3,
         0.0, 0.0},
        {"auxetic isotropic (nu = -0.5), plane stress", 0, 1e9, 1e9, 0.0, 1e9, -0.5, 0.0, 0.0},
    };
    *count = test_quick() ? 2 : sizeof list / sizeof list[0];
    return list;
}

/* docs/theory.md (M1)-(M4): compliances with tensor shear strain, reduced for plane strain by
 * s'ij = sij - si3 sj3 / s33; E = 1/sqrt(s11 s22), nu = -E s12, delta^4 = s22/s11,
 * kappa = E (s12 + s66); A = (1 - nu)/E, B = sqrt(2(1 + kappa))/(pi delta E),
 * C = delta sqrt(2(1 + kappa))/(pi E). */
static inline reference_constants reference_constants_of(const test_material *m)
{
    double s11 = 1.0 / m->e11, s22 = 1.0 / m->e22, s12 = -m->nu12 / m->e11;
    double s66 = 1.0 / (2.0 * m->g12);
    reference_constants r;
    if (m->plane_strain) {
        double s33 = 1.0 / m->e33, s13 = -m->nu13 / m->e11, s23 = -m->nu23 / m->e22;
        s11 -= s13 * s13 / s33;
        s22 -= s23 * s23 / s33;
        s12 -= s13 * s23 / s33;
    }
    r.e = 1.0 / sqrt(s11 * s22);
    r.nu = -r.e * s12;
    r.delta = sqrt(sqrt(s22 / s11));
    r.kappa = r.e * (s12 + s66);
    r.a = (1.0 - r.nu) / r.e;
    r.b = sqrt(2.0 * (1.0 + r.kappa)) / (TEST_PI * r.delta * r.e);
    r.c = r.delta * sqrt(2.0 * (1.0 + r.kappa)) / (TEST_PI * r.e);
    return r;
}

static inline orthoslip_material *test_material_new(const test_material *m)
{
    orthoslip_material *out = NULL;
    if (m->plane_strain)
        CHECK_OK(orthoslip_material_new_plane_strain(m->e11, m->e22, m->e33, m->g12, m->nu12,
                                                     m->nu13, m->nu23, &out));
    else
        CHECK_OK(orthoslip_material_new_plane_stress(m->e11, m->e22, m->g12, m->nu12, &out));
    CHECK(out != NULL);
    return out;
}

/* A contact for material m, friction mu and the given method. */
static inline orthoslip_contact *test_contact_new(const test_material *m, double mu,
                                                  orthoslip_method method)
{
    orthoslip_material *mat = test_material_new(m);
    orthoslip_contact *k = NULL;
    CHECK_OK(orthoslip_contact_new(mat, &k));
    CHECK(k != NULL);
    orthoslip_material_free(mat);
    CHECK_OK(orthoslip_contact_set_friction(k, mu));
    CHECK_OK(orthoslip_contact_set_method(k, method));
    return k;
}

#endif
