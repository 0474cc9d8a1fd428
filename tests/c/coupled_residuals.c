/* The coupled solution (METHOD_COUPLED) satisfies the full problem, checked by GSL quadrature
 * of the library's p and q (residuals.h): (E1) on |x| < 1 (paper eq. (10)) and (E2) on the
 * stick zone (paper eq. (11)) below 1e-8 relative to the size of their terms, int p = 1,
 * int q = 0, |q| <= mu p on the stick zone, q = mu p sgn x on the slip zones and the slip
 * direction. Edge exponent g = 1/2 - arctan(bp mu)/pi. */
#include "residuals.h"

int main(void)
{
    return residual_program("coupled_residuals", ORTHOSLIP_METHOD_COUPLED,
                            RESIDUAL_E1 | RESIDUAL_E2 | RESIDUAL_INTEGRALS |
                                RESIDUAL_FRICTION | RESIDUAL_SLIP_DIRECTION);
}
