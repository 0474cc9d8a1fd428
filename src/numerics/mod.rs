//! The numerical tools the solvers share, one home each: special functions, orthogonal
//! polynomials, Gauss quadrature, Cauchy transforms of weighted polynomials and root finding.

pub(crate) mod bonded;
pub(crate) mod cauchy;
pub(crate) mod jacobi_transform;
pub(crate) mod lstsq;
pub(crate) mod orthopoly;
pub(crate) mod quadrature;
pub(crate) mod quotient;
pub(crate) mod roots;
pub(crate) mod special;
