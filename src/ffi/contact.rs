//! Contact handles: a material with friction, method and tolerance, and the solve.

use super::{
    MethodArg, deref, deref_mut, free_handle, new_handle, orthoslip_material, orthoslip_solution,
    orthoslip_status, run,
};
use crate::contact::{Contact, Method};
use crate::error::Error;

/// A contact scene (opaque): a copy of the material plus friction coefficient, method and
/// tolerance. `orthoslip_contact_solve` may be called on the same contact from many threads
/// at once; the setters and `orthoslip_contact_free` must not run concurrently with any other
/// use of that contact.
pub struct orthoslip_contact {
    pub(crate) inner: Contact,
}

/// Creates a contact on a copy of material `m`, with friction mu = 0, method
/// ORTHOSLIP_METHOD_AUTO and tolerance 1e-8. `m` may be freed afterwards.
///
/// On success `*out` owns a new handle, to be released with `orthoslip_contact_free`.
/// Returns ORTHOSLIP_OK or ORTHOSLIP_ERROR_NULL_POINTER (`m` or `out` NULL); on failure
/// `*out` is set to NULL.
///
/// # Safety
/// `m` must be NULL or a live material; `out` NULL or valid for writing one pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_contact_new(
    m: *const orthoslip_material,
    out: *mut *mut orthoslip_contact,
) -> orthoslip_status {
    unsafe {
        new_handle("orthoslip_contact_new", out, || {
            Ok(orthoslip_contact {
                inner: Contact::new(deref(m, "m")?.inner),
            })
        })
    }
}

/// Releases a contact. NULL is a no-op. Solutions made from it stay valid.
///
/// # Safety
/// `k` must be NULL or a handle from `orthoslip_contact_new`, not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_contact_free(k: *mut orthoslip_contact) {
    unsafe { free_handle(k) }
}

/// Sets the Coulomb friction coefficient mu (finite, >= 0; mu = 0 is the frictionless limit:
/// c = 0, q = 0).
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (the contact is then unchanged).
///
/// # Safety
/// `k` must be NULL or a live contact not used by another thread during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_contact_set_friction(
    k: *mut orthoslip_contact,
    mu: f64,
) -> orthoslip_status {
    run("orthoslip_contact_set_friction", || unsafe {
        Ok(deref_mut(k, "k")?.inner.set_friction(mu)?)
    })
}

/// Sets the solution method (default ORTHOSLIP_METHOD_AUTO).
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (a value outside `orthoslip_method`; the contact is then unchanged).
///
/// # Safety
/// `k` must be NULL or a live contact not used by another thread during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_contact_set_method(
    k: *mut orthoslip_contact,
    method: MethodArg,
) -> orthoslip_status {
    run("orthoslip_contact_set_method", || unsafe {
        let k = deref_mut(k, "k")?;
        let m = Method::from_code(method.0).ok_or_else(|| {
            Error::InvalidArgument(format!(
                "method = {} is not an orthoslip_method value (0..=4)",
                method.0
            ))
        })?;
        k.inner.set_method(m);
        Ok(())
    })
}

/// Sets the tolerance: the target for |c - c_exact| (finite, 0 < tol < 1; default 1e-8) and,
/// unless `orthoslip_contact_set_traction_tolerance` set it apart, for the traction error of
/// `orthoslip_solution_traction_error_estimate`. ORTHOSLIP_METHOD_AUTO picks the cheapest
/// method whose error estimates meet both; ORTHOSLIP_METHOD_COUPLED and ORTHOSLIP_METHOD_LCP
/// refine until they meet both, to 1e-12 at most (the tolerance floor: below it a solve
/// returns ORTHOSLIP_ERROR_TOLERANCE_NOT_MET naming the floor unless its estimates meet the
/// tolerance anyway); the closed-form approximations (GOODMAN, SPENCE) ignore it and report
/// their model errors in the two estimates.
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (the contact is then unchanged).
///
/// # Safety
/// `k` must be NULL or a live contact not used by another thread during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_contact_set_tolerance(
    k: *mut orthoslip_contact,
    tol: f64,
) -> orthoslip_status {
    run("orthoslip_contact_set_tolerance", || unsafe {
        Ok(deref_mut(k, "k")?.inner.set_tolerance(tol)?)
    })
}

/// Solves the contact: stick half-width c and the tractions p(x), q(x).
///
/// On success `*out` owns a new solution, to be released with `orthoslip_solution_free`.
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER, ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (method not available), ORTHOSLIP_ERROR_NO_CONVERGENCE,
/// ORTHOSLIP_ERROR_TOLERANCE_NOT_MET, ORTHOSLIP_ERROR_NO_ADMISSIBLE_SOLUTION (the root found
/// for c gives an inadmissible solution: no solution of the assumed form exists) or
/// ORTHOSLIP_ERROR_INTERNAL; on failure `*out` is set to NULL. Safe to call on the same
/// contact from many threads at once.
///
/// # Safety
/// `k` must be NULL or a live contact; `out` NULL or valid for writing one pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_contact_solve(
    k: *const orthoslip_contact,
    out: *mut *mut orthoslip_solution,
) -> orthoslip_status {
    unsafe {
        new_handle("orthoslip_contact_solve", out, || {
            Ok(orthoslip_solution {
                inner: deref(k, "k")?.inner.solve()?,
            })
        })
    }
}

/// Sets the traction tolerance: the target for the traction error of
/// `orthoslip_solution_traction_error_estimate` (tol > 0; INFINITY means "tractions not
/// needed": only the tolerance on c counts). Until this is called, the traction tolerance
/// follows `orthoslip_contact_set_tolerance`. ORTHOSLIP_METHOD_AUTO picks the cheapest method
/// meeting both tolerances; COUPLED and LCP refine until both are met; GOODMAN and SPENCE
/// ignore it.
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (tol NaN, zero or negative; the contact is then unchanged).
///
/// # Safety
/// `k` must be NULL or a live contact not used by another thread during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_contact_set_traction_tolerance(
    k: *mut orthoslip_contact,
    tol: f64,
) -> orthoslip_status {
    run("orthoslip_contact_set_traction_tolerance", || unsafe {
        Ok(deref_mut(k, "k")?.inner.set_traction_tolerance(tol)?)
    })
}
