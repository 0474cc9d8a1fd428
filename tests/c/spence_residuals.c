/* Spence's approximation (METHOD_SPENCE) satisfies (E2) on the stick zone (paper eq. (11))
 * below 1e-8 relative to A p, int p = 1 and int q = 0, checked by GSL quadrature of the
 * library's p and q (residuals.h). It does not satisfy (E1) exactly, so that is not checked.
 * Edge exponent g = 1/2 - arctan(bp mu)/pi. */
#include "residuals.h"

int main(void)
{
    return residual_program("spence_residuals", ORTHOSLIP_METHOD_SPENCE,
                            RESIDUAL_E2 | RESIDUAL_INTEGRALS);
}
