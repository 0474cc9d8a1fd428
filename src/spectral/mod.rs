//! COUPLED on global bases per zone (docs/theory_spectral.md): the spectral solver of the
//! coupled equations (E1)-(E4) of the reduced problem (bp = bq = b*, friction mu~).
//!
//! - [`basis`]: per zone, Jacobi polynomials carrying the local exponents (g at x = +-c,
//!   -g at x = +-1) and poles clustered towards the neighbouring singular points;
//! - [`points`]: the collocation points;
//! - [`system`]: for a trial c, the bordered least-squares system with the constant sigma in
//!   (E2), whose zero fixes c;
//! - here: c from sigma(lc) = 0, lc = ln(c / (1 - c)), from the tabulated stick edge, at
//!   successive levels of the bases' sizes until two levels agree on c and the tractions
//!   within the tolerances (the rounding noise (R2) counted in, and in thin slip zones the
//!   answering level's spread under its rows reordered, (S10)) and the equations hold at the
//!   collocation points to the traction tolerance (R1). One solve per level: sigma's slope
//!   comes from level 1 (at lc and lc + [`SLOPE_STEP`]), and each level's Newton step
//!   -sigma / slope gives its root (S5).
//!
//! Phase one of the rebuild: the solver answers where it converges from the tabulated stick
//! edge in the mid-range of c; the caller falls back to the panels elsewhere.

pub(crate) mod basis;
pub(crate) mod points;
pub(crate) mod system;

#[cfg(test)]
mod tests;

use crate::numerics::quadrature::gauss_legendre_rule;
use crate::problem::StickEdge;
pub(crate) use system::Constants;
use system::{Assembled, Fixed, Noise, Sizes};

/// Smallest edge exponent g the bases serve (large friction, g ~ 1/(pi b* mu~)). Measured on
/// the grid of `coupled::tests::small_g_against_the_panels` (b* = 0.25 .. 0.99 in 9 rows, at
/// the tabulated points the bases serve; c to 1e-10, tractions to 1e-8), each answer against
/// the panels (docs/theory_spectral.md section 7), with the stick q's quotient family
/// ((Q6)-(Q8)):
///
/// | g | served | answered | agreeing |
/// |---|---|---|---|
/// | 3e-4, 1e-3 | 18 | 18 | 18 |
/// | 1e-5 .. 1e-4 | 27 | 27 | 27 |
/// | 1e-6 | 9 | 6 | 6 |
/// | 1e-7 | 5 | 3 | 3 |
///
/// (median 1.4 ms against the panels' 9.6 ms; each unanswered point cost 34-100 ms before the
/// panels answered.) On the table's 53 x 53 and 24 x 24 grids
/// (`coupled::tests::spectral_agrees_with_the_panels_on_a_grid`,
/// `tests::agrees_with_the_table_on_a_fine_grid`) with g >= 1e-5 served, 8 of 2193 served
/// points did not answer, all at g = 1.1e-5 .. 2.8e-5 (b* = 0.33 .. 0.38, 1 - c = 1e-5 ..
/// 1.5e-4); with g >= 3e-5, 1666 and 344 served points, all answered (before the quotient
/// family, with g >= 0.002: 1114 and 229). Below, the large-friction terms of (E2), of size
/// mu p ~ b p / (pi g), meet the traction tolerance in their rounding.
pub(crate) const G_MIN: f64 = 3e-5;

/// Thinnest slip zone the bases serve. With the stick poles' offsets exact (Z - tau from the
/// points' offsets, `numerics::jacobi_transform::Point::minus`) and the nearest stick pole at
/// 0.03 (1 - c) (`system::BONDED_NEAREST`), measured from Spence's start at c to 1e-10 and
/// tractions to 1e-8 against the panels (docs/theory_spectral.md section 6), every answer
/// within the sum of both estimates (largest ratio 0.25 in c, 0.24 in the tractions):
///
/// | b* | mu~ | g | 1 - c | level | spectral | panels |
/// |---|---|---|---|---|---|---|
/// | 0.02 | 0.2 | 0.499 | 2.8e-13 | 2 | 42 ms | 2.9 s |
/// | 0.1 | 1.5 | 0.453 | 3.7e-13 | 3 | 115 ms | 4.2 s |
/// | 0.15 | 10 | 0.187 | 8.3e-13 | 3 | 119 ms | 4.7 s |
/// | 0.05 | 0.5 | 0.492 | 1.9e-12 | 2 | 70 ms | 3.0 s |
/// | 0.12 | 2 | 0.425 | 2.7e-12 | 3 | 91 ms | 3.1 s |
/// | 0.15 | 4 | 0.328 | 1.2e-11 | 3 | 119 ms | 3.3 s |
/// | 0.1 | 1 | 0.468 | 1.8e-10 | 3 | 100 ms | 0.93 s |
/// | 0.05 | 0.4 | 0.494 | 3.4e-10 | 2 | 46 ms | 0.87 s |
/// | 0.02 | 0.15 | 0.499 | 5.6e-10 | 2 | 52 ms | 1.3 s |
/// | 0.15 | 2 | 0.407 | 9.5e-10 | 2 | 76 ms | 0.87 s |
/// | 0.2 | 50 | 0.032 | 1.0e-9 | 3 | 46 ms | 0.78 s |
/// | 0.2 | 10 | 0.148 | 2.2e-9 | 3 | 47 ms | 0.74 s |
///
/// (one run each, wall times on the shared 2-core machine). Before, the rounded Z - tau
/// put a noise of eps / (0.1 (1 - c)) into the stick poles' columns and no slip zone of
/// 3e-9 or less answered.
///
/// Below 2.5e-13 (the limit before), measured the same way from the guessed edge at
/// (1e-10, 1e-8), against the panels at (1e-11, 1e-10) (one run each, wall times on the
/// shared machine; the ratio is the tractions' distance over the sum of both estimates; c
/// always within the panels' estimate):
///
/// | b* | mu~ | 1 - c | level | spectral | panels | ratio |
/// |---|---|---|---|---|---|---|
/// | 0.03 | 0.3 | 4.5e-13 | 2 | 36 ms | 8.5 s | 0.09 |
/// | 0.05 | 0.55 | 1.6e-13 | 2 | 62 ms | 10.1 s | 0.21 |
/// | 0.14 | 10 | 8.8e-14 | 4 | 57 ms | 10.0 s | 0.22 |
/// | 0.12 | 3 | 7.2e-14 | 3 | 63 ms | 21.7 s | 0.35 |
/// | 0.1 | 1.8 | 3.0e-14 | 3 | 50 ms | 15.6 s | 0.14 |
/// | 0.02 | 0.2154 | 2.7e-14 | 2 | 62 ms | 10.9 s | 0.34 |
/// | 0.05 | 0.6 | 1.5e-14 | 3 | 55 ms | 11.8 s | 0.09 |
/// | 0.12 | 3.8 | 1.4e-14 | 3 | 83 ms | 13.7 s | 0.18 |
/// | 0.12 | 4.642 | 4.6e-15 | 3 | 91 ms | 24.4 s | 0.08 |
/// | 0.1 | 2.154 | 3.2e-15 | 3 | 52 ms | 12.9 s | 0.38 |
/// | 0.08 | 1.3 | 2.3e-15 | 4 | 100 ms | 18.9 s | 0.07 |
/// | 0.12 | 6 | 1.5e-15 | 4 | 64 ms | 13.7 s | 0.08 |
///
/// Thinner ones (0.12, 10: 3.2e-16; 0.08, 1.6: 5.1e-17; 0.1, 4.642: 3.5e-18) found no level
/// that met the estimates, and the panels answered. With the tractions to 1e-10 none of
/// 1 - c = 1.1e-11 .. 3.2e-15 answered (the levels' tractions stayed 1e-11 .. 3e-10 apart
/// over levels 2-10 at b* = 0.05, mu~ = 0.4642); the panels answer there. Below the thinnest
/// measured the panels answer.
///
/// The same limit holds down to g = [`G_MIN`] (the former rule g >= 0.03 below 1 - c = 1e-3
/// is gone). Measured there (g = 0.0021 .. 0.03, mu~ = cot(pi g) / b*; c to 1e-10, tractions
/// to 1e-8; below b* = 0.25 from Spence's start, above from the table; each answer against
/// the panels, one run, wall times on the shared 2-core machine, docs/theory_spectral.md
/// section 7):
///
/// | b* | 1 - c | points | answered | agreeing | level | spectral | panels |
/// |---|---|---|---|---|---|---|---|
/// | 0.152 .. 0.155 | 3.3e-13 .. 7.1e-13 | 8 | 6 | 6 | 3-4 | 78-139 ms | 2.2-3.4 s |
/// | 0.16 .. 0.185 | 1.7e-12 .. 1.3e-10 | 19 | 19 | 19 | 3 | 54-229 ms | 2.0-20 s |
/// | 0.19 .. 0.245 | 2.3e-10 .. 9.8e-8 | 32 | 32 | 32 | 2-3 | 29-100 ms | 0.50-2.2 s |
/// | 0.25, 0.35 (9 x 9 grid) | 1.3e-7 .. 4.9e-5 | 18 | 18 | 18 | 2-3 | 3.2-10 ms | 64-395 ms |
/// | 0.28 .. 0.41 (53 x 53 grid) | 1.5e-6 .. 4.8e-4 | 30 | 30 | 30 | 2 | 3.7-12 ms | 40-250 ms |
///
/// (the grids: `coupled::tests::small_g_against_the_panels`, whose b* = 0.25 and 0.35 rows
/// this rule newly serves, and the points of
/// `coupled::tests::spectral_agrees_with_the_panels_on_a_grid` with g < 0.03 and
/// 1 - c < 1e-3).
///
/// The largest distances over the sums of both estimates were 0.26 in c and 0.79 in the
/// tractions. The two unanswered points have g = 0.0021 (b* = 0.152 and 0.155): the search
/// from Spence's stick edge gave up after 91-132 ms (the panels answer); from the panels' c,
/// [`from_edge`] answered at level 8.
const W_MIN: f64 = 1.4e-15;

/// Smallest stick zone the bases serve from the tabulated stick edge. Below c = 4e-5
/// (`system::SMALL_STICK_BELOW`) the slip zone has one collocation point more per slip pole
/// column and decade of x - c. Measured from the table's edge (as COUPLED calls
/// [`from_edge`]), c to 1e-10, each answer against the panels at (1e-12, 1e-10)
/// (docs/theory_spectral.md section 5, "Small stick zones"), on b* = 0.25 .. 0.95 (15 rows)
/// by mu~ = 0.01 .. 1 (61 log-spaced), the points with 1e-13 < c < 4e-5 that the
/// full-slip limit does not answer:
///
/// | c | tractions | points | answered | largest true / estimate | unknowns | median, max |
/// |---|---|---|---|---|---|---|
/// | 1e-11 .. 4e-5 | 1e-8 | 148 | 148 | 0.32 | 58-101 | 0.51, 0.95 ms |
/// | 1e-11 .. 4e-5 | 1e-10 | 165 | 165 | 0.81 (one more below) | 67-138 | 0.60, 5.9 ms |
/// | 2e-12 .. 1e-11 | 1e-10 | 6 | 2 | 0.24 (c) | 153, 224 | 9.1, 15.5 ms |
///
/// (thread CPU time of single answers; c's estimate is the table's bound, the answers' c
/// within 5e-4 of it from the panels'; the last row with this limit lowered). One answer at
/// (1e-10, 1e-10), b* = 0.75, mu~ = 0.0681 (c = 3.7e-11), lay 4.3e-13 from the panels at
/// (1e-12, 1e-10) against its estimate of 3.4e-13, and 9.1e-14 from the panels at
/// (1e-13, 1e-11), which lay 3.9e-13 from the first: the reference's error, not the
/// answer's. Below c = 1e-11 the table ends (its zeta = 0 is the full-slip law's
/// c = 1e-11) and the answers come from Spence's stick edge ([`from_guess`], which keeps
/// [`GUESS_C_MIN`]), after 9-15 ms or not at all (at b* = 0.95, mu~ = 0.1343,
/// c = 1.4e-12, the residual (R1) stayed at 2e-10 .. 6e-10 over levels 2-10); the panels
/// answer there.
const C_MIN: f64 = 1e-11;

/// Smallest traction tolerance at which the bases serve stick zones below
/// `system::SMALL_STICK_BELOW` (c < 4e-5), the smallest measured ([`C_MIN`]'s table). On the
/// same 15 x 61 sweep at (1e-6, 1e-4) and (1e-8, 1e-6) the 57 and 107 answers all lay within
/// their estimates of the panels at (1e-12, 1e-10) (at most 0.089 and 0.148, 0.47 and 0.48 ms
/// median); at (1e-12, 1e-12) 85 of 197 answered and 55 lay above their own estimates of
/// 5e-15 .. 6e-14 against those panels (true errors up to 1.3e-12, the reference's own),
/// and up to 14.8 times above them against the panels at (1e-13, 1e-11), which in most of
/// those points gave the same answer as at (1e-12, 1e-10): no reference there is
/// independent and tight enough to check them, so the panels answer, as before.
const SMALL_STICK_TRACTION_TOL: f64 = 1e-10;

/// Smallest stick zone [`from_guess`] serves (b* < 0.25 under the table's strips, and
/// anywhere outside the table), the smallest the bases served before the slip points of
/// `system::SMALL_STICK_BELOW`: measured from Spence's start on b* = 0.02 .. 0.24 (12 rows)
/// by mu~ = 1e-3 .. 0.32 (40 log-spaced), c = 1.9e-11 .. 4e-5, against the panels at
/// (1e-12, 1e-10), the 61 and 66 points answered in a median 3.0 and 3.1 ms (the root
/// search from the guess, levels 2-4), and at (1e-10, 1e-10) 5 of 66 missed their own
/// estimates (true / estimate up to 4.4 in the tractions, 3.7 in c, the tractions' true
/// errors 2e-15 .. 4e-13, at the reference's own accuracy); not served until measured
/// against a tighter reference.
const GUESS_C_MIN: f64 = 4e-5;

/// Largest b* the bases serve in this phase: the largest of the table's grids, 0.989, where
/// every point answered at level 3 and agreed with the panels (c = 2.9e-4 .. 4.1e-2).
const B_MAX: f64 = 0.99;

/// Levels of the bases' sizes tried in turn ([`Sizes::at`]): the mid-range scenes stop at
/// levels 2-4; the 1 - c = 2.1e-3 of b* = 0.2857, mu~ = 1 needs 7 for tractions to 1e-10,
/// and 10 (227 unknowns) takes them to 3e-14.
const FIRST_LEVEL: usize = 1;
const MAX_LEVEL: usize = 10;

/// Levels in a row whose Newton step did not halve after which the root search gives up
/// where that step alone moves the tractions past the tolerance: thin slip zones, where the
/// levels' roots jump by about 1e-7 in lc. On the 129 points of a 53 x 53 grid of the
/// table's coordinates that the first routing's limits left out, at (1e-10, 1e-8): with no
/// such rule 125 answered and 4 (1 - c = 1.2e-5 .. 2.2e-5) went to the panels after about
/// 48 ms of levels; with 2, the same 125 answered and the 4 gave up after 12-32 ms; with 1,
/// 3 more gave up.
const STALLED_LEVELS: usize = 2;

/// Slip zones thinner than this answer from the root search ([`newton_ladder`]) only once the
/// next level's root lies within the answer's estimate of c. There the levels' roots can
/// stall and jump: at b* = 0.23, mu~ = 1.209 (1 - c = 7.0e-5) those of levels 2-5 were
/// 9.57037663, ...6220, ...6159 and ...5698 against the panels' 9.5703765706, so level 4
/// answered with c 3.6e-12 off against an estimate of 2.3e-12, and level 5 would have
/// refused it. Of the 63 points of
/// `coupled::tests::spectral_agrees_with_the_panels_below_the_table_edge_on_a_grid`, 8 had
/// 1 - c below 1e-3, this one the only failure; the largest ratio of distance to estimate
/// elsewhere was 0.30.
const CONFIRM_BELOW: f64 = 1e-3;

/// Slip zones thinner than this count their answering level's rounding spread in the
/// estimates ([`rounding_spread`], docs/theory_spectral.md (S10)). Measured at (1e-10, 1e-8)
/// without the check, at the answering level's c and sizes: the tractions' distance
/// ([`crate::problem::traction_distance`]) of that level solved with its rows reversed, and
/// the largest of four shuffles, from the rows as assembled, over the answer's estimate
/// (one run; the last two rows answered at the table's edge as a pair of solutions,
/// [`Assembled::solve_pair`], and their frames are solved once):
///
/// | b*, mu~ | 1 - c | reversed | shuffles, largest |
/// |---|---|---|---|
/// | 0.02, 0.2 | 2.8e-13 | 0.79 | 0.88 |
/// | 0.1, 1.5 | 3.7e-13 | 0.10 | 0.32 |
/// | 0.15, 10 | 8.3e-13 | 0.65 | 1.07 |
/// | 0.16, 400 | 1.7e-12 | 0.18 | 0.19 |
/// | 0.12, 2 | 2.7e-12 | 0.13 | 0.48 |
/// | 0.15, 4 | 1.2e-11 | 0.04 | 0.28 |
/// | 0.19, 335 | 2.3e-10 | 0.18 | 0.18 |
/// | 0.05, 0.4 | 3.4e-10 | 0.08 | 0.14 |
/// | 0.2, 200 | 8.8e-10 | 0.25 | 0.25 |
/// | 0.2, 50 | 1.0e-9 | 0.15 | 0.29 |
/// | 0.2, 10 | 2.2e-9 | 0.05 | 0.19 |
/// | 0.22, 580 | 8.4e-9 | 0.017 | 0.017 |
/// | 0.2, 3.0949 | 3.8e-8 | 0.003 | 0.003 |
/// | 0.05, 0.29515 | 1.2e-7 | 0.005 | 0.005 |
/// | 0.33, 400 | 1.8e-5 | 0.04 | 0.06 |
/// | 0.05, 0.1866; 0.08, 0.284 | 7.5e-5, 1.6e-4 | 0.002, 0.000 | 0.003, 0.001 |
/// | 0.25, 100; 0.37, 380 | 1.4e-7, 9.5e-5 | 0.03, 0.06 | 0.05, 0.06 |
/// | five mid-range scenes | 0.075 .. 0.96 | at most 0.05 | at most 0.10 |
///
/// Up to 1 - c = 2.2e-9 the spread reaches 0.14-1.07 of the estimate; from 8.4e-9 up at
/// most 0.06, which the estimate holds many times over, so the check is not paid there.
/// With the limit at 1e-8, b* = 0.22, mu~ = 580 at (1e-10, 1e-10) went to the panels (its
/// estimate 9.4e-11 passed 1e-10 with the spread added) for a spread of 0.017.
const ROUNDING_BELOW: f64 = 5e-9;

/// Extra Newton solves per level of a thin slip zone's ladder (1 - c < [`CONFIRM_BELOW`]).
const THIN_NEWTON: usize = 2;

/// Factor on the distance between two levels' c and tractions in the error estimates.
const SAFETY: f64 = 2.0;

/// Step in lc of the difference quotient that gives sigma's slope and the tractions' move per
/// unit of lc (sigma moves by about 3e-5 over it at b* = 0.3, mu~ = 0.5, against a rounding
/// noise below 1e-12).
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

/// The stick-edge table's extent in its coordinates (beta, zeta) up to b* = [`B_MAX`]: the
/// rectangle the tests' and measurements' grids of the tabulated plane span (the table's
/// strips towards the auxetic limit, for c alone, lie beyond what the bases serve).
#[cfg(test)]
pub(crate) fn served_extent() -> ([f64; 2], [f64; 2]) {
    let ([lo_b, hi_b], zeta) = crate::stick_edge_table::extent();
    ([lo_b, hi_b.min(B_MAX.atanh())], zeta)
}

/// Whether [`from_guess`] serves the reduced coupling (b*, mu~) near the stick edge lc: as
/// [`serves_at`], and c >= [`GUESS_C_MIN`].
#[cfg(test)]
pub(crate) fn serves_from_guess_at(b: f64, mu: f64, lc: f64) -> bool {
    let g = 0.5 - (b * mu).atan() / std::f64::consts::PI;
    serves_from_guess(Constants { b, mu, g }, lc)
}

/// Whether [`from_guess`] serves the coupling near lc: [`serves`], and c >= [`GUESS_C_MIN`].
fn serves_from_guess(k: Constants, lc: f64) -> bool {
    serves(k, lc) && StickEdge::from_logit(lc).c >= GUESS_C_MIN
}

/// sigma at lc for the level's sizes (fixed by the starting c, so that sigma(lc) is smooth).
fn sigma_at(k: Constants, lc: f64, sizes: Sizes) -> Option<Level> {
    let (fixed, _) = solved_at(k, lc, sizes, false)?;
    Some(Level { lc, fixed })
}

/// Whether the bases serve the coupling near the stick edge lc: g >= [`G_MIN`],
/// b* <= [`B_MAX`], c >= [`C_MIN`] and 1 - c >= [`W_MIN`].
fn serves(k: Constants, lc: f64) -> bool {
    let e = StickEdge::from_logit(lc);
    k.g >= G_MIN && k.b <= B_MAX && e.c >= C_MIN && e.one_minus_c >= W_MIN
}

/// The solution from the tabulated stick edge lc, known within `bound` in c: c within `tol`
/// and the tractions within `traction_tol` (dq~ weighed by `delta`), or None where no level
/// up to [`MAX_LEVEL`] gets there or the answer is not admissible (the panels answer then).
///
/// Where `bound` <= `tol`, [`at_fixed_edge`] keeps lc, with sigma's slope and the tractions'
/// move per unit of lc bounded ([`SLOPE_FLOOR`], [`SENSITIVITY_BOUNDS`]) or, where the bounds do not
/// decide, measured at the level that needs them ([`First::measured_at`]); else, or where
/// the table's c does not serve, [`newton_ladder`] moves lc from level 1 at lc with the
/// measured slope.
pub(crate) fn from_edge(
    k: Constants,
    lc: f64,
    bound: f64,
    tol: f64,
    traction_tol: f64,
    delta: f64,
) -> Option<Spectral> {
    if !serves(k, lc)
        || (StickEdge::from_logit(lc).c < system::SMALL_STICK_BELOW
            && traction_tol < SMALL_STICK_TRACTION_TOL)
    {
        return None;
    }
    let mut first = First {
        lc,
        base: None,
        measured: None,
    };
    let fixed = if bound <= tol {
        at_fixed_edge(k, &mut first, bound, traction_tol, delta)
    } else {
        None
    };
    fixed.or_else(|| {
        first.measured(k)?;
        first.base(k)?;
        newton_ladder(k, &first, tol, traction_tol, delta)
    })
}

/// Smallest b* [`from_guess`] serves: at b* = 0.005 (mu~ = 1.678e-3, c = 0.03705) the panels'
/// c moved by 3.5e-11 between two reduced frictions one ulp apart, against their estimate of
/// 1.7e-11, so there is no independent reference to check the spectral c against there
/// (sigma's slope is 3.3e-4, so c is weakly fixed; the tractions of the two methods agreed to
/// 1.5e-14). From b* = 0.02 on, every answer agreed with the panels within the estimates
/// (`coupled::tests::spectral_agrees_with_the_panels_from_the_table_below`,
/// `coupled::tests::spectral_agrees_with_the_panels_below_the_table_edge_on_a_grid`).
const GUESS_B_MIN: f64 = 0.02;

/// Most level-1 steps of [`from_guess`]: from Spence's stick edge at the 6 scenes of
/// `coupled::tests::spectral_agrees_with_the_panels_from_the_table_below` (b* = 0.02 .. 0.24,
/// c = 4.4e-5 .. 1 - 1.2e-4) the search took 2-4 before level 1's rounding stopped it; from
/// Spence's 1 - c = 6e-6 at b* = 0.15, mu~ = 10 (1 - c = 8.3e-13, 15.8 away in lc) it took 11,
/// the first 8 of them [`GUESS_MAX_STEP`] long. More means it is not converging and the
/// panels answer.
const GUESS_STEPS: usize = 20;

/// Largest level-1 step in lc of [`from_guess`], a safeguard: the first steps from Spence's c
/// were 4e-5 .. 1.2e-2 in lc at the five scenes traced (b* = 0.005 and 0.1, c = 0.04 .. 0.8);
/// a step beyond 2 means the start is far outside Newton's local model, and it is taken in
/// steps of this length.
const GUESS_MAX_STEP: f64 = 2.0;

/// The solution from a guessed stick edge lc0 (no table, no bound on the guess: outside the
/// tabulated plane, below b* = 0.25 under or above the table's strips there): level 1's root
/// by Newton steps with a secant slope, each at the level's sizes for its own c, until the
/// step moves c by less than a tenth of `tol`; then the root search of [`from_edge`] ([`newton_ladder`]) from there. None where the bases
/// do not serve the guess or the root, or where the steps do not converge within
/// [`GUESS_STEPS`] (the panels answer then).
pub(crate) fn from_guess(
    k: Constants,
    lc0: f64,
    tol: f64,
    traction_tol: f64,
    delta: f64,
) -> Option<Spectral> {
    if k.b < GUESS_B_MIN {
        return None;
    }
    let at = |lc: f64| {
        let e = StickEdge::from_logit(lc);
        serves_from_guess(k, lc)
            .then(|| sigma_at(k, lc, Sizes::at(FIRST_LEVEL, e.c, e.one_minus_c)))
            .flatten()
    };
    let mut cur = at(lc0)?;
    let shifted = at(lc0 + SLOPE_STEP)?;
    let mut slope = (shifted.fixed.sigma - cur.fixed.sigma) / SLOPE_STEP;
    let mut prev_step = f64::INFINITY;
    // the tractions' move per unit of lc, measured between the last two steps (thin slip)
    let mut rate: Option<f64> = None;
    for _ in 0..GUESS_STEPS {
        if slope == 0.0 || !slope.is_finite() {
            return None;
        }
        let step = (-cur.fixed.sigma / slope).clamp(-GUESS_MAX_STEP, GUESS_MAX_STEP);
        if step.abs() <= SLOPE_STEP && step.abs() > 0.5 * prev_step.abs() {
            // no longer halving where Newton converges fast: level 1's own rounding floor
            return from_edge(k, cur.lc, f64::INFINITY, tol, traction_tol, delta);
        }
        prev_step = step;
        let e = StickEdge::from_logit(cur.lc);
        // a thin slip zone's tractions move by rate |step| in lc (rate ~ sqrt(1 - c)), while
        // its c moves by only c (1 - c) |step|: both must be met
        let tractions_met = e.one_minus_c >= CONFIRM_BELOW
            || rate.is_some_and(|r| SAFETY * r * step.abs() <= 0.1 * traction_tol);
        if e.c * e.one_minus_c * step.abs() <= 0.1 * tol && tractions_met {
            return from_edge(k, cur.lc, f64::INFINITY, tol, traction_tol, delta);
        }
        let next = at(cur.lc + step)?;
        if step.abs() > SLOPE_STEP {
            // the secant (below SLOPE_STEP the sigmas' rounding would dominate it)
            slope = (next.fixed.sigma - cur.fixed.sigma) / step;
        }
        if e.one_minus_c < CONFIRM_BELOW {
            let (dp, dq) = graded_distance(&next.fixed, &cur.fixed).parts;
            rate = Some(edge_move_factor(k.g, e.c, e.one_minus_c) * (dp + delta * dq) / step.abs());
        }
        cur = next;
    }
    None
}

/// Lower bound on sigma's slope d sigma / d lc per unit of b*, where the bases serve. Measured
/// at level 1 over lc + [`SLOPE_STEP`]: on the 604 served points of a 53 x 53 grid of the
/// table's coordinates the slope was 8.3e-3 .. 0.19 and slope / b* 0.031 .. 0.19 (the smallest
/// at the smallest stick zones, c = 9e-5, g = 0.496); at the smallest stick zone served
/// (b* = 0.25, c = 4.2e-5) slope / b* was 0.029. The bound is 0.0125, under half of that.
const SLOPE_FLOOR: f64 = 0.0125;

/// One band of [`SENSITIVITY_BOUNDS`]: (b* below, per lc (p, q~), per sigma (p, q~)).
type SensitivityBand = (f64, (f64, f64), (f64, f64));

/// Upper bounds, per band of b*, on the tractions' move per unit of lc,
/// (int |dp|, int |dq~|) / dlc, and per unit of sigma at a fixed level's sizes,
/// (int |dp|, int |dq~|) / |d sigma| = rate / |slope|, where the bases serve: (b* below, per
/// lc, per sigma). Both grow with b*, the coupling through which c moves the tractions at
/// all. Measured at levels 1 and 2 over lc + [`SLOPE_STEP`] on the 918 served nodes of a
/// 53 x 53 grid of the table's coordinates (b* = 0.02 .. 0.99, c = 1e-4 .. 1 - 1e-5), the
/// largest per band:
///
/// | b* | points | per lc, p | q~ | per sigma, p | q~ |
/// |---|---|---|---|---|---|
/// | 0 .. 0.1 | 16 | 0.00122 | 0.0142 | 0.171 | 1.98 |
/// | 0.1 .. 0.2 | 18 | 0.00731 | 0.0358 | 0.422 | 2.06 |
/// | 0.2 .. 0.3 | 36 | 0.019 | 0.0617 | 0.689 | 2.23 |
/// | 0.3 .. 0.4 | 49 | 0.0369 | 0.0974 | 0.979 | 2.57 |
/// | 0.4 .. 0.5 | 68 | 0.0774 | 0.217 | 1.46 | 4.08 |
/// | 0.5 .. 0.6 | 64 | 0.143 | 0.506 | 2.1 | 7.37 |
/// | 0.6 .. 0.7 | 61 | 0.234 | 0.971 | 2.8 | 11.6 |
/// | 0.7 .. 0.8 | 96 | 0.412 | 2.02 | 3.8 | 18.5 |
/// | 0.8 .. 0.9 | 126 | 1.11 | 3.83 | 8 | 27.1 |
/// | 0.9 .. 0.95 | 119 | 2.32 | 5.5 | 14.6 | 36.9 |
/// | 0.95 .. 0.99 | 265 | 2.46 | 4.09 | 13.7 | 24.2 |
///
/// The bounds are twice the largest. (One bound for the whole plane, (4, 8) per lc and
/// (30, 70) per sigma, was near the largest only at b* >= 0.8; at b* = 0.33, c = 0.09 the
/// move per lc measured 3.4e-3 against 4, so every speed scene at tractions to 1e-10 measured
/// the slope and the move, one more solve.)
const SENSITIVITY_BOUNDS: [SensitivityBand; 11] = [
    (0.1, (0.0025, 0.029), (0.35, 4.0)),
    (0.2, (0.015, 0.072), (0.85, 4.2)),
    (0.3, (0.038, 0.124), (1.4, 4.5)),
    (0.4, (0.074, 0.195), (2.0, 5.2)),
    (0.5, (0.155, 0.434), (2.9, 8.2)),
    (0.6, (0.286, 1.01), (4.2, 14.8)),
    (0.7, (0.468, 1.94), (5.6, 23.2)),
    (0.8, (0.824, 4.04), (7.6, 37.0)),
    (0.9, (2.22, 7.66), (16.0, 54.2)),
    (0.95, (4.64, 11.0), (29.2, 73.8)),
    (f64::INFINITY, (4.92, 8.18), (27.4, 48.4)),
];

/// Upper bounds on the tractions' move per unit of c, (int |dp|, int |dq~|) / dc =
/// rate / (c (1 - c)), where c < [`SMALL_C`]: per band of b* (b* below, then the bounds for
/// c below 0.01, 0.1 and [`SMALL_C`]). A stick zone of size c moves the tractions mostly
/// within a few c of it, so the move per lc falls like c, while the table's uncertainty in
/// lc, its bound on c over c (1 - c), grows as 1/c; the move per c is nearly constant in c
/// and grows with b*, so a bound per band of b* and of c is 5-40 times tighter than
/// [`SENSITIVITY_BOUNDS`] alone at small and mid-sized stick zones. Measured as
/// [`First::measured_at`] measures it, at levels 1, 2 and 3, on the 161 x 161 grid of the
/// table's coordinates (`tests::measure_rate_per_c_by_b`, c from 1e-4 up; below, the move
/// per lc is level 1's own change, [`RATE_FLOOR`]), the largest per band (p, q~):
///
/// | b* | c < 0.01 | 0.01 .. 0.1 | 0.1 .. 0.3 |
/// |---|---|---|---|
/// | 0 .. 0.1 | 1.28e-3, 8.90e-3 | 2.34e-3, 1.45e-2 | 3.56e-3, 2.19e-2 |
/// | 0.1 .. 0.2 | 7.19e-3, 2.18e-2 | 1.31e-2, 3.57e-2 | 1.98e-2, 5.41e-2 |
/// | 0.2 .. 0.3 | 1.65e-2, 3.47e-2 | 3.00e-2, 5.74e-2 | 4.52e-2, 8.75e-2 |
/// | 0.3 .. 0.4 | 3.33e-2, 5.34e-2 | 6.03e-2, 8.96e-2 | 9.00e-2, 0.138 |
/// | 0.4 .. 0.5 | 6.25e-2, 8.22e-2 | 0.112, 0.141 | 0.165, 0.218 |
/// | 0.5 .. 0.6 | 0.112, 0.129 | 0.199, 0.226 | 0.326, 0.415 |
/// | 0.6 .. 0.7 | 0.197, 0.210 | 0.344, 0.374 | 0.539, 0.686 |
/// | 0.7 .. 0.8 | 0.395, 0.408 | 0.742, 0.859 | 1.06, 1.54 |
/// | 0.8 .. 0.9 | 1.24, 1.37 | 2.00, 2.82 | 2.68, 6.55 |
/// | 0.9 .. 0.95 | 2.86, 3.58 | 4.80, 10.5 | 4.93, 21.7 |
/// | 0.95 .. 0.99 | 20.1, 41.2 | 22.1, 94.4 | 9.88, 47.2 |
///
/// (6-1041 points per cell, 16,954 solves in all.) The bounds are twice the largest. The grid
/// of `tests::sensitivity_bounds_hold` (37 x 37 cell midpoints, only its centre a node of
/// this one) checks them.
/// (With [`SENSITIVITY_BOUNDS`] alone from c = 0.01 up, and one pair, (55, 70), below, the
/// bound on the move at tractions to 1e-10 failed b* = 0.318, c = 0.020 (delta = 10,
/// mu = 1), which then measured the slope and the move, one more solve, and b* = 0.448,
/// c = 0.124 (kappa = 0.4, mu = 0.3), which solved a second pair.)
const RATE_PER_C: [(f64, [(f64, f64); 3]); 11] = [
    (0.1, [(2.6e-3, 1.8e-2), (4.7e-3, 2.9e-2), (7.2e-3, 4.4e-2)]),
    (0.2, [(1.5e-2, 4.4e-2), (2.7e-2, 7.2e-2), (4.0e-2, 0.11)]),
    (0.3, [(3.3e-2, 7.0e-2), (6.0e-2, 0.115), (9.1e-2, 0.175)]),
    (0.4, [(6.7e-2, 0.107), (0.121, 0.18), (0.18, 0.276)]),
    (0.5, [(0.125, 0.165), (0.225, 0.282), (0.33, 0.436)]),
    (0.6, [(0.225, 0.259), (0.398, 0.451), (0.652, 0.83)]),
    (0.7, [(0.395, 0.42), (0.688, 0.749), (1.08, 1.372)]),
    (0.8, [(0.79, 0.816), (1.484, 1.718), (2.13, 3.08)]),
    (0.9, [(2.48, 2.75), (4.0, 5.64), (5.37, 13.1)]),
    (0.95, [(5.73, 7.16), (9.61, 20.9), (9.87, 43.4)]),
    (f64::INFINITY, [(40.3, 82.5), (44.3, 189.0), (19.8, 94.4)]),
];

/// Lower bounds on [`RATE_PER_C`]'s bound on the move per lc, (int |dp|, int |dq~|) / dlc: below
/// c = 4e-5 (served since `system::SMALL_STICK_BELOW`) the move measured at level 1 over
/// lc + [`SLOPE_STEP`] does not fall with c. On the 165 points with c = 1.2e-11 .. 4e-5 of
/// b* = 0.25 .. 0.95 (15 rows) by mu~ = 0.01 .. 1 (61 log-spaced) it was 1e-7 .. 2.7e-6 (p)
/// at c < 1e-8 whatever c, up to 3700 times [`RATE_PER_C`]'s bound (b* = 0.95,
/// c = 1.3e-11: 2.65e-6): level 1's own change over the step rather than the tractions'
/// (measured the same way at level 3, at most 4.1 times that bound). The largest anywhere
/// below 4e-5 were 3.6e-5 (p) and 4.5e-5 (q~). Towards b* = 0.99 the move grows: on the
/// 294 served points with c < 4e-5 of the 37 x 37 grid of `tests::sensitivity_bounds_hold`
/// and of b* = 0.25 .. 0.99 (20 rows) by mu~ = 0.01 .. 1 (61 log-spaced), per band of b*
/// (with the stick zone's cluster of `points::STICK_CLUSTER_FROM`):
///
/// | b* | points | p | q~ |
/// |---|---|---|---|
/// | 0.25 .. 0.95 | 248 | 2.1e-5 | 2.3e-5 |
/// | 0.95 .. 0.97 | 18 | 4.2e-5 | 4.2e-5 |
/// | 0.97 .. 0.98 | 6 | 4.8e-5 | 4.2e-5 |
/// | 0.98 .. 0.99 | 22 | 2.45e-4 | 3.27e-4 |
///
/// The floors are twice the largest of each band, below b* = 0.98 and above (b* below,
/// floors). They take over from [`RATE_PER_C`]'s bound below c = floor / (its bound per c):
/// about 2.4e-6 at b* above 0.95 (1.2e-5 above 0.98), 1.4e-3 at b* = 0.3 .. 0.4 and 0.037
/// below b* = 0.1, where the move per lc is small anyway (the bounds only get looser).
const RATE_FLOOR: [(f64, (f64, f64)); 2] =
    [(0.98, (9.6e-5, 9.0e-5)), (f64::INFINITY, (4.9e-4, 6.6e-4))];

/// The stick zones below which [`RATE_PER_C`] bounds the move per lc too: the table's
/// largest band of c (above 0.3 the slip zone's width w takes over: the move per c grows as
/// 1/w, up to (4.1e4, 2.0e5) at b* = 0.2 .. 0.3 with c above 0.5).
const SMALL_C: f64 = 0.3;

/// The bounds at b* and the stick edge c (1 - c = w): (per lc, per sigma), from
/// [`SENSITIVITY_BOUNDS`] and, for c < [`SMALL_C`], [`RATE_PER_C`].
fn sensitivity_bounds(b: f64, g: f64, c: f64, w: f64) -> ((f64, f64), (f64, f64)) {
    let &(_, (mut p, mut q), by_sigma) = SENSITIVITY_BOUNDS
        .iter()
        .find(|r| b < r.0)
        .unwrap_or(&SENSITIVITY_BOUNDS[SENSITIVITY_BOUNDS.len() - 1]);
    if c < SMALL_C {
        let &(_, floor) = RATE_FLOOR
            .iter()
            .find(|r| b < r.0)
            .unwrap_or(&RATE_FLOOR[RATE_FLOOR.len() - 1]);
        let &(_, by_c) = RATE_PER_C
            .iter()
            .find(|r| b < r.0)
            .unwrap_or(&RATE_PER_C[RATE_PER_C.len() - 1]);
        let (per_c_p, per_c_q) = by_c[if c < 0.01 {
            0
        } else if c < 0.1 {
            1
        } else {
            2
        }];
        p = p.min((per_c_p * c * w).max(floor.0));
        q = q.min((per_c_q * c * w).max(floor.1));
    }
    let f = edge_move_factor(g, c, w);
    ((f * p, f * q), (f * by_sigma.0, f * by_sigma.1))
}

/// The factor on the tractions' move per unit of lc as measured over [`SLOPE_STEP`] that
/// bounds it over any smaller move (docs/theory_spectral.md (S11)). The edge terms
/// (c - x)^g of q on the stick side and (x - c)^g of p and q on the slip zone move by
/// A (1 - d^g / (1 + g)) d in L1 when c moves by d (to first order in d, the zone's scale
/// taken as 1): per unit of c the move grows as d falls, like ln(1/d) while g ln(1/d) < 1,
/// where the smooth terms' stays. The factor is its largest over d down to one ulp of lc,
/// eps c (1 - c), over its value at the step, d = c (1 - c) [`SLOPE_STEP`]. Measured
/// (`tests::move_per_lc_grows_as_the_edge_terms_say`, level 4 at the table's c, q~'s move
/// over lc + 1e-9 per unit of lc over that over the step, by a rule graded to 1e-15 at c):
///
/// | b*, g | measured | edge terms at 1e-9 | over the estimates' move at the step | factor |
/// |---|---|---|---|---|
/// | 0.99, 1e-3 (c = 0.049) | 2.638 | 2.243 | 3.022 | 3.601 |
/// | 0.75, 1e-3 | 2.393 | 2.373 | 2.908 | 3.873 |
/// | 0.6, 0.01 | 2.048 | 2.044 | 2.639 | 3.045 |
/// | 0.5, 0.1 | 1.278 | 1.283 | 1.525 | 1.358 |
/// | 0.3, 0.3 | 1.004 | 1.006 | 1.042 | 1.006 |
///
/// (the estimates measure the move with [`distance`]'s 32 points per zone, which miss part of
/// the edge terms' move next to c; [`SAFETY`] covers the last two rows). Without it, at
/// b* = 0.99, g = 1e-3 the answer at (1e-10, 1e-10), at the table's c 1.9e-13 from the root,
/// lay 7.5e-11 from the tractions at the root against an estimate of 6.0e-11.
fn edge_move_factor(g: f64, c: f64, w: f64) -> f64 {
    let moved = |d: f64| 1.0 - d.powf(g) / (1.0 + g);
    let cw = c * w;
    (moved(f64::EPSILON * cw) / moved(SLOPE_STEP * cw)).max(1.0)
}

/// The starting lc with level 1 there (solved on first use) and, once measured, sigma's slope and the tractions' move per unit of lc.
struct First {
    lc: f64,
    base: Option<Level>,
    measured: Option<Sensitivity>,
}

/// sigma's slope and the tractions' move per unit of lc, (int |dp|, int |dq~|) / dlc.
#[derive(Clone, Copy)]
struct Sensitivity {
    slope: f64,
    rate: (f64, f64),
}

impl First {
    /// Level 1 at the starting lc, solved on first use.
    fn base(&mut self, k: Constants) -> Option<&Level> {
        if self.base.is_none() {
            let e = StickEdge::from_logit(self.lc);
            self.base = Some(sigma_at(
                k,
                self.lc,
                Sizes::at(FIRST_LEVEL, e.c, e.one_minus_c),
            )?);
        }
        self.base.as_ref()
    }

    /// The slope and the rate, measured on first use: level 1 again at lc + [`SLOPE_STEP`].
    fn measured(&mut self, k: Constants) -> Option<Sensitivity> {
        if self.measured.is_none() {
            let e = StickEdge::from_logit(self.lc);
            let sizes = Sizes::at(FIRST_LEVEL, e.c, e.one_minus_c);
            let base = self.base(k)?.fixed.clone();
            self.measured_at(k, &base, sizes)?;
        }
        self.measured
    }

    /// The slope and the rate measured at a level's own sizes: `cur`, solved at the starting
    /// lc with `sizes`, against the same sizes at lc + [`SLOPE_STEP`] (one solve; at a known
    /// edge in place of level 1 twice, [`First::measured`]).
    fn measured_at(&mut self, k: Constants, cur: &Fixed, sizes: Sizes) -> Option<Sensitivity> {
        if self.measured.is_none() {
            let shifted = sigma_at(k, self.lc + SLOPE_STEP, sizes)?.fixed;
            let slope = (shifted.sigma - cur.sigma) / SLOPE_STEP;
            if slope == 0.0 || !slope.is_finite() {
                return None;
            }
            let (mp, mq) = distance(&shifted, cur).parts;
            let e = StickEdge::from_logit(self.lc);
            let f = edge_move_factor(k.g, e.c, e.one_minus_c) / SLOPE_STEP;
            self.measured = Some(Sensitivity {
                slope,
                rate: (f * mp, f * mq),
            });
        }
        self.measured
    }
}

/// The tractions at the starting lc, whose c is within `bound` of the exact one: half levels
/// from [`first_half_level`] on, each one assembly and one factorisation at lc that solve both
/// the level and its coarser columns ([`Assembled::solve_pair`]), until the level's
/// tractions agree with the coarser ones, or with the level below where that is nearer,
/// within `traction_tol`, less what the distance from lc to the root moves them. Each level
/// also checks the edge: the root its sigma points to, sigma / slope away, must lie within the
/// bound plus [`SAFETY`] times sigma's uncertainty over the slope, else None (a level whose
/// tractions are not yet within the tolerance of its coarser columns is passed over instead,
/// [`OFF_EDGE_PASSES`] times); that
/// uncertainty is the larger of sigma's differences from the coarser columns and from the
/// level below (with the sparser rows above level 1, sigma moved by 1e-11 .. 5e-11 between
/// half levels at mu~ = 1; taking only the difference nearer in the tractions refused the
/// known edge there and the ply at mu = 1 climbed from 59 to 87-101 unknowns). c keeps its
/// bound as its estimate.
///
/// The tractions' move to the root is the smaller of two bounds on it ((S9)): the move per lc
/// times the bound on lc's distance ([`SAFETY`] times each), and the move per sigma times
/// the level's |sigma| plus [`SAFETY`] times its uncertainty. The slope,
/// the move per lc and the move per sigma are the bounds [`SLOPE_FLOOR`] and
/// [`SENSITIVITY_BOUNDS`] (a smaller slope and larger moves only make the tests stricter) until
/// the edge test fails with them, or a level's tractions meet the tolerance but not with the
/// move added while the bound by lc's distance alone exceeds it; then the slope and the move
/// per lc are measured at the level's sizes ([`First::measured_at`]) and the test is
/// repeated. None where, measured,
/// the move with sigma's uncertainty taken off |sigma| (which the levels above do not lower)
/// exceeds `traction_tol`.
fn at_fixed_edge(
    k: Constants,
    first: &mut First,
    bound: f64,
    traction_tol: f64,
    delta: f64,
) -> Option<Spectral> {
    let lc = first.lc;
    let edge = StickEdge::from_logit(lc);
    let (c, w) = (edge.c, edge.one_minus_c);
    let uncertainty = bound / (c * w);
    let mut below: Option<Fixed> = None;
    let mut passes = OFF_EDGE_PASSES;
    for half in first_half_level(traction_tol, k, w)..=2 * MAX_LEVEL {
        let sizes = Sizes::at_real(0.5 * half as f64, c, w);
        // each level with its coarser columns on the same rows (one assembly and one
        // factorisation for both); the estimate is the distance to the nearer of those and
        // the level below
        let system = Assembled::new(k, c, w, sizes);
        let (coarse, cur) = system.solve_pair().ok()?;
        if !cur.sigma.is_finite() {
            return None;
        }
        if half == 2 * FIRST_LEVEL && first.base.is_none() {
            first.base = Some(Level {
                lc,
                fixed: cur.clone(),
            });
        }
        // sigma's uncertainty: the larger of its differences from the coarser columns and
        // from the level below (both at lc)
        let mut dsigma = (cur.sigma - coarse.sigma).abs();
        let compared = level_distance(&cur, &coarse);
        let (mut dp, mut dq) = compared.parts;
        if let Some(b) = below.take() {
            dsigma = dsigma.max((cur.sigma - b.sigma).abs());
            let (bp, bq) = level_distance(&cur, &b).parts;
            if bp + delta * bq < dp + delta * dq {
                (dp, dq) = (bp, bq);
            }
        }
        let off_edge = |s: Option<Sensitivity>| {
            let slope = s.map_or(SLOPE_FLOOR * k.b, |s| s.slope.abs());
            (cur.sigma / slope).abs() > uncertainty + SAFETY * dsigma / slope
        };
        if off_edge(first.measured)
            && (first.measured.is_some() || off_edge(Some(first.measured_at(k, &cur, sizes)?)))
        {
            if passes > 0 && SAFETY * (dp + delta * dq) > traction_tol {
                passes -= 1;
                below = Some(cur);
                continue;
            }
            return None;
        }
        // lc's distance to the root by sigma, |sigma| / slope, with sigma's uncertainty
        // added (spread) and taken off (least)
        let spread = cur.sigma.abs() + SAFETY * dsigma;
        let least = (cur.sigma.abs() - SAFETY * dsigma).max(0.0);
        let shift = |s: Option<Sensitivity>, sigma: f64| {
            let (by_lc, by_sigma) = match s {
                Some(s) => (s.rate, (s.rate.0 / s.slope.abs(), s.rate.1 / s.slope.abs())),
                None => sensitivity_bounds(k.b, k.g, c, w),
            };
            (
                SAFETY * (by_lc.0 * uncertainty).min(by_sigma.0 * sigma),
                SAFETY * (by_lc.1 * uncertainty).min(by_sigma.1 * sigma),
            )
        };
        let exceeds = |sh: (f64, f64)| sh.0 + delta * sh.1 > traction_tol;
        let mut moved = shift(first.measured, spread);
        if first.measured.is_none()
            && exceeds(shift(None, f64::INFINITY))
            && exceeds((SAFETY * dp + moved.0, SAFETY * dq + moved.1))
            && !exceeds((SAFETY * dp, SAFETY * dq))
        {
            // the move alone fails the level, and the bound on lc's distance would fail
            // every level
            moved = shift(Some(first.measured_at(k, &cur, sizes)?), spread);
        }
        if let Some(s) = first.measured
            && exceeds(shift(Some(s), least))
        {
            // no level above takes the move below the tolerance
            return None;
        }
        let meets = |parts: (f64, f64)| {
            parts.0 + delta * parts.1 <= traction_tol && cur.residual <= traction_tol
        };
        let mut parts = (SAFETY * dp + moved.0, SAFETY * dq + moved.1);
        if meets(parts) && w < ROUNDING_BELOW {
            // a thin slip zone's rounding spread, counted once the level meets its
            // estimates (as the root search counts it, [`rounding_spread`]): the tractions'
            // distance from the same system solved with its rows reversed, and sigma's,
            // which widens lc's distance to the root (a failed second solve: no answer here)
            parts = match reversed_rows(&system) {
                Some(other) => {
                    let (rp, rq) = graded_distance(&other, &cur).parts;
                    let rsigma = (other.sigma - cur.sigma).abs();
                    let moved = shift(
                        first.measured,
                        cur.sigma.abs() + SAFETY * dsigma.max(rsigma),
                    );
                    (SAFETY * (dp + rp) + moved.0, SAFETY * (dq + rq) + moved.1)
                }
                None => (f64::INFINITY, f64::INFINITY),
            };
        }
        if meets(parts) {
            match verdict(compared.noise, traction_tol, delta, parts) {
                Verdict::Answer(parts) => {
                    return Some(Spectral {
                        edge,
                        error: bound,
                        traction_parts: parts,
                        fixed: cur,
                        level: half.div_ceil(2),
                    });
                }
                Verdict::Inadmissible => return None,
                Verdict::Noisy => {}
            }
        }
        below = Some(cur);
    }
    None
}

/// Levels off the edge that [`at_fixed_edge`] passes over while their tractions are not yet
/// within the tolerance of their coarser columns: such a level's sigma can lie further from
/// the root than its distance to the coarser columns says (b* = 0.774, mu~ = 0.650, c = 0.15:
/// level 1.5's sigma / slope was 5e-10 in lc against an uncertainty of 2e-10, level 2
/// answered at the table's c). On the 918 served nodes of a 53 x 53 grid of the table's
/// coordinates at (1e-10, 1e-8), from level 1.5: 876 answers with none, 885 with one, 885
/// with two.
const OFF_EDGE_PASSES: usize = 1;

/// The first half level (level times 2) of [`at_fixed_edge`] at the traction tolerance: level
/// 1.5 at 1e-8, half a level more per two decades below (level 2 at 1e-10), and level 1.5
/// above as well ([`FIRST_HALF_LEVEL_MIN`]). Measured on the 10 spectral scenes of `examples/spectral_timing.rs`
/// with the half-level ladder, the sum of n^3 over the levels solved (n unknowns; the QR's
/// cost, and the assembly's grows like n^2) for the first level:
///
/// | traction tolerance | from level 1 | 1.5 | 2 | 2.5 |
/// |---|---|---|---|---|
/// | 1e-8 | 2292k (3 answers at level 1, 7 at 1.5) | 2145k (8 at 1.5, 2 at 2) | | |
/// | 1e-10 | | | 3842k (6 at 2, 3 at 2.5, 1 at 3) | 4691k (7 at 2.5, 3 at 3) |
///
/// Half a level more where the first one rarely answers: slip zones of 1 - c = 0.01 .. 0.2,
/// and 1 - c >= 0.5 at b* >= 0.75 ([`late_start`]).
fn first_half_level(traction_tol: f64, k: Constants, w: f64) -> usize {
    let decades = (1e-8 / traction_tol).log10();
    let late = if late_start(k, w) { 1.0 } else { 0.0 };
    (3.0 + (0.5 * decades).round() + late)
        .clamp(FIRST_HALF_LEVEL_MIN as f64, 2.0 * MAX_LEVEL as f64) as usize
}

/// The lowest first half level of [`at_fixed_edge`], at loose tolerances: level 1.5, whose
/// sparser points and slip degrees ([`system::Sizes`]) make it cheaper than level 1 with
/// about as many unknowns (40-73 against 40-75 on the speed scenes) and far more accurate.
/// Measured on the 10 spectral speed scenes (c to 1e-10; thread CPU time, the median over the
/// scenes, alternated twice in one run; true error against the panels at (1e-13, 1e-11)):
///
/// | tractions to | from level 1 | from level 1.5 | largest true / estimate from 1.5 |
/// |---|---|---|---|
/// | 1e-6 | 0.177, 0.178 ms | 0.120, 0.119 ms | 0.060 |
/// | 1e-4 | 0.179, 0.227 ms | 0.157, 0.124 ms | 0.060 |
///
/// (with c to 1e-6 and 1e-4 as well, the same ratios: every answer at level 1.5, estimates
/// 1.6e-11 .. 2.0e-8). Before, a looser tolerance cost more than 1e-8
/// (`examples/speed_accuracy`: 210 and 221 us at tol 1e-4 and 1e-6 against 141 us at 1e-8).
const FIRST_HALF_LEVEL_MIN: usize = 3;

/// Where [`at_fixed_edge`] starts half a level higher: 1 - c in [0.01, 0.2), or 1 - c >= 0.5
/// at b* >= 0.75. On the 918 served nodes of a 53 x 53 grid of the table's coordinates at
/// (1e-10, 1e-8) (delta = 1; the least time of four runs, alternated), by band:
///
/// | 1 - c | points | answered at 1.5 | answered from 1.5 | from 2 | time from 1.5 | from 2 |
/// |---|---|---|---|---|---|---|
/// | < 0.01 | 114 | 104 | 114 | 114 | 233 ms | 290 ms |
/// | 0.01 .. 0.2 | 132 | 50 | 122 | 130 | 104 ms | 77 ms |
/// | 0.2 .. 0.5 | 115 | 112 | 112 | 110 | 39 ms | 51 ms |
/// | >= 0.5, b* < 0.75 | 89 | 87 | 88 | 89 | 28 ms | 30 ms |
/// | >= 0.5, b* >= 0.75 | 468 | 136 | 449 | 460 | 461 ms | 333 ms |
///
/// (an unanswered point goes on to the root search). Over the grid: 865 ms from level 1.5
/// everywhere (885 answered), 781 ms from level 2 everywhere (903), 709 ms with this rule
/// (904). At (1e-10, 1e-10), from level 2 or 2.5, the rule changed the sum by 1.5 % (5.33 s,
/// 5.27 s).
fn late_start(k: Constants, w: f64) -> bool {
    (0.01..0.2).contains(&w) || (w >= 0.5 && k.b >= 0.75)
}

/// The root search as a ladder of levels with one solve each: level L is solved at lc_L, its
/// root is r_L = lc_L - sigma_L / slope (one Newton step with level 1's slope), and
/// lc_(L+1) = r_L. Level 1's root is only compared, not moved to: the table's c is closer
/// (at 1 - c = 6e-5 level 1's root was 4e-7 off in lc, the table 1e-8). The estimates, with
/// d(L, L-1) the distance of two levels' roots in c:
/// - c: [`SAFETY`] (d(L, L-1) + c (1 - c) (|r_L - lc_L| + |r_(L-1) - lc_(L-1)|)), the roots'
///   distance and each level's own step, which bounds its Newton step's error;
/// - tractions: [`SAFETY`] times their distance between the levels (each at its lc) plus
///   their move over |r_L - lc_L|, since they are those at lc_L;
/// - where 1 - c < [`ROUNDING_BELOW`], once a level meets both without it, [`SAFETY`] times
///   its spread under rounding ([`rounding_spread`]) added to both.
fn newton_ladder(
    k: Constants,
    first: &First,
    tol: f64,
    traction_tol: f64,
    delta: f64,
) -> Option<Spectral> {
    let Sensitivity { slope, rate } = first.measured?;
    let base = first.base.as_ref()?;
    let mut lc = base.lc;
    let mut prev_step = -base.fixed.sigma / slope;
    let mut prev_root = lc + prev_step;
    let mut prev = base.fixed.clone();
    let mut stalled = 0;
    // a thin slip zone's answer, held until the next level's root confirms it
    let mut candidate: Option<(Spectral, f64)> = None;
    for level in FIRST_LEVEL + 1..=MAX_LEVEL {
        let edge = StickEdge::from_logit(lc);
        let (c, w) = (edge.c, edge.one_minus_c);
        // the rounding check's system is kept where it is due
        let check = w < ROUNDING_BELOW;
        let (mut cur, mut system) = solved_at(k, lc, Sizes::at(level, c, w), check)?;
        let mut step = -cur.sigma / slope;
        // a thin slip zone's tractions move by rate |step| with the level's own step: Newton
        // at this level while that exceeds the tolerance and the step still halves
        if w < CONFIRM_BELOW {
            for _ in 0..THIN_NEWTON {
                if SAFETY * (rate.0 + delta * rate.1) * step.abs() <= 0.5 * traction_tol {
                    break;
                }
                let Some((next, next_system)) =
                    solved_at(k, lc + step, Sizes::at(level, c, w), check)
                else {
                    break;
                };
                let next_step = -next.sigma / slope;
                if next_step.abs() > 0.5 * step.abs() {
                    break;
                }
                (lc, cur, system, step) = (lc + step, next, next_system, next_step);
            }
        }
        let edge = StickEdge::from_logit(lc);
        let root = lc + step;
        if let Some((held, held_root)) = candidate.take() {
            let moved = StickEdge::from_logit(root).distance(StickEdge::from_logit(held_root));
            if moved <= held.error {
                return Some(held);
            }
        }
        let distance_c = StickEdge::from_logit(root).distance(StickEdge::from_logit(prev_root));
        let mut error = SAFETY * (distance_c + c * w * (step.abs() + prev_step.abs()));
        let compared = level_distance(&cur, &prev);
        let (dp, dq) = compared.parts;
        let mut parts = (
            SAFETY * (dp + rate.0 * step.abs()),
            SAFETY * (dq + rate.1 * step.abs()),
        );
        let meets = |error: f64, parts: (f64, f64)| {
            error <= tol
                && parts.0 + delta * parts.1 <= traction_tol
                && cur.residual <= traction_tol
        };
        if meets(error, parts)
            && let Some(system) = &system
        {
            // the level's rounding spread, counted once the level meets its estimates (a
            // failed second solve: no answer at this level)
            match rounding_spread(system, &cur, slope, rate) {
                Some(spread) => {
                    error += SAFETY * c * w * spread.dlc;
                    parts.0 += SAFETY * spread.parts.0;
                    parts.1 += SAFETY * spread.parts.1;
                }
                None => error = f64::INFINITY,
            }
        }
        if meets(error, parts) {
            match verdict(compared.noise, traction_tol, delta, parts) {
                Verdict::Answer(parts) => {
                    let answer = Spectral {
                        edge,
                        error,
                        traction_parts: parts,
                        fixed: cur.clone(),
                        level,
                    };
                    if w >= CONFIRM_BELOW {
                        return Some(answer);
                    }
                    candidate = Some((answer, root));
                }
                Verdict::Inadmissible => return None,
                Verdict::Noisy => {}
            }
        }
        stalled = if level > FIRST_LEVEL + 1 && step.abs() > 0.5 * prev_step.abs() {
            stalled + 1
        } else {
            0
        };
        if stalled >= STALLED_LEVELS
            && SAFETY * (rate.0 + delta * rate.1) * step.abs() > traction_tol
        {
            return None;
        }
        (prev, prev_root, prev_step) = (cur, root, step);
        lc = root;
    }
    None
}

/// The fixed-c system at lc for `sizes`, solved (None where it fails or sigma is not
/// finite), with the assembled system kept where `keep` (for [`rounding_spread`]).
fn solved_at(
    k: Constants,
    lc: f64,
    sizes: Sizes,
    keep: bool,
) -> Option<(Fixed, Option<Assembled>)> {
    let e = StickEdge::from_logit(lc);
    let system = Assembled::new(k, e.c, e.one_minus_c, sizes);
    let fixed = system.solve().ok()?;
    fixed.sigma.is_finite().then_some(())?;
    Some((fixed, keep.then_some(system)))
}

/// A level's spread under rounding ([`rounding_spread`]).
struct Spread {
    /// Its root's spread in lc, |d sigma| / |slope|.
    dlc: f64,
    /// Its tractions' spread, (int |dp|, int |dq~|): at the level's lc, plus their move per
    /// lc over `dlc`.
    parts: (f64, f64),
}

/// The rounding check of a thin slip zone's level (docs/theory_spectral.md, (S10)): the
/// level's system `system` solved again with its rows in reverse order, whose answer differs
/// from `cur` (the rows as assembled) only by rounding; its distance from `cur` (graded, as
/// the thin slip zones' levels are compared), and sigma's difference carried to the root
/// through the slope and to the tractions through their move per lc `rate`. None where
/// the second solve fails.
fn rounding_spread(
    system: &Assembled,
    cur: &Fixed,
    slope: f64,
    rate: (f64, f64),
) -> Option<Spread> {
    let other = reversed_rows(system)?;
    let dlc = (other.sigma - cur.sigma).abs() / slope.abs();
    let (dp, dq) = graded_distance(&other, cur).parts;
    Some(Spread {
        dlc,
        parts: (dp + rate.0 * dlc, dq + rate.1 * dlc),
    })
}

/// The system `system` solved with its rows in reverse order (None where that fails or sigma
/// is not finite): the same least squares in another rounding.
fn reversed_rows(system: &Assembled) -> Option<Fixed> {
    let order: Vec<usize> = (0..system.rows()).rev().collect();
    let other = system.solve_rows(&order).ok()?;
    other.sigma.is_finite().then_some(other)
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

/// The verdict on a level whose estimates `parts` meet `traction_tol`, from its rounding
/// noise as [`distance`] or [`graded_distance`] saw it (None: not admissible): the noise, an
/// L1 error in p and q~ ([`Check`]), is added to the estimate.
fn verdict(noise: Option<(f64, f64)>, traction_tol: f64, delta: f64, parts: (f64, f64)) -> Verdict {
    let Some(noise) = noise else {
        return Verdict::Inadmissible;
    };
    let parts = (parts.0 + noise.0, parts.1 + noise.1);
    if parts.0 + delta * parts.1 <= traction_tol {
        Verdict::Answer(parts)
    } else {
        Verdict::Noisy
    }
}

/// Gauss-Legendre points per zone of [`distance`]. The distance is an L1 norm of a difference
/// that changes sign (a kink per sign change, so the rule converges algebraically) and only
/// has to be right to a fraction of itself: it is doubled into the estimate ([`SAFETY`]),
/// which the true error stayed below by factors of 12-300 on the speed scenes. Measured on
/// the 10 spectral speed scenes (c to 1e-10; thread CPU time, median over the scenes, the
/// three alternated in one run; estimates relative to 48 points):
///
/// | points | tractions 1e-8 | estimate / 48's | 1e-10 | estimate / 48's |
/// |---|---|---|---|---|
/// | 48 | 0.187 ms | 1 | 0.406 ms | 1 |
/// | 32 | 0.178 ms | 0.94 .. 1.2 | 0.389 ms | 0.98 .. 1.07 |
/// | 24 | 0.172 ms | 0.95 .. 1.3 | 0.381 ms | 0.94 .. 1.09 |
///
/// (every answer at the same level with each; largest true error / estimate 0.040 at 1e-8,
/// 0.083 at 1e-10 with 32 points). 32 keeps a margin for the admissibility check, which
/// looks at the same points.
const DISTANCE_POINTS: usize = 32;

/// What [`distance`] measures between a level and another solution, and what it sees of the
/// level on the way.
#[derive(Clone, Copy)]
struct Compared {
    /// (int |dp|, int |dq~|) over (-1, 1).
    parts: (f64, f64),
    /// The level's rounding noise (int |noise of p|, int |noise of q~|) over (-1, 1) by the
    /// same rule ([`Fixed::probe_both`]), or None where it is not admissible there.
    noise: Option<(f64, f64)>,
}

/// The admissibility check over a rule's points: p > 0 everywhere and |q| <= mu p on the
/// stick zone (to 1e-6 relative), with the rounding noise there as the estimates take it
/// ([`verdict`]):
/// - integrated by the rule's weights, (int |noise of p|, int |noise of q~|) over (-1, 1)
///   ([`distance`]): the L1 norm of the tractions' own rounding, as the estimates measure
///   their error;
/// - in thin slip zones ([`graded_distance`]) the largest noise relative to p, taken as
///   an L1 error of that size in p (int p = 1) and of mu~ times it in q~ (|q| <= mu p): the
///   bound before the integrated one, kept there because it is also the margin that the
///   thin zones' traction estimates need (docs/theory_spectral.md (R2), "Integrated"):
///   at b* = 0.25, 1 - c = 1.3e-7, levels 2-8 at the panels' c lie within 1e-12 .. 1e-11
///   of each other and 3.2e-11 .. 3.6e-11 from the panels, and with the integrated noise
///   the answers at (1e-10, 1e-10) lay up to 1.35 times their estimates from the panels.
struct Check {
    mu: f64,
    integrate: bool,
    noise: Option<(f64, f64)>,
}

impl Check {
    fn new(mu: f64, integrate: bool) -> Self {
        Check {
            mu,
            integrate,
            noise: Some((0.0, 0.0)),
        }
    }

    fn see(&mut self, at: &points::Pt, weight: f64, (p, q, noise): (f64, f64, Noise)) {
        let ok = p > 0.0 && (!at.on_stick() || q.abs() <= self.mu * p * (1.0 + 1e-6));
        let (integrate, mu) = (self.integrate, self.mu);
        self.noise = self.noise.filter(|_| ok).map(|(np, nq)| {
            if integrate {
                (np + weight * noise.p, nq + weight * noise.q)
            } else {
                let relative = noise.p.max(noise.q / mu) / p.abs();
                (np.max(relative), nq.max(mu * relative))
            }
        });
    }

    /// The noise over (-1, 1) as an L1 error (the integral over the half line doubled).
    fn noise(&self) -> Option<(f64, f64)> {
        let factor = if self.integrate { 2.0 } else { 1.0 };
        self.noise.map(|(np, nq)| (factor * np, factor * nq))
    }
}

/// (int |dp|, int |dq|) over (-1, 1) between a level `a` and another solution `b` (the norm
/// of [`crate::problem::traction_distance`]), with `a`'s admissibility and noise at the same
/// points. Each zone by [`DISTANCE_POINTS`] Gauss-Legendre points in its own variable: on the
/// stick zone tau = x / c over its half (0, 1); on the slip zone u with 1 - x = (1 - c) u^m,
/// m = 1 / (1 - g), in which the edge's (1 - x)^-g dx is (1 - c) m du, so the tractions'
/// edge singularity leaves a smooth integrand. Each solution is evaluated at its own offsets
/// from its own stick edge (theirs differ by the levels' error in c).
fn distance(a: &Fixed, b: &Fixed) -> Compared {
    use points::Pt;
    let (c, w, g) = (a.basis.c, a.basis.w, a.basis.k.g);
    let rule = gauss_legendre_rule(DISTANCE_POINTS);
    let (t, wt) = (&rule.0, &rule.1);
    let mut work = Vec::new();
    let mut check = Check::new(a.basis.k.mu, true);
    let (mut dp, mut dq) = (0.0, 0.0);
    for (&t, &wt) in t.iter().zip(wt) {
        let x = 0.5 * c * (1.0 + t);
        let ((pa, qa, noise), (pb, qb)) = a.probe_both(b, |f| Pt::at(x, f.basis.c), &mut work);
        check.see(&Pt::at(x, c), 0.5 * c * wt, (pa, qa, noise));
        dp += 0.5 * c * wt * (pa - pb).abs();
        dq += 0.5 * c * wt * (qa - qb).abs();
    }
    let m = 1.0 / (1.0 - g);
    for (&t, &wt) in t.iter().zip(wt) {
        let u = 0.5 * (1.0 + t);
        let um = u.powf(m);
        let omx = w * um;
        let ((pa, qa, noise), (pb, qb)) =
            a.probe_both(b, |f| Pt::from_end(omx, f.basis.w), &mut work);
        let jac = 0.5 * wt * w * m * um / u;
        check.see(&Pt::from_end(omx, w), jac, (pa, qa, noise));
        dp += jac * (pa - pb).abs();
        dq += jac * (qa - qb).abs();
    }
    Compared {
        parts: (2.0 * dp, 2.0 * dq),
        noise: check.noise(),
    }
}

/// The distance between a level `a` and another solution `b` as the estimates take it:
/// [`graded_distance`] where `a`'s slip zone is thinner than [`CONFIRM_BELOW`], else
/// [`distance`].
fn level_distance(a: &Fixed, b: &Fixed) -> Compared {
    if a.basis.w < CONFIRM_BELOW {
        graded_distance(a, b)
    } else {
        distance(a, b)
    }
}

/// [`distance`] for a thin slip zone (1 - c < [`CONFIRM_BELOW`]), where the stick zone's
/// tractions vary on the scale 1 - c next to x = c and [`DISTANCE_POINTS`] Gauss points in tau
/// do not see it: 20-point Gauss-Legendre panels graded by factors of 3 in the distance from x
/// = c (on both sides, from 1e-14 of the zone) and from x = 1, and one panel over the stick
/// zone's inner half; `a`'s admissibility and noise at the same points.
fn graded_distance(a: &Fixed, b: &Fixed) -> Compared {
    use points::Pt;
    let (c, w) = (a.basis.c, a.basis.w);
    let rule = gauss_legendre_rule(20);
    let (t, wt) = (&rule.0, &rule.1);
    let mut work = Vec::new();
    let mut check = Check::new(a.basis.k.mu, false);
    let (mut sp, mut sq) = (0.0, 0.0);
    // panels (kind, d_lo, d_hi) in the offset d from x = c (kinds 0, 2), 0 (1) or 1 (3)
    let mut panels: Vec<(u8, f64, f64)> = Vec::new();
    let grade = |panels: &mut Vec<(u8, f64, f64)>, kind: u8, len: f64| {
        let (mut prev, mut d) = (0.0, 1e-14 * len);
        while d < 0.5 * len {
            panels.push((kind, prev, d));
            prev = d;
            d *= 3.0;
        }
        panels.push((kind, prev, 0.5 * len));
    };
    // stick: x = c - d (d up to c / 2) and x = d (the centre half); slip: x = c + d, x = 1 - d
    grade(&mut panels, 0, c);
    panels.push((1, 0.0, 0.5 * c));
    grade(&mut panels, 2, w);
    grade(&mut panels, 3, w);
    for (kind, lo, hi) in panels {
        for (x, ww) in t.iter().zip(wt) {
            let d = lo + (hi - lo) * 0.5 * (x + 1.0);
            let pt = match kind {
                0 => Pt {
                    x: c - d,
                    omx: w + d,
                    xmc: -d,
                },
                1 => Pt {
                    x: d,
                    omx: 1.0 - d,
                    xmc: d - c,
                },
                2 => Pt {
                    x: c + d,
                    omx: w - d,
                    xmc: d,
                },
                _ => Pt::from_end(d, w),
            };
            let ((pa, qa, noise), (pb, qb)) = a.probe_both(b, |_| pt, &mut work);
            check.see(&pt, ww * 0.5 * (hi - lo), (pa, qa, noise));
            sp += ww * 0.5 * (hi - lo) * (pa - pb).abs();
            sq += ww * 0.5 * (hi - lo) * (qa - qb).abs();
        }
    }
    Compared {
        parts: (2.0 * sp, 2.0 * sq),
        noise: check.noise(),
    }
}
