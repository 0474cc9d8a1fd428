/* Goodman's solution (METHOD_GOODMAN) satisfies its own equations, checked by GSL quadrature
 * of the library's p and q (residuals.h): (E2) on the stick zone (paper eq. (11)) below 1e-8
 * relative to A p, int p = 1, int q = 0, the friction law pointwise and the slip direction.
 * (E1) is not checked: Goodman's approximation neglects q in it (docs/theory.md §7). */
#include "residuals.h"

int main(void)
{
    return residual_program("goodman_residuals", ORTHOSLIP_METHOD_GOODMAN,
                            RESIDUAL_E2 | RESIDUAL_INTEGRALS | RESIDUAL_FRICTION |
                                RESIDUAL_SLIP_DIRECTION);
}
