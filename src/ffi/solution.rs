//! Solution handles: stick edge, error estimate, method used and tractions.

use super::{Failure, deref, free_handle, orthoslip_method, orthoslip_status, run, write_all};
use crate::contact::Solution;
use crate::error::Error;

/// A solved contact (opaque). Immutable: may be queried from many threads at once.
pub struct orthoslip_solution {
    pub(crate) inner: Solution,
}

/// Releases a solution. NULL is a no-op.
///
/// # Safety
/// `s` must be NULL or a handle from `orthoslip_contact_solve`, not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_solution_free(s: *mut orthoslip_solution) {
    unsafe { free_handle(s) }
}

/// Writes the stick half-width c (0 <= c < 1, units of the punch half-width a): the solid
/// sticks to the punch on |x| < c and slips on c < |x| < 1.
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (a load-path state from `orthoslip_history_solution`: no single c, its stick set is
/// `orthoslip_solution_stick_zone`'s [c1, c2]); nothing written on failure.
///
/// # Safety
/// `s` must be NULL or a live solution; `c` NULL or valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_solution_stick_half_width(
    s: *const orthoslip_solution,
    c: *mut f64,
) -> orthoslip_status {
    run("orthoslip_solution_stick_half_width", || unsafe {
        let sol = &deref(s, "s")?.inner;
        sol.require_symmetric("the stick half-width c")?;
        write_all([(c, "c")], [sol.c()])
    })
}

/// Writes the slip-zone width 1 - c (units of a) with full relative accuracy, also when c is
/// within 1e-9 or less of 1 (it is never computed as 1 - c in floating point).
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (a load-path state from `orthoslip_history_solution`: no single c); nothing written on
/// failure.
///
/// # Safety
/// `s` must be NULL or a live solution; `one_minus_c` NULL or valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_solution_slip_width(
    s: *const orthoslip_solution,
    one_minus_c: *mut f64,
) -> orthoslip_status {
    run("orthoslip_solution_slip_width", || unsafe {
        let sol = &deref(s, "s")?.inner;
        sol.require_symmetric("the slip-zone width 1 - c")?;
        write_all([(one_minus_c, "one_minus_c")], [sol.one_minus_c()])
    })
}

/// Evaluates the tractions at n points: x[i] in units of the punch half-width a; p[i] and
/// q[i] dimensionless per P/a, i.e. sigma_yy(x, 0) = -(P/a) p(x/a) and
/// sigma_xy(x, 0) = (P/a) q(x/a) (paper eq. (6)); int p dx = 1, q is odd and positive for
/// x > c. For |x| > 1, p = q = 0; at |x| = 1 the punch-edge singularity
/// p ~ (1 - |x|)^(-g) is reported as p = +INFINITY, q = +-INFINITY (0 when mu = 0).
/// A load-path state (`orthoslip_history_solution`): p and q without symmetry,
/// int q dx = Q/P, q at x = +-1 infinite of the sign of q next to that edge.
/// `x` may alias `p` or `q` (in-place evaluation).
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER (any pointer NULL, also when n = 0) or
/// ORTHOSLIP_ERROR_INVALID_ARGUMENT (some x[i] NaN or infinite); on failure nothing is
/// written.
///
/// # Safety
/// `s` must be NULL or a live solution; `x` NULL or valid for n reads; `p` and `q` NULL or
/// valid for n writes each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_solution_tractions(
    s: *const orthoslip_solution,
    x: *const f64,
    n: usize,
    p: *mut f64,
    q: *mut f64,
) -> orthoslip_status {
    run("orthoslip_solution_tractions", || unsafe {
        let sol = deref(s, "s")?;
        for (ptr, name) in [(x, "x"), (p.cast_const(), "p"), (q.cast_const(), "q")] {
            deref(ptr, name)?;
        }
        if let Some(i) = (0..n).find(|&i| !(*x.add(i)).is_finite()) {
            return Err(
                Error::InvalidArgument(format!("x[{i}] = {} is not finite", *x.add(i))).into(),
            );
        }
        // Raw reads and writes, element by element, so that x may alias p or q.
        for i in 0..n {
            let (pi, qi) = sol.inner.tractions(*x.add(i));
            *p.add(i) = pi;
            *q.add(i) = qi;
        }
        Ok::<(), Failure>(())
    })
}

/// Writes the method that produced the solution (never ORTHOSLIP_METHOD_AUTO: AUTO reports
/// the method it chose).
///
/// Returns ORTHOSLIP_OK or ORTHOSLIP_ERROR_NULL_POINTER (nothing written).
///
/// # Safety
/// `s` must be NULL or a live solution; `used` NULL or valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_solution_method(
    s: *const orthoslip_solution,
    used: *mut orthoslip_method,
) -> orthoslip_status {
    run("orthoslip_solution_method", || unsafe {
        let m = deref(s, "s")?.inner.method().into();
        write_all([(used, "used")], [m])
    })
}

/// Writes the solution's estimate of |c - c_exact|, c_exact being the stick half-width of
/// the exact coupled problem: discretisation error for COUPLED and LCP; for the
/// approximations GOODMAN and SPENCE an empirical model-error bound (twice the largest error
/// measured by COUPLED at the surrounding points of a table computed offline, plus 1e-10;
/// validated at random points off the table, not certified), +INFINITY where the table gives
/// no bound (outside its range of b* = 0.005 .. 0.99, or where the exact solver failed
/// nearby). Never NaN. A load-path state (`orthoslip_history_solution`): the estimate of
/// the error of its stick set's ends c1, c2 (the larger; +INFINITY if the half-panel grid
/// failed).
///
/// Returns ORTHOSLIP_OK or ORTHOSLIP_ERROR_NULL_POINTER (nothing written).
///
/// # Safety
/// `s` must be NULL or a live solution; `c_error` NULL or valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_solution_error_estimate(
    s: *const orthoslip_solution,
    c_error: *mut f64,
) -> orthoslip_status {
    run("orthoslip_solution_error_estimate", || unsafe {
        let v = deref(s, "s")?.inner.error_estimate();
        write_all([(c_error, "c_error")], [v])
    })
}

/// Writes the solution's estimate of its traction error
/// e_t = int_{-1}^{1} (|p(x) - p_exact(x)| + |q(x) - q_exact(x)|) dx, in units of the normal
/// load P (p and q per P/a, int p dx = 1). No weight is needed: the punch-edge singularities
/// p, |q| ~ (1 - |x|)^(-g), g <= 1/2, are integrable. An integral norm, because a stick edge
/// off by dc moves the shear traction's step at x = c: a pointwise norm would see O(dc^g)
/// there, this one O(mu p(c) dc).
/// COUPLED: from its last two orders; LCP: from its last two grids; GOODMAN and SPENCE: an
/// empirical model-error bound (a table measured offline against COUPLED, validated off its
/// grid, not certified), +INFINITY where the table gives no bound. Never NaN. A load-path
/// state (`orthoslip_history_solution`): `orthoslip_history_traction_error_estimate`'s.
///
/// Returns ORTHOSLIP_OK or ORTHOSLIP_ERROR_NULL_POINTER (nothing written).
///
/// # Safety
/// `s` must be NULL or a live solution; `err` NULL or valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_solution_traction_error_estimate(
    s: *const orthoslip_solution,
    err: *mut f64,
) -> orthoslip_status {
    run("orthoslip_solution_traction_error_estimate", || unsafe {
        let v = deref(s, "s")?.inner.traction_error_estimate();
        write_all([(err, "err")], [v])
    })
}
