//! Model error of the closed-form approximations: bounds on |c_approx - c_exact| for
//! Goodman's and Spence's c, used for their error estimates and by METHOD_AUTO.
//!
//! c depends on the material and the friction only through (b*, mu~) (THEORY.md section 4),
//! for the approximations as for the exact problem, so the model error is a function on that
//! plane. It is tabulated offline by the COUPLED solver on a grid of b* and log10 mu~
//! (`cargo run --release --example model_error_table` regenerates `table.rs`;
//! `tests/model_error_table.rs` recomputes every entry and checks the committed table).
//!
//! Why a table and not an a-posteriori residual: the residual of eq. (10) for Goodman's p0 is
//! bp q, known at once, but turning it into a bound on c needs the sensitivity of c to the
//! pressure near the edges, i.e. the coupled solve itself; a table costs a lookup and its
//! bound is checked against the exact solution on the whole plane by the tests.
//!
//! The bound at a point is [`SAFETY`] times the largest tabulated error around it (see
//! [`bound`]: the errors vary smoothly in b* and log mu~ away from their sign changes, where
//! they are small), plus [`FLOOR`], the accuracy of the tabulated reference.

#[rustfmt::skip]
mod table;

use crate::coupled;
use crate::error::Result;
use crate::problem::{Coupling, Profile, StickEdge};
use crate::{goodman, spence};

/// The closed-form approximations whose model error is tabulated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Approximation {
    /// Goodman's approximation.
    Goodman,
    /// Spence's approximation.
    Spence,
}

/// Multiplier on the tabulated errors.
pub const SAFETY: f64 = 2.0;

/// Tolerance of the COUPLED reference the table is made with (absolute, in c).
pub const FLOOR: f64 = 1e-10;

pub use table::{B_STAR, LOG10_MU};

/// One approximation's tabulated errors: rows over [`B_STAR`], columns over [`LOG10_MU`].
pub type Grid = [[f64; LOG10_MU.len()]; B_STAR.len()];

/// The tabulated model errors of an approximation.
pub fn tabulated(a: Approximation) -> &'static Grid {
    match a {
        Approximation::Goodman => &table::GOODMAN,
        Approximation::Spence => &table::SPENCE,
    }
}

/// The grid interval [i, i + 1] holding v (clamped to the ends).
fn interval(grid: &[f64], v: f64) -> (usize, usize) {
    match grid.partition_point(|&g| g <= v) {
        0 => (0, 0),
        i if i == grid.len() => (i - 1, i - 1),
        i => (i - 1, i),
    }
}

/// A bound on |c_approx - c_exact| for the approximation at the coupling k, or None where
/// the table gives none (b* outside the rows, or the reference failed nearby).
///
/// Inside the grid: the largest error at the cell's corners. Below the first column (mu~
/// smaller): c grows with mu~ for every method, so |c_approx - c_exact| <= max of the c's
/// at the first column ([`table::BELOW`]). Above the last column: 1 - c falls with mu~, so
/// the error is at most the largest 1 - c at the last column ([`table::ABOVE`]).
pub fn bound(a: Approximation, k: &Coupling) -> Option<f64> {
    if k.mu == 0.0 {
        return Some(0.0); // every method gives c = 0 exactly
    }
    let (reduced, _) = k.reduced();
    let (b, l) = (reduced.bp, reduced.mu.log10());
    if !(B_STAR[0]..=B_STAR[B_STAR.len() - 1]).contains(&b) {
        return None;
    }
    let (i0, i1) = interval(&B_STAR, b);
    let worst = if l < LOG10_MU[0] {
        table::BELOW[i0].max(table::BELOW[i1])
    } else if l > LOG10_MU[LOG10_MU.len() - 1] {
        table::ABOVE[i0].max(table::ABOVE[i1])
    } else {
        let (j0, j1) = interval(&LOG10_MU, l);
        let e = tabulated(a);
        e[i0][j0].max(e[i0][j1]).max(e[i1][j0]).max(e[i1][j1])
    };
    worst.is_finite().then_some(SAFETY * worst + FLOOR)
}

/// What one COUPLED reference solve at (b*, mu~) gives the table.
#[derive(Clone, Copy, Debug)]
pub struct Sample {
    /// |c_goodman - c_exact|.
    pub goodman: f64,
    /// |c_spence - c_exact|.
    pub spence: f64,
    /// The largest c of the three methods.
    pub max_c: f64,
    /// The largest 1 - c of the three methods.
    pub max_one_minus_c: f64,
}

/// |c_a - c_b|, from whichever of c and 1 - c keeps its accuracy.
fn distance(a: StickEdge, b: StickEdge) -> f64 {
    if a.c.max(b.c) > 0.5 {
        (a.one_minus_c - b.one_minus_c).abs()
    } else {
        (a.c - b.c).abs()
    }
}

/// The model errors at (b*, mu~), with c_exact from COUPLED to [`FLOOR`]: the generator of
/// the table and of its test.
pub fn sample(b_star: f64, mu_tilde: f64) -> Result<Sample> {
    let k = Coupling {
        bp: b_star,
        bq: b_star,
        mu: mu_tilde,
    };
    let exact = coupled::solve(&k, FLOOR)?.edge();
    let g = goodman::solve(&k)?.edge();
    let s = spence::solve(&k)?.edge();
    Ok(Sample {
        goodman: distance(g, exact),
        spence: distance(s, exact),
        max_c: exact.c.max(g.c).max(s.c),
        max_one_minus_c: exact.one_minus_c.max(g.one_minus_c).max(s.one_minus_c),
    })
}

/// The source text of `table.rs` for the given grids (used by the generator example). Each
/// value is rounded up to two significant digits; inf where the reference failed.
pub fn table_source(b_star: &[f64], log10_mu: &[f64]) -> String {
    use std::fmt::Write as _;
    let samples: Vec<Vec<Option<Sample>>> = b_star
        .iter()
        .map(|&b| {
            log10_mu
                .iter()
                .map(|&l| sample(b, 10f64.powf(l)).ok())
                .collect()
        })
        .collect();
    let num = |v: Option<f64>| match v {
        Some(v) if v.is_finite() => format!("{:.1e}", round_up(v)),
        _ => "f64::INFINITY".into(),
    };
    let list = |v: Vec<String>| v.join(", ");
    let mut s = String::from(
        "//! Generated by `cargo run --release --example model_error_table`; do not edit.\n\
         //! Model errors |c_approx - c_exact| on the grid (b*, log10 mu~), rounded up to two\n\
         //! significant digits; inf where the COUPLED reference failed.\n\n",
    );
    let (nb, nl) = (b_star.len(), log10_mu.len());
    let grid = |v: &[f64]| list(v.iter().map(|x| format!("{x:?}")).collect());
    writeln!(
        s,
        "/// Rows: b*.\npub const B_STAR: [f64; {nb}] = [{}];",
        grid(b_star)
    )
    .ok();
    writeln!(
        s,
        "/// Columns: log10 mu~.\npub const LOG10_MU: [f64; {nl}] = [{}];",
        grid(log10_mu)
    )
    .ok();
    type Pick = fn(&Sample) -> f64;
    for (name, pick) in [
        ("GOODMAN", (|x| x.goodman) as Pick),
        ("SPENCE", |x| x.spence),
    ] {
        writeln!(
            s,
            "\n/// Model error of {name}.\npub(super) const {name}: [[f64; {nl}]; {nb}] = ["
        )
        .ok();
        for row in &samples {
            let cells = row.iter().map(|x| num(x.as_ref().map(pick))).collect();
            writeln!(s, "    [{}],", list(cells)).ok();
        }
        s.push_str("];\n");
    }
    let below = samples.iter().map(|r| num(r[0].map(|x| x.max_c))).collect();
    let above = samples
        .iter()
        .map(|r| num(r[nl - 1].map(|x| x.max_one_minus_c)))
        .collect();
    writeln!(s, "\n/// Largest c of the three methods at the first column.\npub(super) const BELOW: [f64; {nb}] = [{}];", list(below)).ok();
    writeln!(s, "\n/// Largest 1 - c of the three methods at the last column.\npub(super) const ABOVE: [f64; {nb}] = [{}];", list(above)).ok();
    s
}

/// v rounded up to two significant digits (0 stays 0): the decimal printed with `{:.1e}`
/// is >= v.
pub fn round_up(v: f64) -> f64 {
    if v <= 0.0 {
        return 0.0;
    }
    let scale = 10f64.powi(v.log10().floor() as i32 - 1);
    let r: f64 = format!("{:.1e}", (v / scale).ceil() * scale)
        .parse()
        .unwrap_or(v);
    if r < v {
        // The next two-digit decimal up (the printed neighbour fell below v).
        format!("{:.1e}", r + scale).parse().unwrap_or(v)
    } else {
        r
    }
}
