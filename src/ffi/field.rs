//! What engineers compute from a solution (issue 10): stresses inside the solid, the
//! punch-edge intensity and the slip. The field is built from the solution's own tractions
//! on first use (a fraction of a millisecond) and shared by every later call and thread.

use super::solution::orthoslip_solution;
use super::{Failure, deref, orthoslip_status, run, write_all};
use crate::error::Error;

/// The first of n values that is not finite, as an InvalidArgument failure naming it.
///
/// # Safety
/// `v` must be valid for n reads.
unsafe fn check_finite(v: *const f64, n: usize, name: &str) -> Result<(), Failure> {
    match (0..n).find(|&i| !unsafe { *v.add(i) }.is_finite()) {
        Some(i) => {
            let value = unsafe { *v.add(i) };
            Err(Error::InvalidArgument(format!("{name}[{i}] = {value} is not finite")).into())
        }
        None => Ok(()),
    }
}

/// Evaluates the stresses inside the solid at n points (x[i], y[i]) in units of the punch
/// half-width a, dimensionless per P/a. The solid is y < 0; y = 0 gives the surface values
/// as limits from inside, and so do depths below 1e-150 (they differ from them by less than
/// rounding), and below 1e-150 / beta for materials whose characteristic roots are that
/// small (beta = delta (sqrt((1 + kappa) / 2) + sqrt((kappa - 1) / 2)) for kappa > 1, delta
/// sqrt((1 + kappa) / 2) for kappa <= 1, from orthoslip_material_effective: the field at
/// depth y is the surface's at depth beta |y|). Tension is positive. On the punch at y = 0:
/// syy = -p, sxy = q (q: the traction on the solid in +x); at the punch edges themselves
/// (|x| = 1 at the depths that take the surface values) sxx = syy = -INFINITY and
/// sxy = +-INFINITY (0 when mu = 0). Each method's stresses are
/// those of its own tractions (Lekhnistskii's potentials of the half-plane). Near the
/// surface at the punch edge, sxx(x, 0) ~ -k [delta^2 + (1 - nu) mu^2] (1 - |x|)^(-g) with the
/// (k, g) of orthoslip_solution_edge_intensity (GOODMAN: -k delta^2 (1 - |x|)^(-1/2)).
/// A load-path state (`orthoslip_history_solution`): the field of its tractions without
/// symmetry (at x = +-1 on the surface sxy is infinite of the sign of q next to that edge).
/// `x` or `y` may alias an output (in-place evaluation).
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER (any pointer NULL, also when n = 0) or
/// ORTHOSLIP_ERROR_INVALID_ARGUMENT (some x[i] or y[i] NaN or infinite, or y[i] > 0); on
/// failure nothing is written.
///
/// # Safety
/// `s` must be NULL or a live solution; `x` and `y` NULL or valid for n reads; `sxx`, `syy`
/// and `sxy` NULL or valid for n writes each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_solution_stresses(
    s: *const orthoslip_solution,
    x: *const f64,
    y: *const f64,
    n: usize,
    sxx: *mut f64,
    syy: *mut f64,
    sxy: *mut f64,
) -> orthoslip_status {
    run("orthoslip_solution_stresses", || unsafe {
        let sol = deref(s, "s")?;
        for (ptr, name) in [
            (x, "x"),
            (y, "y"),
            (sxx.cast_const(), "sxx"),
            (syy.cast_const(), "syy"),
            (sxy.cast_const(), "sxy"),
        ] {
            deref(ptr, name)?;
        }
        check_finite(x, n, "x")?;
        check_finite(y, n, "y")?;
        if let Some(i) = (0..n).find(|&i| *y.add(i) > 0.0) {
            return Err(Error::InvalidArgument(format!(
                "y[{i}] = {} > 0 is outside the solid (y <= 0)",
                *y.add(i)
            ))
            .into());
        }
        // Raw reads and writes, element by element, so that x and y may alias the outputs.
        for i in 0..n {
            let [a, b, c] = sol.inner.stresses(*x.add(i), *y.add(i))?;
            *sxx.add(i) = a;
            *syy.add(i) = b;
            *sxy.add(i) = c;
        }
        Ok::<(), Failure>(())
    })
}

/// Writes the punch-edge singularity of the solution's pressure, p(x) ~ k (1 - |x|)^(-g) as
/// |x| -> 1, k dimensionless per P/a; on a slip edge q ~ mu p sgn x. g = 1/2 - arctan(bp mu)/pi
/// (GOODMAN, whose p = 1/(pi sqrt(1 - x^2)) ignores the coupling: g = 1/2, k = 1/(pi sqrt 2)).
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (a load-path state from `orthoslip_history_solution`: its two edges have different
/// singularities, which its grid does not resolve); nothing written on failure.
///
/// # Safety
/// `s` must be NULL or a live solution; `k` and `g` NULL or valid for one write each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_solution_edge_intensity(
    s: *const orthoslip_solution,
    k: *mut f64,
    g: *mut f64,
) -> orthoslip_status {
    run("orthoslip_solution_edge_intensity", || unsafe {
        let sol = deref(s, "s")?;
        deref(k.cast_const(), "k")?;
        deref(g.cast_const(), "g")?;
        sol.inner.require_symmetric("the edge intensity")?;
        let (kv, gv) = sol.inner.edge_intensity();
        write_all([(k, "k"), (g, "g")], [kv, gv])
    })
}

/// Evaluates the tangential surface displacement of the solid relative to the punch at n
/// points x[i] (units of a), per P/E (E: the effective modulus of
/// orthoslip_material_effective; P: the normal force per unit thickness). It is 0 on the stick
/// zone and the slip on the slip zones (negative for x > c: the solid slides inward), and odd
/// in x; beyond the punch (|x| > 1) it is the surface displacement relative to the punch.
/// `x` may alias `slip` (in-place evaluation).
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER (any pointer NULL, also when n = 0) or
/// ORTHOSLIP_ERROR_INVALID_ARGUMENT (some x[i] NaN or infinite, or a load-path state from
/// `orthoslip_history_solution`, whose slip depends on its path and not on its tractions
/// alone); on failure nothing is written.
///
/// # Safety
/// `s` must be NULL or a live solution; `x` NULL or valid for n reads; `slip` NULL or valid
/// for n writes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_solution_slip(
    s: *const orthoslip_solution,
    x: *const f64,
    n: usize,
    slip: *mut f64,
) -> orthoslip_status {
    run("orthoslip_solution_slip", || unsafe {
        let sol = deref(s, "s")?;
        deref(x, "x")?;
        deref(slip.cast_const(), "slip")?;
        sol.inner.require_symmetric("the slip function")?;
        check_finite(x, n, "x")?;
        for i in 0..n {
            *slip.add(i) = sol.inner.slip(*x.add(i))?;
        }
        Ok::<(), Failure>(())
    })
}
