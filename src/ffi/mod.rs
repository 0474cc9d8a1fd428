//! The C ABI. Conventions, after rustls-ffi:
//! - every fallible function returns an `orthoslip_status`; out-parameters are written only
//!   on `ORTHOSLIP_OK`, except that a handle out-parameter (`T **out`) is set to NULL first,
//!   so it is NULL after every failure;
//! - a failure also stores a readable message in this thread's last-error slot
//!   (`orthoslip_last_error_message`); nothing else is global or mutable;
//! - no panic unwinds across the boundary: bodies run under `catch_unwind` and a caught panic
//!   becomes `ORTHOSLIP_ERROR_PANIC`, distinct from `ORTHOSLIP_ERROR_INTERNAL` (a failed
//!   internal check reported as an error); recording the message runs under `catch_unwind`
//!   too;
//! - enum values coming from C are read as integers and validated, never trusted.

#![allow(non_camel_case_types)]

mod contact;
mod material;
mod solution;
// after `solution`: its functions come last in the header (the ABI is append-only)
mod field;
// after `field`: the load path and fretting cycles (issue 27)
mod fretting;

use std::any::Any;
use std::cell::RefCell;
use std::ffi::{c_char, c_int};
use std::fmt::Write as _;
use std::panic::{AssertUnwindSafe, catch_unwind};

use crate::contact::Method;
use crate::error::Error;

use material::orthoslip_material;
use solution::orthoslip_solution;

/// Status code returned by every fallible orthoslip function.
#[repr(C)]
#[allow(non_camel_case_types)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum orthoslip_status {
    /// Success: the out-parameters were written.
    ORTHOSLIP_OK = 0,
    /// A required pointer argument was NULL.
    ORTHOSLIP_ERROR_NULL_POINTER = 1,
    /// A number was NaN, infinite, negative or out of range, or an enum value was invalid.
    ORTHOSLIP_ERROR_INVALID_ARGUMENT = 2,
    /// The elastic constants do not give a positive definite in-plane strain energy.
    ORTHOSLIP_ERROR_INADMISSIBLE_MATERIAL = 3,
    /// An iterative method stopped without converging.
    ORTHOSLIP_ERROR_NO_CONVERGENCE = 4,
    /// The method ran, but its error estimate exceeds the requested tolerance.
    ORTHOSLIP_ERROR_TOLERANCE_NOT_MET = 5,
    /// A bug in orthoslip: an internal invariant failed (reported, not panicked).
    ORTHOSLIP_ERROR_INTERNAL = 6,
    /// A bug in orthoslip: a panic was caught at the boundary instead of unwinding into the
    /// caller.
    ORTHOSLIP_ERROR_PANIC = 7,
    /// The solver found the stick-edge root of the assumed form (a central stick zone
    /// |x| < c flanked by two slip zones), but that solution violates an admissibility
    /// condition (p < 0 somewhere in the contact, |q| > mu p on the stick zone, or slip
    /// against the friction): no solution of this form exists for this input. Appended after
    /// PANIC: the values above keep their numbers.
    ORTHOSLIP_ERROR_NO_ADMISSIBLE_SOLUTION = 8,
}

/// Solution method.
#[repr(C)]
#[allow(non_camel_case_types)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum orthoslip_method {
    /// The cheapest method whose error estimate meets the contact's tolerance.
    ORTHOSLIP_METHOD_AUTO = 0,
    /// Goodman's approximation (closed form; neglects the shear traction's effect on p).
    ORTHOSLIP_METHOD_GOODMAN = 1,
    /// Spence's approximation (closed form; keeps the slip-zone edge exponent in p).
    ORTHOSLIP_METHOD_SPENCE = 2,
    /// The high-order solver of the full coupled equations.
    ORTHOSLIP_METHOD_COUPLED = 3,
    /// The paper's linear-complementarity formulation solved by a smoothing Newton method.
    ORTHOSLIP_METHOD_LCP = 4,
}

impl From<Method> for orthoslip_method {
    fn from(m: Method) -> Self {
        match m {
            Method::Auto => Self::ORTHOSLIP_METHOD_AUTO,
            Method::Goodman => Self::ORTHOSLIP_METHOD_GOODMAN,
            Method::Spence => Self::ORTHOSLIP_METHOD_SPENCE,
            Method::Coupled => Self::ORTHOSLIP_METHOD_COUPLED,
            Method::Lcp => Self::ORTHOSLIP_METHOD_LCP,
        }
    }
}

/// An `orthoslip_method` value as received from C: an integer, validated before use
/// (the header shows it as `orthoslip_method`).
#[repr(transparent)]
#[derive(Clone, Copy, Debug)]
pub struct MethodArg(pub c_int);

/// An `orthoslip_status` value as received from C (the header shows it as `orthoslip_status`).
#[repr(transparent)]
#[derive(Clone, Copy, Debug)]
pub struct StatusArg(pub c_int);

/// A failure on its way out through the ABI.
pub(crate) struct Failure {
    status: orthoslip_status,
    message: String,
}

impl From<Error> for Failure {
    fn from(e: Error) -> Self {
        use orthoslip_status::*;
        let status = match e {
            Error::InvalidArgument(_) => ORTHOSLIP_ERROR_INVALID_ARGUMENT,
            Error::InadmissibleMaterial(_) => ORTHOSLIP_ERROR_INADMISSIBLE_MATERIAL,
            Error::NoConvergence(_) => ORTHOSLIP_ERROR_NO_CONVERGENCE,
            Error::ToleranceNotMet { .. } => ORTHOSLIP_ERROR_TOLERANCE_NOT_MET,
            Error::NoAdmissibleSolution(_) => ORTHOSLIP_ERROR_NO_ADMISSIBLE_SOLUTION,
            Error::Internal(_) => ORTHOSLIP_ERROR_INTERNAL,
        };
        Failure {
            status,
            message: e.to_string(),
        }
    }
}

impl Failure {
    fn null(name: &str) -> Self {
        Failure {
            status: orthoslip_status::ORTHOSLIP_ERROR_NULL_POINTER,
            message: format!("null pointer: argument `{name}` must not be NULL"),
        }
    }
}

thread_local! {
    static LAST_ERROR: RefCell<String> = const { RefCell::new(String::new()) };
}

/// Stores `function: message` in this thread's last-error slot. Never panics: a slot that is
/// gone (thread teardown) or borrowed is left as it is.
fn set_last_error(function: &str, message: &str) {
    let _ = LAST_ERROR.try_with(|slot| {
        if let Ok(mut text) = slot.try_borrow_mut() {
            text.clear();
            let _ = write!(text, "{function}: {message}");
        }
    });
}

/// The text of a panic payload (a `&str` or `String` message, else empty).
fn panic_text(payload: &(dyn Any + Send)) -> &str {
    payload
        .downcast_ref::<&str>()
        .copied()
        .or_else(|| payload.downcast_ref::<String>().map(String::as_str))
        .unwrap_or("")
}

/// Runs an ABI body: catches panics, records failures in the last-error slot and turns the
/// outcome into a status. Everything after a failure (formatting and storing the message,
/// dropping a panic payload) also runs under `catch_unwind`; should that panic too, its
/// payload is leaked rather than dropped outside.
pub(crate) fn run(function: &str, body: impl FnOnce() -> Result<(), Failure>) -> orthoslip_status {
    let outcome = catch_unwind(AssertUnwindSafe(body));
    if matches!(outcome, Ok(Ok(()))) {
        return orthoslip_status::ORTHOSLIP_OK;
    }
    catch_unwind(AssertUnwindSafe(move || match outcome {
        Ok(Ok(())) => orthoslip_status::ORTHOSLIP_OK,
        Ok(Err(failure)) => {
            set_last_error(function, &failure.message);
            failure.status
        }
        Err(payload) => {
            let message = format!("panic caught ({})", panic_text(payload.as_ref()));
            set_last_error(function, &message);
            orthoslip_status::ORTHOSLIP_ERROR_PANIC
        }
    }))
    .unwrap_or_else(|payload| {
        std::mem::forget(payload);
        orthoslip_status::ORTHOSLIP_ERROR_PANIC
    })
}

/// A shared reference from a pointer that must not be NULL.
///
/// # Safety
/// `ptr` must be NULL or point to a live `T`.
pub(crate) unsafe fn deref<'a, T>(ptr: *const T, name: &str) -> Result<&'a T, Failure> {
    unsafe { ptr.as_ref() }.ok_or_else(|| Failure::null(name))
}

/// A mutable reference from a pointer that must not be NULL.
///
/// # Safety
/// `ptr` must be NULL or point to a live `T` not aliased elsewhere during the call.
pub(crate) unsafe fn deref_mut<'a, T>(ptr: *mut T, name: &str) -> Result<&'a mut T, Failure> {
    unsafe { ptr.as_mut() }.ok_or_else(|| Failure::null(name))
}

/// Runs a constructor into a handle out-parameter: `*out` is NULL on every failure and the
/// new boxed handle on success.
///
/// # Safety
/// `out` must be NULL or valid for one pointer write.
pub(crate) unsafe fn new_handle<T>(
    function: &str,
    out: *mut *mut T,
    make: impl FnOnce() -> Result<T, Failure>,
) -> orthoslip_status {
    run(function, || {
        if out.is_null() {
            return Err(Failure::null("out"));
        }
        unsafe { *out = std::ptr::null_mut() };
        let handle = Box::into_raw(Box::new(make()?));
        unsafe { *out = handle };
        Ok(())
    })
}

/// Frees a handle made by [`new_handle`]; NULL is a no-op.
///
/// # Safety
/// `ptr` must be NULL or a handle from [`new_handle`] not freed before.
pub(crate) unsafe fn free_handle<T>(ptr: *mut T) {
    if !ptr.is_null() {
        // Dropping plain data cannot panic; the guard is belt and braces.
        let _ = catch_unwind(AssertUnwindSafe(|| drop(unsafe { Box::from_raw(ptr) })));
    }
}

/// Writes values through out-pointers after checking all of them for NULL first, so that
/// nothing is written unless everything can be.
///
/// # Safety
/// Each non-NULL pointer must be valid for one write.
pub(crate) unsafe fn write_all<T: Copy, const N: usize>(
    outs: [(*mut T, &str); N],
    values: [T; N],
) -> Result<(), Failure> {
    if let Some((_, name)) = outs.iter().find(|(p, _)| p.is_null()) {
        return Err(Failure::null(name));
    }
    for ((ptr, _), v) in outs.into_iter().zip(values) {
        unsafe { *ptr = v };
    }
    Ok(())
}

/// Copies this thread's last error message into `buf` and returns its full length in bytes
/// (without the terminating NUL).
///
/// At most `len` bytes are written, always NUL-terminated when `len > 0`, so a message
/// longer than `len - 1` bytes is truncated; call with `buf = NULL, len = 0` to learn the
/// length. The message is the one of the last failed orthoslip call on the calling thread
/// (empty, length 0, if none failed); successful calls leave it unchanged. Never fails.
///
/// # Safety
/// `buf` must be NULL or valid for writing `len` bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_last_error_message(buf: *mut c_char, len: usize) -> usize {
    catch_unwind(|| {
        LAST_ERROR.with(|slot| {
            let msg = slot.borrow();
            if !buf.is_null() && len > 0 {
                let n = msg.len().min(len - 1);
                // SAFETY: the caller provides `len` writable bytes at `buf`.
                unsafe {
                    std::ptr::copy_nonoverlapping(msg.as_ptr(), buf.cast::<u8>(), n);
                    *buf.add(n) = 0;
                }
            }
            msg.len()
        })
    })
    .unwrap_or(0)
}

/// The name of a status code as a static NUL-terminated string, e.g.
/// "ORTHOSLIP_ERROR_NULL_POINTER"; "ORTHOSLIP_STATUS_UNKNOWN" for a value outside the enum.
/// The string is owned by the library and must not be freed.
#[unsafe(no_mangle)]
pub extern "C" fn orthoslip_status_string(status: StatusArg) -> *const c_char {
    let s: &'static std::ffi::CStr = match status.0 {
        0 => c"ORTHOSLIP_OK",
        1 => c"ORTHOSLIP_ERROR_NULL_POINTER",
        2 => c"ORTHOSLIP_ERROR_INVALID_ARGUMENT",
        3 => c"ORTHOSLIP_ERROR_INADMISSIBLE_MATERIAL",
        4 => c"ORTHOSLIP_ERROR_NO_CONVERGENCE",
        5 => c"ORTHOSLIP_ERROR_TOLERANCE_NOT_MET",
        6 => c"ORTHOSLIP_ERROR_INTERNAL",
        7 => c"ORTHOSLIP_ERROR_PANIC",
        8 => c"ORTHOSLIP_ERROR_NO_ADMISSIBLE_SOLUTION",
        _ => c"ORTHOSLIP_STATUS_UNKNOWN",
    };
    s.as_ptr()
}

/// The library version ("MAJOR.MINOR.PATCH") as a static NUL-terminated string owned by the
/// library.
#[unsafe(no_mangle)]
pub extern "C" fn orthoslip_version() -> *const c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn last_error() -> String {
        LAST_ERROR.with(|slot| slot.borrow().clone())
    }

    /// A caught panic and an internal error have their own statuses and messages; success
    /// leaves the message alone.
    #[test]
    fn panics_and_internal_errors_are_told_apart() {
        let status = run("orthoslip_test_panic", || panic!("boom"));
        assert_eq!(status, orthoslip_status::ORTHOSLIP_ERROR_PANIC);
        assert_eq!(last_error(), "orthoslip_test_panic: panic caught (boom)");
        let status = run("orthoslip_test_internal", || {
            Err(Error::Internal("invariant".into()).into())
        });
        assert_eq!(status, orthoslip_status::ORTHOSLIP_ERROR_INTERNAL);
        assert_eq!(
            last_error(),
            "orthoslip_test_internal: internal error: invariant"
        );
        assert_eq!(
            run("orthoslip_test_ok", || Ok(())),
            orthoslip_status::ORTHOSLIP_OK
        );
        assert!(last_error().starts_with("orthoslip_test_internal"));
        let name = unsafe { std::ffi::CStr::from_ptr(orthoslip_status_string(StatusArg(7))) };
        assert_eq!(name.to_str(), Ok("ORTHOSLIP_ERROR_PANIC"));
    }

    /// The ABI is append-only: every status keeps its number and its name, listed here by
    /// hand (not derived from the enum), and values past the last one are unknown.
    #[test]
    fn statuses_keep_their_numbers_and_names() {
        use orthoslip_status::*;
        let table = [
            (ORTHOSLIP_OK, 0, "ORTHOSLIP_OK"),
            (
                ORTHOSLIP_ERROR_NULL_POINTER,
                1,
                "ORTHOSLIP_ERROR_NULL_POINTER",
            ),
            (
                ORTHOSLIP_ERROR_INVALID_ARGUMENT,
                2,
                "ORTHOSLIP_ERROR_INVALID_ARGUMENT",
            ),
            (
                ORTHOSLIP_ERROR_INADMISSIBLE_MATERIAL,
                3,
                "ORTHOSLIP_ERROR_INADMISSIBLE_MATERIAL",
            ),
            (
                ORTHOSLIP_ERROR_NO_CONVERGENCE,
                4,
                "ORTHOSLIP_ERROR_NO_CONVERGENCE",
            ),
            (
                ORTHOSLIP_ERROR_TOLERANCE_NOT_MET,
                5,
                "ORTHOSLIP_ERROR_TOLERANCE_NOT_MET",
            ),
            (ORTHOSLIP_ERROR_INTERNAL, 6, "ORTHOSLIP_ERROR_INTERNAL"),
            (ORTHOSLIP_ERROR_PANIC, 7, "ORTHOSLIP_ERROR_PANIC"),
            (
                ORTHOSLIP_ERROR_NO_ADMISSIBLE_SOLUTION,
                8,
                "ORTHOSLIP_ERROR_NO_ADMISSIBLE_SOLUTION",
            ),
        ];
        let name = |value: c_int| {
            let s = unsafe { std::ffi::CStr::from_ptr(orthoslip_status_string(StatusArg(value))) };
            s.to_str().unwrap().to_owned()
        };
        for (status, value, expected) in table {
            assert_eq!(status as c_int, value, "{expected}");
            assert_eq!(name(value), expected);
        }
        for value in [-1, 9, 99] {
            assert_eq!(name(value), "ORTHOSLIP_STATUS_UNKNOWN");
        }
    }

    /// A solution of the assumed form that is inadmissible has its own status and message.
    #[test]
    fn no_admissible_solution_maps_to_its_status() {
        let status = run("orthoslip_test_inadmissible", || {
            Err(Error::NoAdmissibleSolution("p < 0 near x = 0.99".into()).into())
        });
        assert_eq!(
            status,
            orthoslip_status::ORTHOSLIP_ERROR_NO_ADMISSIBLE_SOLUTION
        );
        assert_eq!(status as c_int, 8);
        assert_eq!(
            last_error(),
            "orthoslip_test_inadmissible: no admissible solution: p < 0 near x = 0.99"
        );
    }

    /// A message cannot be stored while the slot is borrowed: the call still returns its
    /// status, without a panic.
    #[test]
    fn a_busy_slot_does_not_panic() {
        LAST_ERROR.with(|slot| {
            let _held = slot.borrow_mut();
            let status = run("orthoslip_test", || Err(Failure::null("x")));
            assert_eq!(status, orthoslip_status::ORTHOSLIP_ERROR_NULL_POINTER);
        });
    }
}
