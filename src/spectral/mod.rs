//! COUPLED on global bases per zone (docs/theory_spectral.md): the spectral solver of the
//! coupled equations (E1)-(E4) of the reduced problem (bp = bq = b*, friction mu~).
//!
//! - [`basis`]: per zone, Jacobi polynomials carrying the local exponents (g at x = +-c,
//!   -g at x = +-1) and poles clustered towards the neighbouring singular points;
//! - [`points`]: the collocation points;
//! - [`system`]: for a trial c, the bordered least-squares system with the constant sigma in
//!   (E2), whose zero fixes c;
//! - here: c by the secant method on sigma(lc), lc = ln(c / (1 - c)), from a starting
//!   guess, at successive levels of the bases' sizes until two levels agree on c and the
//!   tractions within the tolerances, the equations hold at the collocation points to the
//!   traction tolerance (R1) and the tractions' rounding noise is small (R2).
//!
//! Phase one of the rebuild: the solver answers where it converges from the tabulated stick
//! edge in the mid-range of c; the caller falls back to the panels elsewhere.

pub(crate) mod basis;
pub(crate) mod points;
pub(crate) mod system;

#[cfg(test)]
mod tests;

use crate::numerics::quadrature::{gauss_jacobi, gauss_legendre};
use crate::problem::StickEdge;
pub(crate) use system::Constants;
use system::{Fixed, Sizes, solve_fixed};

/// Smallest edge exponent g the bases serve. As g -> 0 (large friction, g ~ 1/(pi b* mu~))
/// the slip zone's two weights (1 - s)^-g and (1 - s)^-g (1 + s)^g, and the stick zone's
/// Legendre and P^(g,g) families, become the same functions, and the frame degenerates. On
/// the 24 x 24 grid of the table's coordinates (c to 1e-10, tractions to 1e-8) with no
/// limit down to g = 0.005, every point with g <= 0.024 went unanswered after 50-150 ms of
/// levels, and the one answer at g = 0.027 (with 1 - c = 3.4e-6) was 8.6e-8 from the
/// panels' against estimates of 6.9e-9 and 2.6e-9; from g = 0.03 on, the grids of 24, 37
/// and 53 points per side answered every point and agreed with the panels
/// (docs/theory_spectral.md (B5)).
///
/// The difference quotient ((1 + s)^g - 1) / g is the basis for small g (the panels use it
/// from g < 1e-2); until it is built, the panels answer there.
const G_MIN: f64 = 0.03;

/// Thinnest slip zone the bases serve in this phase: on the 24 x 24 grid with no limit,
/// 1 - c = 6.6e-6 answered and agreed with the panels, 4.1e-6 went unanswered (g = 0.061)
/// and 3.4e-6 answered wrongly (g = 0.027, see [`G_MIN`]); on the grids of 37 and 53 points
/// per side every point down to 6.7e-6 answered and agreed with the panels. Thinner slip
/// zones are the next phase's (tapered poles, or the inner/outer split with the bonded
/// family).
const W_MIN: f64 = 5e-6;

/// Smallest stick zone the bases serve in this phase, the smallest measured: at c = 4.8e-5
/// (the carbon ply at mu = 0.1) the answer passed GSL's pointwise check in
/// tests/c/coupled_residuals.c and agreed with the panels' tractions to 4.8e-12
/// (examples/spectral_timing.rs).
const C_MIN: f64 = 4e-5;

/// Largest b* the bases serve in this phase: the largest of the table's grids, 0.989, where
/// every point answered at level 3 and agreed with the panels (c = 2.9e-4 .. 4.1e-2).
const B_MAX: f64 = 0.99;

/// Levels of the bases' sizes tried in turn ([`Sizes::at`]): the mid-range scenes stop at
/// levels 2-4; the 1 - c = 2.1e-3 of b* = 0.2857, mu~ = 1 needs 7 for tractions to 1e-10,
/// and 10 (227 unknowns) takes them to 3e-14.
const FIRST_LEVEL: usize = 1;
const MAX_LEVEL: usize = 10;

/// Factor on the distance between two levels' c and tractions in the error estimates.
const SAFETY: f64 = 2.0;

/// The secant iteration stops when its step in lc falls below this (c to about
/// 1e-13 c (1 - c)).
const LC_STEP: f64 = 1e-13;

/// Most chord steps per level.
const MAX_STEPS: usize = 12;

/// Step in lc of the difference quotient that gives the chord method its slope (sigma moves
/// by about 3e-5 over it at b* = 0.3, mu~ = 0.5, against a rounding noise below 1e-12).
const SLOPE_STEP: f64 = 1e-3;

/// The solution of one level: its stick edge and the fixed-c system there.
#[derive(Clone, Debug)]
pub(crate) struct Level {
    pub(crate) lc: f64,
    pub(crate) fixed: Fixed,
}

/// The spectral solution with its estimates.
#[derive(Clone, Debug)]
pub(crate) struct Spectral {
    pub(crate) edge: StickEdge,
    /// Estimated |c - c_exact|.
    pub(crate) error: f64,
    /// Estimated traction error of the reduced problem's (p, q~), as the two parts
    /// (int |dp|, int |dq~|) (the caller weighs dq~ by delta).
    pub(crate) traction_parts: (f64, f64),
    pub(crate) fixed: Fixed,
    pub(crate) level: usize,
}

impl Spectral {
    /// (p, q~) at 0 <= x < 1.
    pub(crate) fn half_line_tractions(&self, x: f64) -> (f64, f64) {
        self.fixed.at(x)
    }

    /// Number of unknowns of the returned level.
    pub(crate) fn unknowns(&self) -> usize {
        self.fixed.unknowns()
    }
}

/// Whether the bases serve the reduced coupling (b*, mu~) near the stick edge lc.
#[cfg(test)]
pub(crate) fn serves_at(b: f64, mu: f64, lc: f64) -> bool {
    let g = 0.5 - (b * mu).atan() / std::f64::consts::PI;
    serves(Constants { b, mu, g }, lc)
}

/// sigma at lc for the level's sizes (fixed by the starting c, so that sigma(lc) is smooth).
fn sigma_at(k: Constants, lc: f64, sizes: Sizes) -> Option<Level> {
    let e = StickEdge::from_logit(lc);
    let fixed = solve_fixed(k, e.c, e.one_minus_c, sizes).ok()?;
    fixed.sigma.is_finite().then_some(Level { lc, fixed })
}

/// Whether the bases serve the coupling near the stick edge lc: g >= [`G_MIN`],
/// b* <= [`B_MAX`], c >= [`C_MIN`] and 1 - c >= [`W_MIN`].
fn serves(k: Constants, lc: f64) -> bool {
    let e = StickEdge::from_logit(lc);
    k.g >= G_MIN && k.b <= B_MAX && e.c >= C_MIN && e.one_minus_c >= W_MIN
}

/// The root of sigma(lc) at `sizes` by the chord method from `start`: steps -sigma / slope
/// with one slope per solve (`slope` from a previous level, else the difference quotient over
/// [`SLOPE_STEP`], far above sigma's rounding noise), until a step falls below [`LC_STEP`]
/// (the iterate is kept, no further solve), or a step no longer halves |sigma| (the noise
/// floor: the iterate of smallest |sigma|). Returns the root's level and the slope.
pub(crate) fn root(
    k: Constants,
    start: f64,
    sizes: Sizes,
    slope: Option<f64>,
) -> Option<(Level, f64)> {
    let mut cur = sigma_at(k, start, sizes)?;
    let slope = match slope {
        Some(d) => d,
        None => {
            let other = sigma_at(k, start + SLOPE_STEP, sizes)?;
            let d = (other.fixed.sigma - cur.fixed.sigma) / SLOPE_STEP;
            if other.fixed.sigma.abs() < cur.fixed.sigma.abs() {
                cur = other;
            }
            d
        }
    };
    if slope == 0.0 || !slope.is_finite() {
        return None;
    }
    for _ in 0..MAX_STEPS {
        let step = -cur.fixed.sigma / slope;
        if step.abs() <= LC_STEP * (1.0 + cur.lc.abs()) {
            return Some((cur, slope));
        }
        let next = sigma_at(k, cur.lc + step, sizes)?;
        if next.fixed.sigma.abs() >= 0.5 * cur.fixed.sigma.abs() {
            // sigma's noise floor, which is the level's own discretisation error (at b* = 0.3,
            // mu~ = 0.5: 5e-8 at level 1, 1e-12 at level 4): the comparison of levels
            // measures what is left
            return Some((cur, slope));
        }
        cur = next;
    }
    None
}

/// Solves the reduced problem from the starting lc until two successive levels agree on c
/// within `tol` and on the tractions within `traction_tol` (estimates: [`SAFETY`] times the
/// differences), the traction error weighing dq~ by `delta`; None where no level up to
/// [`MAX_LEVEL`] gets there or the answer is not admissible.
pub(crate) fn solve(
    k: Constants,
    start: f64,
    tol: f64,
    traction_tol: f64,
    delta: f64,
) -> Option<Spectral> {
    if !serves(k, start) {
        return None;
    }
    let mut prev: Option<(Level, f64)> = None;
    let mut lc = start;
    let mut slope = None;
    for level in FIRST_LEVEL..=MAX_LEVEL {
        let e = StickEdge::from_logit(lc);
        let sizes = Sizes::at(level, e.c, e.one_minus_c);
        let (cur, d) = root(k, lc, sizes, slope)?;
        slope = Some(d);
        // the level's own uncertainty in lc: the chord step its sigma still asks for
        let left = (cur.fixed.sigma / d).abs();
        if let Some((p, p_left)) = &prev {
            let (ec, ep) = (StickEdge::from_logit(cur.lc), StickEdge::from_logit(p.lc));
            let error = SAFETY * (ec.distance(ep) + ec.c * ec.one_minus_c * (left + p_left));
            let (dp, dq) = distance(&cur.fixed, &p.fixed);
            let parts = (SAFETY * dp, SAFETY * dq);
            if error <= tol
                && parts.0 + delta * parts.1 <= traction_tol
                && cur.fixed.residual <= traction_tol
            {
                match verdict(&cur.fixed, k.mu, traction_tol, delta, parts) {
                    Verdict::Answer(parts) => {
                        return Some(Spectral {
                            edge: ec,
                            error,
                            traction_parts: parts,
                            fixed: cur.fixed,
                            level,
                        });
                    }
                    Verdict::Inadmissible => return None,
                    Verdict::Noisy => {}
                }
            }
        }
        lc = cur.lc;
        prev = Some((cur, left));
    }
    None
}

/// The tractions at a stick edge known within `bound` (in c) of the exact one, `bound`
/// <= `tol` (the tabulated stick edge): no root search. At level 1 the solutions at lc and
/// lc + [`SLOPE_STEP`] give sigma's slope and how far the tractions move per unit of lc; then
/// one solve per level at lc until two levels' tractions agree within `traction_tol`, less
/// what the uncertainty of c moves them ([`SAFETY`] times the move per lc times the
/// uncertainty in lc). Each level also checks the edge: the root its sigma points to,
/// sigma / slope away, must lie within the bound plus [`SAFETY`] times the two levels'
/// difference, else None (the root search decides); None at once where the move alone
/// exceeds `traction_tol`. c keeps its bound as its estimate.
pub(crate) fn at_edge(
    k: Constants,
    lc: f64,
    bound: f64,
    tol: f64,
    traction_tol: f64,
    delta: f64,
) -> Option<Spectral> {
    if bound > tol || !serves(k, lc) {
        return None;
    }
    let edge = StickEdge::from_logit(lc);
    let (c, w) = (edge.c, edge.one_minus_c);
    let first = Sizes::at(FIRST_LEVEL, c, w);
    let mut prev = sigma_at(k, lc, first)?.fixed;
    let shifted = sigma_at(k, lc + SLOPE_STEP, first)?.fixed;
    let slope = (shifted.sigma - prev.sigma) / SLOPE_STEP;
    if slope == 0.0 || !slope.is_finite() {
        return None;
    }
    let uncertainty = bound / (c * w);
    let (mp, mq) = distance(&shifted, &prev);
    let moved = (
        SAFETY * mp / SLOPE_STEP * uncertainty,
        SAFETY * mq / SLOPE_STEP * uncertainty,
    );
    if moved.0 + delta * moved.1 > traction_tol {
        // the bound on c alone moves the tractions by more than the tolerance (thin slip
        // zones: they move like 1 / (1 - c) per unit of c): the root search decides
        return None;
    }
    for level in FIRST_LEVEL + 1..=MAX_LEVEL {
        let cur = sigma_at(k, lc, Sizes::at(level, c, w))?.fixed;
        let offset = (cur.sigma / slope).abs();
        let noise = ((cur.sigma - prev.sigma) / slope).abs();
        if offset > uncertainty + SAFETY * noise {
            return None;
        }
        let (dp, dq) = distance(&cur, &prev);
        let parts = (SAFETY * dp + moved.0, SAFETY * dq + moved.1);
        if parts.0 + delta * parts.1 <= traction_tol && cur.residual <= traction_tol {
            match verdict(&cur, k.mu, traction_tol, delta, parts) {
                Verdict::Answer(parts) => {
                    return Some(Spectral {
                        edge,
                        error: bound,
                        traction_parts: parts,
                        fixed: cur,
                        level,
                    });
                }
                Verdict::Inadmissible => return None,
                Verdict::Noisy => {}
            }
        }
        prev = cur;
    }
    None
}

/// What a level that meets its estimates answers.
enum Verdict {
    /// The traction estimate with the rounding noise added.
    Answer((f64, f64)),
    /// Its rounding noise, added to the estimate, takes it above the tolerance: the next
    /// level (the noise falls with the level, (R2)).
    Noisy,
    /// p <= 0 or |q| > mu p on the stick zone: no answer.
    Inadmissible,
}

/// The verdict on a level whose estimates `parts` meet `traction_tol`: the noise, relative
/// to p, is added to the estimate (int p = 1, so it is an L1 error of that size).
fn verdict(f: &Fixed, mu: f64, traction_tol: f64, delta: f64, parts: (f64, f64)) -> Verdict {
    let Some(noise) = admissible(f, mu) else {
        return Verdict::Inadmissible;
    };
    let parts = (parts.0 + noise, parts.1 + mu * noise);
    if parts.0 + delta * parts.1 <= traction_tol {
        Verdict::Answer(parts)
    } else {
        Verdict::Noisy
    }
}

/// Gauss points per zone of [`distance`].
const DISTANCE_POINTS: usize = 48;

/// (int |dp|, int |dq|) over (-1, 1) between two levels' tractions (the norm of
/// [`crate::problem::traction_distance`]), each zone by a Gauss rule in its own variable: on
/// the stick zone Gauss-Legendre in tau = x / c, on the slip zone Gauss-Jacobi in s for the
/// edge weight (1 - s)^-g (the integrand divided by it). Both levels are evaluated at the
/// same x: their stick edges differ by the levels' error in c.
fn distance(a: &Fixed, b: &Fixed) -> (f64, f64) {
    let (c, w, g) = (a.basis.c, a.basis.w, a.basis.k.g);
    let (mut dp, mut dq) = (0.0, 0.0);
    let (t, wt) = gauss_legendre(DISTANCE_POINTS);
    for (&t, &wt) in t.iter().zip(&wt) {
        // tau in (0, 1): the half of the stick zone
        let x = 0.5 * c * (1.0 + t);
        let ((pa, qa), (pb, qb)) = (a.at(x), b.at(x));
        dp += 0.5 * c * wt * (pa - pb).abs();
        dq += 0.5 * c * wt * (qa - qb).abs();
    }
    let (s, ws) = gauss_jacobi(DISTANCE_POINTS, -g, 0.0);
    for (&s, &ws) in s.iter().zip(&ws) {
        let x = c + 0.5 * w * (1.0 + s);
        let weight = (1.0 - s).powf(-g);
        let ((pa, qa), (pb, qb)) = (a.at(x), b.at(x));
        dp += 0.5 * w * ws * (pa - pb).abs() / weight;
        dq += 0.5 * w * ws * (qa - qb).abs() / weight;
    }
    (2.0 * dp, 2.0 * dq)
}

/// Points per zone of the admissibility check.
const CHECK_POINTS: usize = 64;

/// Whether the answer is admissible, and its rounding noise: p > 0 everywhere and
/// |q| <= mu p on the stick zone (to 1e-6 relative), at Chebyshev points of each zone; the
/// noise is the largest of [`Fixed::eval_with_noise`] there.
fn admissible(f: &Fixed, mu: f64) -> Option<f64> {
    let (c, w) = (f.basis.c, f.basis.w);
    let mut noise = 0.0f64;
    for i in 0..CHECK_POINTS {
        let th = (i as f64 + 0.5) * std::f64::consts::PI / CHECK_POINTS as f64;
        let (xs, xl) = (c * (0.5 * th).sin(), c + w * (0.5 * th).sin().powi(2));
        let at = |x: f64| {
            let xmc = x - c;
            f.eval_with_noise(&points::Pt {
                x,
                omx: 1.0 - x,
                xmc: if xmc == 0.0 { -f64::MIN_POSITIVE } else { xmc },
            })
        };
        let (stick, slip) = (at(xs), at(xl));
        if !(stick.0 > 0.0 && stick.1.abs() <= mu * stick.0 * (1.0 + 1e-6) && slip.0 > 0.0) {
            return None;
        }
        noise = noise.max(stick.2).max(slip.2);
    }
    Some(noise)
}
