//! A tangential load after the normal load, and fretting cycles (issue 27): load-path
//! handles (`orthoslip_history`), cycle options and cycle results (`orthoslip_cycles`).
//! Units as in `crate::fretting`: x per a; p, q per P/a; displacements and slip amplitudes
//! per P/E; energies per unit thickness in P^2/E; F1 in P^2/(a E), F2 in P^3/(a^2 E).

use std::ffi::c_int;

use super::contact::orthoslip_contact;
use super::solution::orthoslip_solution;
use super::{Failure, deref, deref_mut, free_handle, new_handle, orthoslip_status, run, write_all};
use crate::error::Error;
use crate::fretting::{
    CycleMethod, CycleOptions, CycleResult, CycleState, Fretting, LoadPath, PathPoint, Zone,
};

/// How a load path or a cycle is solved (append-only: new methods get new values).
#[repr(C)]
#[allow(non_camel_case_types)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum orthoslip_cycle_method {
    /// The paper's grid LCP with a loading history: 2n uniform panels on the contact, one
    /// complementarity problem per load step; first order in the panel width and the load
    /// step (docs/theory_tangential.md).
    ORTHOSLIP_CYCLE_METHOD_LCP_HISTORY = 0,
    /// The exact solvers (docs/theory_tangential.md sections 10-15), to the contact's
    /// tolerances: for a load path the normal load, monotonic loading and the branches after
    /// each reversal where they keep one stick set with a slip zone at each end; other loads
    /// are refused with the solver's status and a message (the corner structure of the
    /// ply's unloading above about -0.48 Q* and of its reloading is not built); at bp = 0
    /// with the branches' full-stick ranges. A fretting run follows the cycle's load steps on
    /// that path where it answers every one of them; otherwise it returns the refusal (the
    /// solver's status and a message naming what is not built), never the grid's answer.
    ORTHOSLIP_CYCLE_METHOD_EXACT = 1,
}

/// An `orthoslip_cycle_method` value as received from C: an integer, validated before use.
#[repr(transparent)]
#[derive(Clone, Copy, Debug)]
pub struct CycleMethodArg(pub c_int);

/// How a fretting run ended.
#[repr(C)]
#[allow(non_camel_case_types)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum orthoslip_cycle_state {
    /// The last cycle ends in the state it started from and dissipates nothing (to the
    /// repeat tolerance): every later cycle is elastic.
    ORTHOSLIP_CYCLE_SHAKEDOWN = 0,
    /// The last cycle ends in the state it started from and dissipates energy: every later
    /// cycle is the same.
    ORTHOSLIP_CYCLE_STEADY_SLIP = 1,
    /// No cycle up to the limit repeated its start state.
    ORTHOSLIP_CYCLE_LIMIT_REACHED = 2,
}

impl From<CycleMethod> for orthoslip_cycle_method {
    fn from(m: CycleMethod) -> Self {
        match m {
            CycleMethod::LcpHistory => Self::ORTHOSLIP_CYCLE_METHOD_LCP_HISTORY,
            CycleMethod::Exact => Self::ORTHOSLIP_CYCLE_METHOD_EXACT,
        }
    }
}

impl From<CycleState> for orthoslip_cycle_state {
    fn from(s: CycleState) -> Self {
        match s {
            CycleState::Shakedown => Self::ORTHOSLIP_CYCLE_SHAKEDOWN,
            CycleState::SteadySlip => Self::ORTHOSLIP_CYCLE_STEADY_SLIP,
            CycleState::CycleLimitReached => Self::ORTHOSLIP_CYCLE_LIMIT_REACHED,
        }
    }
}

/// Options of a load path or a fretting run (opaque): method, panels, load steps, repeat
/// tolerance. Immutable once made except through its setters, which need exclusive access.
pub struct orthoslip_cycle_options {
    inner: CycleOptions,
}

/// A load path (opaque): the normal load P, then the tangential load Q moved monotonically
/// from one value to the next by `orthoslip_history_load`. With
/// ORTHOSLIP_CYCLE_METHOD_LCP_HISTORY a grid with half the panels runs alongside for the
/// error estimates; with ORTHOSLIP_CYCLE_METHOD_EXACT the exact solvers' own estimates.
/// The getters may run from many threads at once; `orthoslip_history_load` and
/// `orthoslip_history_free` need exclusive access.
pub struct orthoslip_history {
    inner: LoadPath,
}

/// A fretting run (opaque, immutable): the first loading 0 -> Q* and the cycles
/// Q* -> -Q* -> Q*. May be queried from many threads at once.
pub struct orthoslip_cycles {
    inner: Fretting,
}

/// Points x[i] must be finite and on the contact [-1, 1].
///
/// # Safety
/// `x` must be valid for n reads.
unsafe fn check_points(x: *const f64, n: usize) -> Result<(), Failure> {
    for i in 0..n {
        let v = unsafe { *x.add(i) };
        if !(-1.0..=1.0).contains(&v) {
            return Err(Error::InvalidArgument(format!(
                "x[{i}] = {v} is not on the contact [-1, 1]"
            ))
            .into());
        }
    }
    Ok(())
}

/// Writes the panel values at x[i] of several profiles into as many outputs.
///
/// # Safety
/// `x` must be NULL or valid for n reads; each output NULL or valid for n writes.
unsafe fn sample<const K: usize>(
    x: *const f64,
    n: usize,
    profiles: [&[f64]; K],
    outs: [(*mut f64, &str); K],
) -> Result<(), Failure> {
    unsafe {
        deref(x, "x")?;
        for (ptr, name) in outs {
            deref(ptr.cast_const(), name)?;
        }
        check_points(x, n)?;
        // Raw reads and writes, element by element, so that x may alias an output.
        for i in 0..n {
            let xi = *x.add(i);
            for (profile, (ptr, _)) in profiles.iter().zip(outs) {
                *ptr.add(i) = crate::fretting::panel_value(profile, xi)?;
            }
        }
    }
    Ok(())
}

fn zone_code(z: Zone) -> c_int {
    match z {
        Zone::Stick => 0,
        Zone::SlipPositive => 1,
        Zone::SlipNegative => -1,
    }
}

/// Tractions and zones of a path point at n points.
///
/// # Safety
/// As [`sample`]; `zone` NULL or valid for n writes.
unsafe fn point_tractions(
    pt: &PathPoint,
    x: *const f64,
    n: usize,
    p: *mut f64,
    q: *mut f64,
    zone: *mut c_int,
) -> Result<(), Failure> {
    unsafe {
        deref(zone.cast_const(), "zone")?;
        for (ptr, name) in [(p, "p"), (q, "q")] {
            deref(ptr.cast_const(), name)?;
        }
        deref(x, "x")?;
        check_points(x, n)?;
        let zones: Vec<f64> = pt.zones.iter().map(|z| zone_code(*z) as f64).collect();
        for i in 0..n {
            let xi = *x.add(i);
            let pi = crate::fretting::panel_value(&pt.p, xi)?;
            let qi = crate::fretting::panel_value(&pt.q, xi)?;
            let zi = crate::fretting::panel_value(&zones, xi)? as c_int;
            *p.add(i) = pi;
            *q.add(i) = qi;
            *zone.add(i) = zi;
        }
    }
    Ok(())
}

/// Creates cycle options with the defaults: ORTHOSLIP_CYCLE_METHOD_LCP_HISTORY, 100 panels
/// per half-width, 10 load steps per quarter cycle, repeat tolerance 1e-8.
///
/// On success `*out` owns a new handle, to be released with `orthoslip_cycle_options_free`.
/// Returns ORTHOSLIP_OK or ORTHOSLIP_ERROR_NULL_POINTER; on failure `*out` is set to NULL.
///
/// # Safety
/// `out` must be NULL or valid for writing one pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycle_options_new(
    out: *mut *mut orthoslip_cycle_options,
) -> orthoslip_status {
    unsafe {
        new_handle("orthoslip_cycle_options_new", out, || {
            Ok(orthoslip_cycle_options {
                inner: CycleOptions::default(),
            })
        })
    }
}

/// Releases cycle options. NULL is a no-op.
///
/// # Safety
/// `o` must be NULL or a handle from `orthoslip_cycle_options_new`, not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycle_options_free(o: *mut orthoslip_cycle_options) {
    unsafe { free_handle(o) }
}

/// Applies a change to options if the result is valid; else leaves them unchanged.
///
/// # Safety
/// `o` must be NULL or live options not used by another thread during the call.
unsafe fn set_option(
    function: &str,
    o: *mut orthoslip_cycle_options,
    change: impl FnOnce(&mut CycleOptions) -> Result<(), Failure>,
) -> orthoslip_status {
    run(function, || {
        let o = unsafe { deref_mut(o, "o")? };
        let mut next = o.inner;
        change(&mut next)?;
        next.validate()?;
        o.inner = next;
        Ok(())
    })
}

/// Sets the method (default ORTHOSLIP_CYCLE_METHOD_LCP_HISTORY).
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (a value outside `orthoslip_cycle_method`; the options are then unchanged).
///
/// # Safety
/// `o` must be NULL or live options not used by another thread during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycle_options_set_method(
    o: *mut orthoslip_cycle_options,
    method: CycleMethodArg,
) -> orthoslip_status {
    unsafe {
        set_option("orthoslip_cycle_options_set_method", o, |opt| {
            opt.method = CycleMethod::from_code(method.0).ok_or_else(|| {
                Error::InvalidArgument(format!(
                    "method = {} is not an orthoslip_cycle_method value (0, 1)",
                    method.0
                ))
            })?;
            Ok(())
        })
    }
}

/// Sets the panels per half-width n of ORTHOSLIP_CYCLE_METHOD_LCP_HISTORY (2n on the
/// contact; 8 ..= 2000, default 100). The error estimates come from a second grid with n/2
/// panels; the cost grows like n^3.
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (out of range; the options are then unchanged).
///
/// # Safety
/// `o` must be NULL or live options not used by another thread during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycle_options_set_panels(
    o: *mut orthoslip_cycle_options,
    panels: usize,
) -> orthoslip_status {
    unsafe {
        set_option("orthoslip_cycle_options_set_panels", o, |opt| {
            opt.panels = panels;
            Ok(())
        })
    }
}

/// Sets the load steps per quarter cycle (2 ..= 10000, default 10): the first loading
/// 0 -> Q* takes this many, each half cycle twice as many, each `orthoslip_history_load`
/// this many. The dissipation is first order in the step; its error estimate comes from a
/// run with half the steps.
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (out of range; the options are then unchanged).
///
/// # Safety
/// `o` must be NULL or live options not used by another thread during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycle_options_set_steps(
    o: *mut orthoslip_cycle_options,
    steps: usize,
) -> orthoslip_status {
    unsafe {
        set_option("orthoslip_cycle_options_set_steps", o, |opt| {
            opt.steps = steps;
            Ok(())
        })
    }
}

/// Sets the repeat tolerance (finite, > 0; default 1e-8): a cycle repeats when its end state
/// differs from its start state by at most this in int |q_end - q_start| dx (units of P) and
/// in the punch displacement (units of P/E); a repeating cycle that dissipates at most this
/// (P^2/E) is shakedown, else a steady slip cycle.
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (the options are then unchanged).
///
/// # Safety
/// `o` must be NULL or live options not used by another thread during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycle_options_set_repeat_tolerance(
    o: *mut orthoslip_cycle_options,
    tol: f64,
) -> orthoslip_status {
    unsafe {
        set_option("orthoslip_cycle_options_set_repeat_tolerance", o, |opt| {
            opt.repeat_tolerance = tol;
            Ok(())
        })
    }
}

/// The stick set [c1, c2] of a normal-load solution: c1 = -c, c2 = c; of a load-path state
/// (`orthoslip_history_solution`): its own (as `orthoslip_history_stick_zone`).
///
/// Returns ORTHOSLIP_OK or ORTHOSLIP_ERROR_NULL_POINTER (nothing written).
///
/// # Safety
/// `s` must be NULL or a live solution; `c1`, `c2` NULL or valid for one write each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_solution_stick_zone(
    s: *const orthoslip_solution,
    c1: *mut f64,
    c2: *mut f64,
) -> orthoslip_status {
    run("orthoslip_solution_stick_zone", || unsafe {
        let (a, b) = deref(s, "s")?.inner.stick_set();
        write_all([(c1, "c1"), (c2, "c2")], [a, b])
    })
}

/// The normal-load state (Q = 0) of contact `k` (its material and friction; its method and
/// tolerances are not used: the path is solved by the default cycle options,
/// ORTHOSLIP_CYCLE_METHOD_LCP_HISTORY with 100 panels per half-width and 10 steps per load;
/// with options choosing ORTHOSLIP_CYCLE_METHOD_EXACT, `orthoslip_history_new_with_options`
/// solves to k's tolerances: `orthoslip_contact_set_tolerance` for the stick set's ends,
/// `orthoslip_contact_set_traction_tolerance` for the tractions).
///
/// On success `*out` owns a new handle, to be released with `orthoslip_history_free`.
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER, ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (friction mu = 0: no tangential load can be carried) or ORTHOSLIP_ERROR_NO_CONVERGENCE;
/// on failure `*out` is set to NULL.
///
/// # Safety
/// `k` must be NULL or a live contact; `out` NULL or valid for writing one pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_history_new(
    k: *const orthoslip_contact,
    out: *mut *mut orthoslip_history,
) -> orthoslip_status {
    unsafe {
        new_handle("orthoslip_history_new", out, || {
            let k = deref(k, "k")?;
            Ok(orthoslip_history {
                inner: LoadPath::new(&k.inner, &CycleOptions::default())?,
            })
        })
    }
}

/// As `orthoslip_history_new`, with options `o` (they are copied; `o` may be freed after).
///
/// # Safety
/// `k` and `o` must be NULL or live handles; `out` NULL or valid for writing one pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_history_new_with_options(
    k: *const orthoslip_contact,
    o: *const orthoslip_cycle_options,
    out: *mut *mut orthoslip_history,
) -> orthoslip_status {
    unsafe {
        new_handle("orthoslip_history_new_with_options", out, || {
            let k = deref(k, "k")?;
            let o = deref(o, "o")?;
            Ok(orthoslip_history {
                inner: LoadPath::new(&k.inner, &o.inner)?,
            })
        })
    }
}

/// Releases a load path. NULL is a no-op.
///
/// # Safety
/// `h` must be NULL or a handle from `orthoslip_history_new*`, not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_history_free(h: *mut orthoslip_history) {
    unsafe { free_handle(h) }
}

/// Q moves monotonically from its current value to q_over_p * P (in the options' number of
/// steps; with ORTHOSLIP_CYCLE_METHOD_EXACT one solve of the branch at q_over_p).
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER, ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (q_over_p NaN or infinite, or |q_over_p| >= mu: gross sliding, refused),
/// ORTHOSLIP_ERROR_NO_ADMISSIBLE_SOLUTION (the pressure turns negative somewhere: the punch
/// would lift off, outside this model) or ORTHOSLIP_ERROR_NO_CONVERGENCE. With
/// ORTHOSLIP_CYCLE_METHOD_EXACT a load the exact solvers do not answer returns their status
/// (ORTHOSLIP_ERROR_NO_CONVERGENCE, ORTHOSLIP_ERROR_NO_ADMISSIBLE_SOLUTION: the answer of
/// the built zone pattern slips against its friction, ORTHOSLIP_ERROR_INVALID_ARGUMENT:
/// outside the branch the solver handles, or ORTHOSLIP_ERROR_TOLERANCE_NOT_MET) with a
/// message naming the step and what the exact path covers; ORTHOSLIP_CYCLE_METHOD_LCP_HISTORY
/// answers those paths. On failure the history is unchanged.
///
/// # Safety
/// `h` must be NULL or a live history not used by another thread during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_history_load(
    h: *mut orthoslip_history,
    q_over_p: f64,
) -> orthoslip_status {
    run("orthoslip_history_load", || unsafe {
        Ok(deref_mut(h, "h")?.inner.load(q_over_p)?)
    })
}

/// Writes the current state: Q/P, the punch's tangential displacement u (per P/E, in a fixed
/// gauge, 0 at the normal load: differences along the path are meaningful; the same gauge
/// with ORTHOSLIP_CYCLE_METHOD_EXACT, where u is the rigid displacement of the exact stick
/// set) and the moment the non-rotating punch carries, int x p dx (per P a).
///
/// Returns ORTHOSLIP_OK or ORTHOSLIP_ERROR_NULL_POINTER (nothing written).
///
/// # Safety
/// `h` must be NULL or a live history; the outputs NULL or valid for one write each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_history_state(
    h: *const orthoslip_history,
    q_over_p: *mut f64,
    u: *mut f64,
    moment: *mut f64,
) -> orthoslip_status {
    run("orthoslip_history_state", || unsafe {
        let path = &deref(h, "h")?.inner;
        let pt = path.point();
        write_all(
            [(q_over_p, "q_over_p"), (u, "u"), (moment, "moment")],
            [pt.q_over_p, pt.punch, path.moment()],
        )
    })
}

/// Writes the stick set [c1, c2] of the step that reached the current state (c1 = -1 or
/// c2 = 1 when it reaches a punch edge; NaN when nothing sticks) and the estimate of the
/// ends' error (from the half-panel grid; +INFINITY if that grid failed). With
/// ORTHOSLIP_CYCLE_METHOD_EXACT: the stick set since the current branch began (since the
/// normal load while loading) and the exact solver's estimate of |dc1| + |dc2|.
///
/// Returns ORTHOSLIP_OK or ORTHOSLIP_ERROR_NULL_POINTER (nothing written).
///
/// # Safety
/// `h` must be NULL or a live history; the outputs NULL or valid for one write each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_history_stick_zone(
    h: *const orthoslip_history,
    c1: *mut f64,
    c2: *mut f64,
    err: *mut f64,
) -> orthoslip_status {
    run("orthoslip_history_stick_zone", || unsafe {
        let ((a, b), e) = deref(h, "h")?.inner.stick_zone();
        write_all([(c1, "c1"), (c2, "c2"), (err, "err")], [a, b, e])
    })
}

/// Evaluates the current state at n points x[i] in [-1, 1]: p and q (per P/a; panel values,
/// piecewise constant) and the zone of the step that reached it: 0 stick, +1 the solid
/// slipped in +x relative to the punch (q = -mu p), -1 in -x (q = +mu p). With
/// ORTHOSLIP_CYCLE_METHOD_EXACT: the exact p and q at x (p = +INFINITY at x = +-1, q
/// infinite of its sign there) and the zone since the current branch began. `x` may alias
/// `p` or `q`.
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER (any pointer NULL, also when n = 0) or
/// ORTHOSLIP_ERROR_INVALID_ARGUMENT (some x[i] NaN or outside [-1, 1]; nothing written).
///
/// # Safety
/// `h` must be NULL or a live history; `x` NULL or valid for n reads; the outputs NULL or
/// valid for n writes each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_history_tractions(
    h: *const orthoslip_history,
    x: *const f64,
    n: usize,
    p: *mut f64,
    q: *mut f64,
    zone: *mut c_int,
) -> orthoslip_status {
    run("orthoslip_history_tractions", || unsafe {
        let path = &deref(h, "h")?.inner;
        deref(zone.cast_const(), "zone")?;
        for (ptr, name) in [(p, "p"), (q, "q")] {
            deref(ptr.cast_const(), name)?;
        }
        deref(x, "x")?;
        check_points(x, n)?;
        // Raw reads and writes, point by point, so that x may alias an output.
        for i in 0..n {
            let (pi, qi, zi) = path.tractions_at(*x.add(i))?;
            *p.add(i) = pi;
            *q.add(i) = qi;
            *zone.add(i) = zone_code(zi);
        }
        Ok(())
    })
}

/// Writes the energy dissipated since the normal load (per unit thickness, P^2/E) and an
/// estimate of its error. The grid: backward Euler over its steps, the estimate its grid
/// error. ORTHOSLIP_CYCLE_METHOD_EXACT: the friction work with the mean pressure over each
/// load step the history took (exact when bp = 0, second order in the load step
/// otherwise), the estimate the exact tractions' part. Neither estimate includes the
/// load-step error (the steps are the caller's).
///
/// Returns ORTHOSLIP_OK or ORTHOSLIP_ERROR_NULL_POINTER (nothing written).
///
/// # Safety
/// `h` must be NULL or a live history; the outputs NULL or valid for one write each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_history_dissipated_energy(
    h: *const orthoslip_history,
    w: *mut f64,
    err: *mut f64,
) -> orthoslip_status {
    run("orthoslip_history_dissipated_energy", || unsafe {
        let e = deref(h, "h")?.inner.dissipated()?;
        write_all([(w, "w"), (err, "err")], [e.value, e.error])
    })
}

/// Writes the estimate of the current tractions' error, int (|dp| + |dq|) dx in units of P
/// (against the half-panel grid).
///
/// Returns ORTHOSLIP_OK or ORTHOSLIP_ERROR_NULL_POINTER (nothing written).
///
/// # Safety
/// `h` must be NULL or a live history; `err` NULL or valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_history_traction_error_estimate(
    h: *const orthoslip_history,
    err: *mut f64,
) -> orthoslip_status {
    run("orthoslip_history_traction_error_estimate", || unsafe {
        let e = deref(h, "h")?.inner.traction_error();
        write_all([(err, "err")], [e])
    })
}

/// Q cycled +q_amp P -> -q_amp P -> +q_amp P after the normal load and the first loading
/// 0 -> q_amp P, until a cycle ends in the state it started from or max_cycles cycles are
/// done, with the default cycle options (ORTHOSLIP_CYCLE_METHOD_LCP_HISTORY, 100 panels per
/// half-width, 10 steps per quarter cycle, repeat tolerance 1e-8). Uses k's material and
/// friction (not its method and tolerances).
///
/// On success `*out` owns a new handle, to be released with `orthoslip_cycles_free`.
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER, ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (q_amp not finite or <= 0; q_amp >= mu: gross sliding, refused; mu = 0; max_cycles 0
/// or > 1000), ORTHOSLIP_ERROR_NO_ADMISSIBLE_SOLUTION (the pressure turns negative on the
/// path: lift-off, outside this model) or ORTHOSLIP_ERROR_NO_CONVERGENCE; on failure `*out`
/// is set to NULL.
///
/// # Safety
/// `k` must be NULL or a live contact; `out` NULL or valid for writing one pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_contact_solve_cycles(
    k: *const orthoslip_contact,
    q_amp_over_p: f64,
    max_cycles: usize,
    out: *mut *mut orthoslip_cycles,
) -> orthoslip_status {
    unsafe {
        new_handle("orthoslip_contact_solve_cycles", out, || {
            solve_cycles(k, &CycleOptions::default(), q_amp_over_p, max_cycles)
        })
    }
}

/// As `orthoslip_contact_solve_cycles`, with options `o`. With
/// ORTHOSLIP_CYCLE_METHOD_EXACT the cycle's load steps are taken on the exact load path
/// (profiles are its values at the grid's panel midpoints); a load it does not answer (the
/// corner structure at bp > 0, not built) returns its status (ORTHOSLIP_ERROR_NO_CONVERGENCE,
/// _NO_ADMISSIBLE_SOLUTION, ...) and a message naming the cycle, the step and what is not
/// built.
///
/// # Safety
/// `k` and `o` must be NULL or live handles; `out` NULL or valid for writing one pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_contact_solve_cycles_with_options(
    k: *const orthoslip_contact,
    o: *const orthoslip_cycle_options,
    q_amp_over_p: f64,
    max_cycles: usize,
    out: *mut *mut orthoslip_cycles,
) -> orthoslip_status {
    unsafe {
        new_handle("orthoslip_contact_solve_cycles_with_options", out, || {
            let o = deref(o, "o")?;
            solve_cycles(k, &o.inner, q_amp_over_p, max_cycles)
        })
    }
}

/// # Safety
/// `k` must be NULL or a live contact.
unsafe fn solve_cycles(
    k: *const orthoslip_contact,
    o: &CycleOptions,
    q_amp_over_p: f64,
    max_cycles: usize,
) -> Result<orthoslip_cycles, Failure> {
    let k = unsafe { deref(k, "k")? };
    let opt = CycleOptions { max_cycles, ..*o };
    Ok(orthoslip_cycles {
        inner: Fretting::solve(&k.inner, q_amp_over_p, &opt)?,
    })
}

/// Releases a fretting run. NULL is a no-op.
///
/// # Safety
/// `cy` must be NULL or a handle from `orthoslip_contact_solve_cycles*`, not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_free(cy: *mut orthoslip_cycles) {
    unsafe { free_handle(cy) }
}

/// The cycle with index `cycle` (0 = the first full cycle).
fn cycle_at(cy: &orthoslip_cycles, cycle: usize) -> Result<&CycleResult, Failure> {
    let n = cy.inner.cycles.len();
    cy.inner.cycles.get(cycle).ok_or_else(|| {
        Error::InvalidArgument(format!("cycle = {cycle} is not below the count {n}")).into()
    })
}

/// Writes the number of cycles computed and whether the last one ends in the state it
/// started from (1: shakedown or a steady slip cycle; 0: the cycle limit was reached).
///
/// Returns ORTHOSLIP_OK or ORTHOSLIP_ERROR_NULL_POINTER (nothing written).
///
/// # Safety
/// `cy` must be NULL or a live handle; `n`, `steady` NULL or valid for one write each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_count(
    cy: *const orthoslip_cycles,
    n: *mut usize,
    steady: *mut c_int,
) -> orthoslip_status {
    run("orthoslip_cycles_count", || unsafe {
        let f = &deref(cy, "cy")?.inner;
        deref(steady.cast_const(), "steady")?;
        write_all([(n, "n")], [f.cycles.len()])?;
        write_all([(steady, "steady")], [c_int::from(f.steady())])
    })
}

/// Writes the method that computed the run.
///
/// Returns ORTHOSLIP_OK or ORTHOSLIP_ERROR_NULL_POINTER (nothing written).
///
/// # Safety
/// `cy` must be NULL or a live handle; `used` NULL or valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_method(
    cy: *const orthoslip_cycles,
    used: *mut orthoslip_cycle_method,
) -> orthoslip_status {
    run("orthoslip_cycles_method", || unsafe {
        let m = deref(cy, "cy")?.inner.method.into();
        write_all([(used, "used")], [m])
    })
}

/// Writes how the run ended: shakedown, a steady slip cycle, or the cycle limit.
///
/// Returns ORTHOSLIP_OK or ORTHOSLIP_ERROR_NULL_POINTER (nothing written).
///
/// # Safety
/// `cy` must be NULL or a live handle; `state` NULL or valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_state(
    cy: *const orthoslip_cycles,
    state: *mut orthoslip_cycle_state,
) -> orthoslip_status {
    run("orthoslip_cycles_state", || unsafe {
        let s = deref(cy, "cy")?.inner.state.into();
        write_all([(state, "state")], [s])
    })
}

/// Writes the energy dissipated in cycle `cycle` (0-based), int mu p |slip increment| dx
/// summed over its steps, per unit thickness in P^2/E (docs/theory_tangential.md (T8)).
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (cycle >= count); nothing written on failure.
///
/// # Safety
/// `cy` must be NULL or a live handle; `w` NULL or valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_dissipated_energy(
    cy: *const orthoslip_cycles,
    cycle: usize,
    w: *mut f64,
) -> orthoslip_status {
    run("orthoslip_cycles_dissipated_energy", || unsafe {
        let c = cycle_at(deref(cy, "cy")?, cycle)?;
        write_all([(w, "w")], [c.dissipation.value])
    })
}

/// Writes the estimate of the error of `orthoslip_cycles_dissipated_energy` (P^2/E): twice
/// the sum of the differences from a run with half the panels and one with half the steps.
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (cycle >= count); nothing written on failure.
///
/// # Safety
/// `cy` must be NULL or a live handle; `err` NULL or valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_dissipated_energy_error(
    cy: *const orthoslip_cycles,
    cycle: usize,
    err: *mut f64,
) -> orthoslip_status {
    run("orthoslip_cycles_dissipated_energy_error", || unsafe {
        let c = cycle_at(deref(cy, "cy")?, cycle)?;
        write_all([(err, "err")], [c.dissipation.error])
    })
}

/// Writes the energy dissipated in the first loading 0 -> Q* (P^2/E) and its error estimate.
///
/// Returns ORTHOSLIP_OK or ORTHOSLIP_ERROR_NULL_POINTER (nothing written).
///
/// # Safety
/// `cy` must be NULL or a live handle; `w`, `err` NULL or valid for one write each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_first_loading_energy(
    cy: *const orthoslip_cycles,
    w: *mut f64,
    err: *mut f64,
) -> orthoslip_status {
    run("orthoslip_cycles_first_loading_energy", || unsafe {
        let e = deref(cy, "cy")?.inner.first_loading_dissipation;
        write_all([(w, "w"), (err, "err")], [e.value, e.error])
    })
}

/// Evaluates the slip amplitude of cycle `cycle` at n points x[i] in [-1, 1]: half the
/// peak-to-peak relative tangential displacement of solid and punch over the cycle, per P/E
/// (panel values; 0 where the panel stuck throughout the cycle). `x` may alias `amp`.
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER (any pointer NULL, also when n = 0) or
/// ORTHOSLIP_ERROR_INVALID_ARGUMENT (cycle >= count, some x[i] NaN or outside [-1, 1]);
/// nothing written on failure.
///
/// # Safety
/// `cy` must be NULL or a live handle; `x` NULL or valid for n reads; `amp` NULL or valid
/// for n writes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_slip_amplitude(
    cy: *const orthoslip_cycles,
    cycle: usize,
    x: *const f64,
    n: usize,
    amp: *mut f64,
) -> orthoslip_status {
    run("orthoslip_cycles_slip_amplitude", || unsafe {
        let handle = deref(cy, "cy")?;
        let c = cycle_at(handle, cycle)?;
        sample(x, n, [&c.slip_amplitude], [(amp, "amp")])
    })
}

/// Writes the error estimate of the slip amplitude of cycle `cycle`: the largest over the
/// panels (P/E).
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (cycle >= count); nothing written on failure.
///
/// # Safety
/// `cy` must be NULL or a live handle; `err` NULL or valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_slip_amplitude_error(
    cy: *const orthoslip_cycles,
    cycle: usize,
    err: *mut f64,
) -> orthoslip_status {
    run("orthoslip_cycles_slip_amplitude_error", || unsafe {
        let c = cycle_at(deref(cy, "cy")?, cycle)?;
        write_all([(err, "err")], [c.slip_amplitude_error])
    })
}

/// Evaluates Ruiz's fretting parameters of cycle `cycle` at n points x[i] in [-1, 1]:
/// F1 = tau_max * delta (P^2/(a E)) and F2 = max(sigma_xx,max, 0) * tau_max * delta
/// (P^3/(a^2 E)), with tau_max the largest |q| over the cycle (P/a), sigma_xx,max the
/// largest surface sigma_xx(x, 0) over the cycle (P/a, tension positive) and delta the slip
/// amplitude (P/E); panel values. `x` may alias `f1` or `f2`.
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER (any pointer NULL, also when n = 0) or
/// ORTHOSLIP_ERROR_INVALID_ARGUMENT (cycle >= count, some x[i] NaN or outside [-1, 1]);
/// nothing written on failure.
///
/// # Safety
/// `cy` must be NULL or a live handle; `x` NULL or valid for n reads; `f1`, `f2` NULL or
/// valid for n writes each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_ruiz(
    cy: *const orthoslip_cycles,
    cycle: usize,
    x: *const f64,
    n: usize,
    f1: *mut f64,
    f2: *mut f64,
) -> orthoslip_status {
    run("orthoslip_cycles_ruiz", || unsafe {
        let handle = deref(cy, "cy")?;
        let c = cycle_at(handle, cycle)?;
        sample(x, n, [&c.f1, &c.f2], [(f1, "f1"), (f2, "f2")])
    })
}

/// Evaluates tau_max (the largest |q| over the cycle, P/a) and sigma_xx,max (the largest
/// surface sigma_xx(x, 0) over the cycle, P/a, tension positive) of cycle `cycle` at n
/// points x[i] in [-1, 1] (panel values), the factors of `orthoslip_cycles_ruiz`.
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER (any pointer NULL, also when n = 0) or
/// ORTHOSLIP_ERROR_INVALID_ARGUMENT (cycle >= count, some x[i] NaN or outside [-1, 1]);
/// nothing written on failure.
///
/// # Safety
/// `cy` must be NULL or a live handle; `x` NULL or valid for n reads; `tau_max`, `sxx_max`
/// NULL or valid for n writes each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_stress_peaks(
    cy: *const orthoslip_cycles,
    cycle: usize,
    x: *const f64,
    n: usize,
    tau_max: *mut f64,
    sxx_max: *mut f64,
) -> orthoslip_status {
    run("orthoslip_cycles_stress_peaks", || unsafe {
        let handle = deref(cy, "cy")?;
        let c = cycle_at(handle, cycle)?;
        sample(
            x,
            n,
            [&c.tau_max, &c.sxx_max],
            [(tau_max, "tau_max"), (sxx_max, "sxx_max")],
        )
    })
}

/// Writes the peaks of F1 and F2 along the contact in cycle `cycle` and where they are (a
/// panel midpoint; NaN where the parameter vanishes everywhere, e.g. a cycle without slip),
/// with the error estimates of the four values (P^2/(a E), P^3/(a^2 E), a). At a slipping
/// punch edge tau_max grows like the edge singularity as the panels shrink: read the
/// estimate before the peak.
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (cycle >= count); nothing written on failure.
///
/// # Safety
/// `cy` must be NULL or a live handle; `f1_max`, `x_f1`, `f2_max`, `x_f2` NULL or valid for
/// one write each; `err` NULL or valid for 4 writes (F1, its x, F2, its x).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_ruiz_peaks(
    cy: *const orthoslip_cycles,
    cycle: usize,
    f1_max: *mut f64,
    x_f1: *mut f64,
    f2_max: *mut f64,
    x_f2: *mut f64,
    err: *mut f64,
) -> orthoslip_status {
    run("orthoslip_cycles_ruiz_peaks", || unsafe {
        let c = cycle_at(deref(cy, "cy")?, cycle)?;
        deref(err.cast_const(), "err")?;
        let (a, b) = (c.f1_peak, c.f2_peak);
        write_all(
            [
                (f1_max, "f1_max"),
                (x_f1, "x_f1"),
                (f2_max, "f2_max"),
                (x_f2, "x_f2"),
            ],
            [a.value, a.x, b.value, b.x],
        )?;
        for (i, e) in [a.error, a.x_error, b.error, b.x_error]
            .into_iter()
            .enumerate()
        {
            *err.add(i) = e;
        }
        Ok(())
    })
}

/// Writes the stick sets of cycle `cycle` at Q = -Q* (its middle) and Q = +Q* (its end),
/// [c1, c2] each (+-1 at a punch edge; NaN when nothing sticks), and the estimate of the
/// four ends' error (the largest).
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (cycle >= count); nothing written on failure.
///
/// # Safety
/// `cy` must be NULL or a live handle; the outputs NULL or valid for one write each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_stick_zones(
    cy: *const orthoslip_cycles,
    cycle: usize,
    c1_minus: *mut f64,
    c2_minus: *mut f64,
    c1_plus: *mut f64,
    c2_plus: *mut f64,
    err: *mut f64,
) -> orthoslip_status {
    run("orthoslip_cycles_stick_zones", || unsafe {
        let c = cycle_at(deref(cy, "cy")?, cycle)?;
        write_all(
            [
                (c1_minus, "c1_minus"),
                (c2_minus, "c2_minus"),
                (c1_plus, "c1_plus"),
                (c2_plus, "c2_plus"),
                (err, "err"),
            ],
            [
                c.stick_at_minus.0,
                c.stick_at_minus.1,
                c.stick_at_plus.0,
                c.stick_at_plus.1,
                c.stick_error,
            ],
        )
    })
}

/// Writes the number of points of cycle `cycle`'s Q-displacement loop: its start and the
/// state after each load step (4 * steps + 1).
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (cycle >= count); nothing written on failure.
///
/// # Safety
/// `cy` must be NULL or a live handle; `len` NULL or valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_loop_length(
    cy: *const orthoslip_cycles,
    cycle: usize,
    len: *mut usize,
) -> orthoslip_status {
    run("orthoslip_cycles_loop_length", || unsafe {
        let c = cycle_at(deref(cy, "cy")?, cycle)?;
        write_all([(len, "len")], [c.loop_points.len()])
    })
}

/// Writes cycle `cycle`'s Q-displacement loop: Q/P and the punch's tangential displacement
/// u (per P/E, fixed gauge) at its start and after each step; `len` must equal
/// `orthoslip_cycles_loop_length`. The loop's area (trapezoidal) is the work of Q over the
/// cycle (see `orthoslip_cycles_energy_balance`).
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (cycle >= count, len not the loop length); nothing written on failure.
///
/// # Safety
/// `cy` must be NULL or a live handle; `q_over_p` and `u` NULL or valid for len writes each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_loop(
    cy: *const orthoslip_cycles,
    cycle: usize,
    len: usize,
    q_over_p: *mut f64,
    u: *mut f64,
) -> orthoslip_status {
    run("orthoslip_cycles_loop", || unsafe {
        let c = cycle_at(deref(cy, "cy")?, cycle)?;
        deref(q_over_p.cast_const(), "q_over_p")?;
        deref(u.cast_const(), "u")?;
        let pts = &c.loop_points;
        if len != pts.len() {
            return Err(Error::InvalidArgument(format!(
                "len = {len} is not the loop length {}",
                pts.len()
            ))
            .into());
        }
        for (i, &(q, d)) in pts.iter().enumerate() {
            *q_over_p.add(i) = q;
            *u.add(i) = d;
        }
        Ok(())
    })
}

/// Writes cycle `cycle`'s energy balance (P^2/E per unit thickness; docs/theory_tangential.md
/// (T9)): the work of Q (the loop's area), the work of P through the normal displacement
/// (p changes with Q when bp > 0), the change of the elastic energy, and the residual
/// loop + normal - (dissipation with mid-step tractions + change), zero up to rounding (NaN
/// when bp = 0, where the operator is not symmetric). When a cycle ends where it started the
/// loop's area is its dissipation.
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (cycle >= count); nothing written on failure.
///
/// # Safety
/// `cy` must be NULL or a live handle; the outputs NULL or valid for one write each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_energy_balance(
    cy: *const orthoslip_cycles,
    cycle: usize,
    loop_work: *mut f64,
    normal_work: *mut f64,
    energy_change: *mut f64,
    residual: *mut f64,
) -> orthoslip_status {
    run("orthoslip_cycles_energy_balance", || unsafe {
        let c = cycle_at(deref(cy, "cy")?, cycle)?;
        write_all(
            [
                (loop_work, "loop_work"),
                (normal_work, "normal_work"),
                (energy_change, "energy_change"),
                (residual, "residual"),
            ],
            [
                c.loop_work,
                c.normal_work,
                c.energy_change,
                c.balance_residual,
            ],
        )
    })
}

/// The state after step `step` (0-based, < 4 * steps) of cycle `cycle`.
fn step_at(cy: &orthoslip_cycles, cycle: usize, step: usize) -> Result<&PathPoint, Failure> {
    let c = cycle_at(cy, cycle)?;
    let n = c.path.len();
    c.path.get(step).ok_or_else(|| {
        Error::InvalidArgument(format!(
            "step = {step} is not below the steps per cycle {n}"
        ))
        .into()
    })
}

/// Writes Q/P, the punch displacement u (P/E) and the stick set [c1, c2] after step `step`
/// (0-based; a cycle has loop length - 1 steps, the first half unloading to -Q*) of cycle
/// `cycle`.
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (cycle or step out of range); nothing written on failure.
///
/// # Safety
/// `cy` must be NULL or a live handle; the outputs NULL or valid for one write each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_step(
    cy: *const orthoslip_cycles,
    cycle: usize,
    step: usize,
    q_over_p: *mut f64,
    u: *mut f64,
    c1: *mut f64,
    c2: *mut f64,
) -> orthoslip_status {
    run("orthoslip_cycles_step", || unsafe {
        let pt = step_at(deref(cy, "cy")?, cycle, step)?;
        write_all(
            [(q_over_p, "q_over_p"), (u, "u"), (c1, "c1"), (c2, "c2")],
            [pt.q_over_p, pt.punch, pt.stick.0, pt.stick.1],
        )
    })
}

/// Evaluates the state after step `step` of cycle `cycle` at n points x[i] in [-1, 1]: p, q
/// (P/a) and the zone of the step (0 stick, +1 the solid slipped in +x relative to the punch,
/// -1 in -x), as `orthoslip_history_tractions`.
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER (any pointer NULL, also when n = 0) or
/// ORTHOSLIP_ERROR_INVALID_ARGUMENT (cycle or step out of range, some x[i] NaN or outside
/// [-1, 1]); nothing written on failure.
///
/// # Safety
/// `cy` must be NULL or a live handle; `x` NULL or valid for n reads; the outputs NULL or
/// valid for n writes each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_step_tractions(
    cy: *const orthoslip_cycles,
    cycle: usize,
    step: usize,
    x: *const f64,
    n: usize,
    p: *mut f64,
    q: *mut f64,
    zone: *mut c_int,
) -> orthoslip_status {
    run("orthoslip_cycles_step_tractions", || unsafe {
        let handle = deref(cy, "cy")?;
        let pt = step_at(handle, cycle, step)?;
        point_tractions(pt, x, n, p, q, zone)
    })
}

/// Writes the error estimates of cycle `cycle`'s loop: of the punch displacement u at its
/// turning points -Q* and +Q* (the larger, per P/E) and of its area, the work of Q (P^2/E).
///
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER or ORTHOSLIP_ERROR_INVALID_ARGUMENT
/// (cycle >= count); nothing written on failure.
///
/// # Safety
/// `cy` must be NULL or a live handle; `u_err` and `work_err` NULL or valid for one write
/// each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_cycles_loop_error(
    cy: *const orthoslip_cycles,
    cycle: usize,
    u_err: *mut f64,
    work_err: *mut f64,
) -> orthoslip_status {
    run("orthoslip_cycles_loop_error", || unsafe {
        let c = cycle_at(deref(cy, "cy")?, cycle)?;
        write_all(
            [(u_err, "u_err"), (work_err, "work_err")],
            [c.loop_error, c.loop_work_error],
        )
    })
}

/// The current state as a solution: tractions, stresses, slip and estimates through the
/// existing getters (`orthoslip_solution_*`; method ORTHOSLIP_METHOD_LCP, and
/// ORTHOSLIP_METHOD_COUPLED for ORTHOSLIP_CYCLE_METHOD_EXACT, whose exact tractions it
/// carries at any x, the stresses from them fitted on panels graded towards every zone end).
/// The state is copied: `h` may be loaded further or freed, the solution keeps this state.
/// - `orthoslip_solution_tractions`: p and q on [-1, 1] without symmetry, the grid's panel
///   values presented as the normal-load LCP solution presents its own (regular parts
///   p / w, q / w linear between the midpoints, w = (1 - |x|)^(-g) with the normal-load edge
///   exponent g); at Q = 0 they are the normal-load LCP solution's on the same grid.
/// - `orthoslip_solution_stresses`: the field of these tractions (no symmetry assumed).
/// - `orthoslip_solution_stick_zone`: the stick set [c1, c2] (NaN when nothing sticks);
///   `orthoslip_solution_error_estimate`: its ends' error estimate;
///   `orthoslip_solution_traction_error_estimate`: the history's traction error estimate.
/// - Refused with ORTHOSLIP_ERROR_INVALID_ARGUMENT (no single value describes an asymmetric
///   state): `orthoslip_solution_stick_half_width`, `orthoslip_solution_slip_width`,
///   `orthoslip_solution_edge_intensity` (the two edges differ) and
///   `orthoslip_solution_slip` (a state's slip depends on its load path, not on its
///   tractions alone; the history's slip increments are in `orthoslip_history_tractions`'
///   zones).
///
/// On success `*out` owns a new handle, to be released with `orthoslip_solution_free`.
/// Returns ORTHOSLIP_OK or ORTHOSLIP_ERROR_NULL_POINTER; on failure `*out` is set to NULL.
///
/// # Safety
/// `h` must be NULL or a live history; `out` NULL or valid for writing one pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_history_solution(
    h: *const orthoslip_history,
    out: *mut *mut orthoslip_solution,
) -> orthoslip_status {
    unsafe {
        new_handle("orthoslip_history_solution", out, || {
            let h = deref(h, "h")?;
            Ok(orthoslip_solution {
                inner: h.inner.solution(),
            })
        })
    }
}
