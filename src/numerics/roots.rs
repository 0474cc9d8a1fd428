//! Brent's bracketing root finder (R. P. Brent, Algorithms for Minimization without
//! Derivatives, 1973, ch. 4: inverse quadratic interpolation, secant and bisection steps),
//! shared by the solvers.

use crate::error::{Error, Result};

/// The secant method's root of f from a and b (at most 40 steps, until the step's ends are
/// within 1e-14 or f does not move): the tests' root of a closed-form reference, independent
/// of [`brent`], which the solvers use.
#[cfg(test)]
pub(crate) fn secant(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let (mut fa, mut fb) = (f(a), f(b));
    for _ in 0..40 {
        if fb == fa || (b - a).abs() < 1e-14 {
            break;
        }
        let next = b - fb * (b - a) / (fb - fa);
        (a, fa) = (b, fb);
        b = next;
        fb = f(b);
    }
    b
}

/// A root of f in the bracket [a, b], where fa = f(a) and fb = f(b) have opposite signs,
/// located to within `xtol` + 2 eps |x|. f may fail; its error is passed on. Returns the
/// bracket end with the smaller |f| once the bracket is that narrow (or f vanishes there);
/// `Error::NoConvergence` after `max_iter` steps.
pub(crate) fn brent(
    mut f: impl FnMut(f64) -> Result<f64>,
    (mut a, mut fa): (f64, f64),
    (mut b, mut fb): (f64, f64),
    xtol: f64,
    max_iter: usize,
) -> Result<f64> {
    let (mut c, mut fc) = (a, fa);
    let (mut d, mut e) = (b - a, b - a);
    for _ in 0..max_iter {
        if fb.signum() == fc.signum() {
            (c, fc) = (a, fa);
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            (a, fa, b, fb, c, fc) = (b, fb, c, fc, b, fb);
        }
        let tol = xtol + 2.0 * f64::EPSILON * b.abs();
        let m = 0.5 * (c - b);
        if m.abs() <= tol || fb == 0.0 {
            return Ok(b);
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q) = if a == c {
                (2.0 * m * s, 1.0 - s)
            } else {
                let (qa, r) = (fa / fc, fb / fc);
                (
                    s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0)),
                    (qa - 1.0) * (r - 1.0) * (s - 1.0),
                )
            };
            if p > 0.0 {
                q = -q;
            }
            p = p.abs();
            if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        (a, fa) = (b, fb);
        b += if d.abs() > tol { d } else { tol.copysign(m) };
        fb = f(b)?;
    }
    Err(Error::NoConvergence(format!(
        "Brent's method did not bracket the root within {max_iter} steps"
    )))
}

/// A 2 x 2 Jacobian, row i the derivatives of the i-th function.
pub(crate) type Jacobian2 = [[f64; 2]; 2];

/// The chord method for two functions of two unknowns: [`chord`] with N = 2.
#[allow(clippy::too_many_arguments)]
pub(crate) fn chord2<S>(
    x0: [f64; 2],
    h: [f64; 2],
    tol: f64,
    max_steps: usize,
    jac: &mut Option<Jacobian2>,
    solve: impl FnMut([f64; 2]) -> crate::error::Result<S>,
    value: impl Fn(&S) -> [f64; 2],
    advance: impl FnMut([f64; 2], [f64; 2]) -> crate::error::Result<([f64; 2], f64)>,
) -> crate::error::Result<([f64; 2], S, f64)> {
    chord(x0, h, tol, max_steps, jac, solve, value, advance)
}

/// The Newton step -J^-1 f: Cramer's rule for N = 2, Gaussian elimination with partial
/// pivoting otherwise; None for a singular or non-finite J.
fn newton_step<const N: usize>(j: &[[f64; N]; N], f: &[f64; N]) -> Option<[f64; N]> {
    let mut dx = [0.0; N];
    if N == 2 {
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        dx[0] = -(j[1][1] * f[0] - j[0][1] * f[1]) / det;
        dx[1] = -(-j[1][0] * f[0] + j[0][0] * f[1]) / det;
        return Some(dx);
    }
    let (mut a, mut b) = (*j, *f);
    for c in 0..N {
        let piv = (c..N).max_by(|&r, &s| a[r][c].abs().total_cmp(&a[s][c].abs()))?;
        a.swap(c, piv);
        b.swap(c, piv);
        if a[c][c] == 0.0 || !a[c][c].is_finite() {
            return None;
        }
        for r in c + 1..N {
            let m = a[r][c] / a[c][c];
            let pivot = a[c];
            for (v, p) in a[r][c..].iter_mut().zip(&pivot[c..]) {
                *v -= m * p;
            }
            b[r] -= m * b[c];
        }
    }
    // J y = f by back substitution, then dx = -y
    for c in (0..N).rev() {
        let s: f64 = (c + 1..N).map(|k| a[c][k] * dx[k]).sum();
        dx[c] = (b[c] - s) / a[c][c];
    }
    for v in &mut dx {
        *v = -*v;
    }
    dx.iter().all(|v| v.is_finite()).then_some(dx)
}

/// The chord method for N functions of N unknowns, f(x) = 0, whose evaluation is a whole
/// solve `solve(x)` giving a state S with f = `value(&S)`:
/// - the Jacobian by forward differences with steps `h`, kept in `jac` across calls (a
///   family of like problems) and taken afresh when a step no longer halves the one before
///   (stale, or the functions' rounding reached: then the search stops once a fresh
///   Jacobian's step does not halve either);
/// - each Newton step dx handed to `advance(x, dx)`, which damps, projects and checks it
///   and returns the next x with the size of the move that measures convergence;
/// - stops when that size is at most `tol`, or after `max_steps` steps.
///
/// Returns the last x, its state and the last move's size. Errors: those of `solve` and
/// `advance`, and `NoConvergence` for a singular or non-finite Jacobian.
#[allow(clippy::too_many_arguments)]
pub(crate) fn chord<S, const N: usize>(
    x0: [f64; N],
    h: [f64; N],
    tol: f64,
    max_steps: usize,
    jac: &mut Option<[[f64; N]; N]>,
    mut solve: impl FnMut([f64; N]) -> crate::error::Result<S>,
    value: impl Fn(&S) -> [f64; N],
    mut advance: impl FnMut([f64; N], [f64; N]) -> crate::error::Result<([f64; N], f64)>,
) -> crate::error::Result<([f64; N], S, f64)> {
    let mut x = x0;
    let mut s = solve(x)?;
    let mut step = f64::INFINITY;
    let mut fresh = false;
    for _ in 0..max_steps {
        let f = value(&s);
        if jac.is_none() {
            let mut j = [[0.0; N]; N];
            for c in 0..N {
                let mut y = x;
                y[c] += h[c];
                let fc = value(&solve(y)?);
                for r in 0..N {
                    j[r][c] = (fc[r] - f[r]) / h[c];
                }
            }
            *jac = Some(j);
            fresh = true;
        }
        let dx = jac
            .as_ref()
            .and_then(|j| newton_step(j, &f))
            .ok_or_else(|| {
                crate::error::Error::NoConvergence("chord method: singular Jacobian".to_string())
            })?;
        let (next, last) = advance(x, dx)?;
        x = next;
        s = solve(x)?;
        let stalled = last > 0.5 * step;
        step = last;
        if step <= tol {
            break;
        }
        if stalled {
            if fresh {
                break;
            }
            *jac = None;
        }
        fresh = false;
    }
    Ok((x, s, step))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_roots_to_the_requested_width() {
        // cos x = x (the Dottie number), a cubic with a root at 2, and a steep exponential.
        let dottie = 0.739_085_133_215_160_6;
        let x = brent(
            |x| Ok(x.cos() - x),
            (0.0, 1.0),
            (1.0, 1f64.cos() - 1.0),
            0.0,
            100,
        )
        .unwrap();
        assert!((x - dottie).abs() <= 4.0 * f64::EPSILON);
        let f = |x: f64| Ok((x - 2.0) * (x * x + 1.0));
        let x = brent(f, (0.0, -2.0), (5.0, 78.0), 1e-10, 100).unwrap();
        assert!((x - 2.0).abs() <= 2e-10);
        let g = |x: f64| (50.0 * x).exp() - 2.0;
        let x = brent(|x| Ok(g(x)), (-1.0, g(-1.0)), (1.0, g(1.0)), 0.0, 200).unwrap();
        assert!((x - 2f64.ln() / 50.0).abs() <= 1e-16);
    }

    /// The chord method in three unknowns finds the root of a coupled nonlinear system
    /// (x = (1, 2, 3): x1 x2 = 6, x0^2 + x1 = 3, x0 + x2^2 = 10) to its tolerance, through
    /// the pivoted elimination (the first equation does not depend on x0: the Jacobian's
    /// first pivot is zero).
    #[test]
    fn chord_in_three_unknowns() {
        let f = |x: [f64; 3]| {
            Ok([
                x[1] * x[2] - 6.0,
                x[0] * x[0] + x[1] - 3.0,
                x[0] + x[2] * x[2] - 10.0,
            ])
        };
        let (x, _, step) = chord(
            [1.1, 1.9, 3.05],
            [1e-7; 3],
            1e-13,
            50,
            &mut None,
            f,
            |v: &[f64; 3]| *v,
            |x: [f64; 3], d: [f64; 3]| {
                Ok((
                    std::array::from_fn(|i| x[i] + d[i]),
                    d.iter().fold(0.0f64, |a, v| a.max(v.abs())),
                ))
            },
        )
        .unwrap();
        assert!(step <= 1e-13, "{step:e}");
        for (v, e) in x.iter().zip([1.0, 2.0, 3.0]) {
            assert!((v - e).abs() < 1e-12, "{x:?}");
        }
    }

    #[test]
    fn passes_on_the_function_error_and_stops_at_the_iteration_cap() {
        let failing = |_x: f64| Err(Error::Internal("boom".into()));
        assert!(matches!(
            brent(failing, (0.0, -1.0), (1.0, 1.0), 0.0, 10),
            Err(Error::Internal(_))
        ));
        let slow = |x: f64| Ok(x);
        assert!(matches!(
            brent(slow, (-1.0, -1.0), (1.0, 1.0), 0.0, 1),
            Err(Error::NoConvergence(_))
        ));
    }
}
