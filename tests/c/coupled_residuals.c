/* The coupled solution (METHOD_COUPLED) satisfies the full problem, checked by GSL quadrature
 * of the library's p and q (residuals.h): (E1) on |x| < 1 (paper eq. (10)) and (E2) on the
 * stick zone (paper eq. (11)) below 1e-8 relative to the size of their terms, int p = 1,
 * int q = 0, |q| <= mu p on the stick zone, q = mu p sgn x on the slip zones and the slip
 * direction. Edge exponent g = 1/2 - arctan(bp mu)/pi.
 *
 * Besides the test materials: a nearly incompressible isotropic material in plane strain
 * (nu = 0.45, b* = 0.091), below the tabulated stick edge's range (b* >= 0.25), where the
 * spectral solver starts from Spence's stick edge (docs/theory_spectral.md (S7)), at
 * frictions whose stick zones it serves (c = 0.2 .. 1 - 3.5e-4). */
#include "residuals.h"

int main(void)
{
    const int mask = RESIDUAL_E1 | RESIDUAL_E2 | RESIDUAL_INTEGRALS | RESIDUAL_FRICTION |
                     RESIDUAL_SLIP_DIRECTION;
    static const test_material low = {"isotropic (nu = 0.45), plane strain",
                                      1,
                                      3e9,
                                      3e9,
                                      3e9,
                                      3e9 / 2.9,
                                      0.45,
                                      0.45,
                                      0.45};
    static const double frictions[] = {0.05, 0.1, 0.3};
    const size_t n = test_quick() ? 1 : sizeof frictions / sizeof frictions[0];
    residual_summary s = residual_summary_new();
    size_t j;
    int rc = residual_program("coupled_residuals", ORTHOSLIP_METHOD_COUPLED, mask);
    gsl_set_error_handler_off();
    for (j = 0; j < n; j++)
        check_residuals(&low, frictions[j], ORTHOSLIP_METHOD_COUPLED, mask, &s);
    printf("coupled_residuals below the table: %d cases: max rel. residual (E1) %.3e, (E2) "
           "%.3e; max |int p - 1| %.3e, |int q| %.3e; max |q|/(mu p) on stick %.6f; %d GSL "
           "calls without GSL_SUCCESS\n",
           s.cases, s.e1, s.e2, s.int_p, s.int_q, s.stick_ratio, s.quad_failures);
    return rc;
}
