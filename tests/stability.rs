//! Behaviour at the edges of the (b*, mu~) plane (docs/theory.md §4-§6) and of the
//! engineering constants that lead there: mu -> 0 and -> infinity, bp mu large, A -> 0
//! (nu -> 1), kappa = 1 and kappa -> -nu, delta far from 1, near-incompressible plane strain,
//! auxetic b* -> 1. Every method, called directly and through `Contact`, must return either a
//! valid edge (0 <= c <= 1, c = 1 only as the rounding of a tiny 1 - c, 0 < 1 - c <= 1, finite
//! estimate) with finite tractions, or a clear error (NoConvergence, NoAdmissibleSolution,
//! ToleranceNotMet or InvalidArgument with a message) — never NaN, never a panic. An error estimate may be
//! +infinity ("no bound known", e.g. GOODMAN beyond the model-error table), never NaN. The error
//! estimates (LCP, COUPLED: `numerical_error`; GOODMAN, SPENCE: plus `model_error::bound`) must
//! bound the true error against a tighter COUPLED run wherever both exist on a small grid.
//!
//! `cargo run --release --example stability_map` maps the same behaviour over the whole plane.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::OnceLock;

use orthoslip::model_error::{self, Approximation};

#[path = "../examples/support/parallel.rs"]
mod parallel;
use orthoslip::{
    Contact, Coupling, Error, Material, Method, Profile, StickEdge, coupled, goodman, lcp, spence,
};

/// Panels of the LCP runs (its cheapest grid).
const LCP_PANELS: usize = 100;
/// Tolerance of the COUPLED runs under test, and of the reference they are checked against.
const COUPLED_TOL: f64 = 1e-8;
const REFERENCE_TOL: f64 = 1e-12;
/// Points where the tractions are evaluated, with their mirror images (q is odd; at x = 0 it
/// jumps when c = 0, so only finiteness is asked there).
const XS: [f64; 5] = [0.0, 0.3, 0.7, 0.95, 0.999];

const E: f64 = 70e9;

/// The edge scenes: name, material and friction coefficient.
fn edge_scenes() -> Vec<(&'static str, Material, f64)> {
    let m = |nu: f64, delta: f64, kappa: f64| Material::effective(E, nu, delta, kappa).unwrap();
    let steel = m(0.3, 1.0, 1.0);
    vec![
        ("mu = 0", steel, 0.0),
        ("mu = 1e-4", steel, 1e-4),
        ("mu = 1e3", steel, 1e3),
        ("b* = 0.9, mu = 100", m(-0.8, 1.0, 1.0), 100.0),
        ("A -> 0 (nu = 1 - 1e-9)", m(1.0 - 1e-9, 1.0, 1.0), 0.3),
        ("kappa = 1, delta = 2", m(0.3, 2.0, 1.0), 0.3),
        ("kappa = -nu + 1e-12", m(0.3, 1.0, -0.3 + 1e-12), 0.3),
        ("delta = 1e-3", m(0.3, 1e-3, 1.0), 0.3),
        ("delta = 1e3", m(0.3, 1e3, 1.0), 0.3),
        (
            "plane strain nu = 0.499",
            Material::plane_strain(E, E, E, E / 2.998, 0.499, 0.499, 0.499).unwrap(),
            0.3,
        ),
        ("auxetic b* = 0.99 (nu = -0.98)", m(-0.98, 1.0, 1.0), 0.3),
    ]
}

/// The methods called directly.
#[derive(Clone, Copy, Debug)]
enum Solver {
    Goodman,
    Spence,
    Lcp,
    Coupled,
}

const SOLVERS: [Solver; 4] = [
    Solver::Goodman,
    Solver::Spence,
    Solver::Lcp,
    Solver::Coupled,
];

fn solve(s: Solver, k: &Coupling, tol: f64) -> orthoslip::Result<Box<dyn Profile>> {
    Ok(match s {
        Solver::Goodman => Box::new(goodman::solve(k)?),
        Solver::Spence => Box::new(spence::solve(k)?),
        Solver::Lcp => Box::new(lcp::solve(k, LCP_PANELS)?),
        Solver::Coupled => Box::new(coupled::solve(k, tol)?),
    })
}

/// What can go wrong with one answer.
#[derive(Debug, PartialEq)]
enum Violation {
    /// 1 - c underflowed to 0 (c = 1): the edge no longer says how wide the slip zones are.
    SlipUnderflow,
    /// Anything else: NaN, out-of-range edge, non-finite tractions, unclear error, panic.
    Broken(String),
}

/// The error must be one of the expected kinds, with a message.
fn check_error(e: &Error) -> Option<Violation> {
    let ok = match e {
        Error::NoConvergence(m) | Error::NoAdmissibleSolution(m) | Error::InvalidArgument(m) => {
            !m.trim().is_empty()
        }
        Error::ToleranceNotMet {
            estimate,
            tolerance,
            detail,
        } => !detail.trim().is_empty() && estimate > tolerance && *tolerance > 0.0,
        Error::InadmissibleMaterial(_) | Error::Internal(_) => false,
    };
    (!ok).then(|| Violation::Broken(format!("unexpected error {e:?}")))
}

/// The edge (c, 1 - c) and estimate (>= 0, possibly +infinity, not NaN) must be valid.
fn check_edge(c: f64, w: f64, estimate: f64) -> Option<Violation> {
    if c == 1.0 && w == 0.0 {
        return Some(Violation::SlipUnderflow);
    }
    let valid = (0.0..=1.0).contains(&c)
        && (c < 1.0 || w <= f64::EPSILON)
        && w > 0.0
        && w <= 1.0
        && ((c + w) - 1.0).abs() <= 4.0 * f64::EPSILON
        && estimate >= 0.0;
    (!valid).then(|| Violation::Broken(format!("c = {c}, 1 - c = {w}, estimate = {estimate}")))
}

/// Tractions at +-x must be finite, p even, q odd (the sign of p is checked separately:
/// see `lcp_on_the_physical_branch_for_strong_orthotropy`).
fn check_tractions(tr: impl Fn(f64) -> (f64, f64)) -> Option<Violation> {
    for x in XS {
        let ((p, q), (pm, qm)) = (tr(x), tr(-x));
        let valid =
            [p, q, pm, qm].iter().all(|v| v.is_finite()) && pm == p && (x == 0.0 || qm == -q);
        if !valid {
            return Some(Violation::Broken(format!(
                "tractions at x = +-{x}: ({p}, {q}), ({pm}, {qm})"
            )));
        }
    }
    None
}

/// The contract for one direct solve (panics caught).
fn check_direct(s: Solver, k: &Coupling) -> Option<Violation> {
    catch_unwind(AssertUnwindSafe(|| match solve(s, k, COUPLED_TOL) {
        Err(e) => check_error(&e),
        Ok(p) => {
            let e = p.edge();
            check_edge(e.c, e.one_minus_c, p.numerical_error())
                .or_else(|| check_tractions(|x| p.tractions(x)))
        }
    }))
    .unwrap_or_else(|_| Some(Violation::Broken("panicked".into())))
}

/// The contract for one scene-level solve (panics caught).
fn check_contact(contact: &Contact, method: Method) -> Option<Violation> {
    catch_unwind(AssertUnwindSafe(|| match contact.solve() {
        Err(e) => check_error(&e),
        Ok(s) => {
            let right_method =
                s.method() != Method::Auto && (method == Method::Auto || s.method() == method);
            let mu = s.coupling().mu;
            let (p1, q1) = s.tractions(1.0);
            let ends = p1 == f64::INFINITY
                && if mu == 0.0 {
                    q1 == 0.0
                } else {
                    q1 == f64::INFINITY
                }
                && s.tractions(1.5) == (0.0, 0.0);
            if !(right_method && ends) {
                return Some(Violation::Broken(format!(
                    "method {:?}, tractions at x = 1: ({p1}, {q1})",
                    s.method()
                )));
            }
            check_edge(s.c(), s.one_minus_c(), s.error_estimate())
                .or_else(|| check_tractions(|x| s.tractions(x)))
        }
    }))
    .unwrap_or_else(|_| Some(Violation::Broken("panicked".into())))
}

/// Every (scene, method) whose answer breaks the contract, with the violation.
fn direct_violations() -> Vec<(String, Violation)> {
    let mut out = Vec::new();
    for (name, material, mu) in edge_scenes() {
        let k = material.coupling(mu);
        for s in SOLVERS {
            if let Some(v) = check_direct(s, &k) {
                out.push((format!("{name}, {s:?}"), v));
            }
        }
    }
    out
}

fn report(violations: &[(String, Violation)]) -> String {
    violations
        .iter()
        .map(|(w, v)| format!("{w}: {v:?}"))
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn every_method_gives_a_valid_edge_or_a_clear_error_at_the_edges() {
    let broken: Vec<_> = direct_violations()
        .into_iter()
        .filter(|(_, v)| *v != Violation::SlipUnderflow)
        .collect();
    assert!(broken.is_empty(), "{}", report(&broken));
}

#[test]
fn frictionless_contact_has_no_stick_zone_and_no_shear() {
    let steel = Material::effective(E, 0.3, 1.0, 1.0).unwrap();
    let k = steel.coupling(0.0);
    for s in SOLVERS {
        let p = solve(s, &k, COUPLED_TOL).unwrap_or_else(|e| panic!("{s:?}: {e}"));
        let e = p.edge();
        assert!(e.c == 0.0 && e.one_minus_c == 1.0, "{s:?}: {e:?}");
        for x in XS {
            let (pp, q) = p.tractions(x);
            assert!(
                pp.is_finite() && pp > 0.0 && q == 0.0,
                "{s:?} at {x}: ({pp}, {q})"
            );
        }
    }
}

#[test]
fn scene_level_gives_a_valid_solution_or_a_clear_error_at_the_edges() {
    let mut broken = Vec::new();
    for (name, material, mu) in edge_scenes() {
        let mut contact = Contact::new(material);
        contact.set_friction(mu).unwrap();
        // loose: LCP's first grids meet it, so no scene runs the large LCP grids
        contact.set_tolerance(1e-2).unwrap();
        for method in Method::ALL {
            contact.set_method(method);
            match check_contact(&contact, method) {
                None | Some(Violation::SlipUnderflow) => {}
                Some(v) => broken.push((format!("{name}, {method:?}"), v)),
            }
        }
    }
    assert!(broken.is_empty(), "{}", report(&broken));
}

#[test]
fn invalid_inputs_give_invalid_argument_with_a_message() {
    let invalid = |e: &Error| matches!(e, Error::InvalidArgument(m) if !m.trim().is_empty());
    let mut contact = Contact::new(Material::effective(E, 0.3, 1.0, 1.0).unwrap());
    for mu in [f64::NAN, -1e-3, f64::INFINITY] {
        assert!(invalid(&contact.set_friction(mu).unwrap_err()), "mu = {mu}");
    }
    for tol in [0.0, 1.0, f64::NAN, -1.0] {
        assert!(
            invalid(&contact.set_tolerance(tol).unwrap_err()),
            "tol = {tol}"
        );
    }
    for k in [
        Coupling {
            bp: 0.3,
            bq: 0.3,
            mu: f64::NAN,
        },
        Coupling {
            bp: 0.3,
            bq: 0.3,
            mu: -0.1,
        },
        Coupling {
            bp: 0.3,
            bq: 0.0,
            mu: 0.3,
        },
    ] {
        for s in SOLVERS {
            let r = catch_unwind(|| solve(s, &k, COUPLED_TOL).map(|p| p.edge()));
            match r {
                Ok(Err(e)) => assert!(invalid(&e), "{s:?} at {k:?}: {e:?}"),
                other => panic!("{s:?} at {k:?}: {other:?}"),
            }
        }
    }
    // b* = 1 is outside the admissible range: valid edge or clear error, never a panic
    let k = Coupling {
        bp: 1.0,
        bq: 1.0,
        mu: 0.3,
    };
    for s in SOLVERS {
        assert_eq!(check_direct(s, &k), None, "{s:?} at b* = 1");
    }
    // the limits themselves are inadmissible materials
    for (nu, kappa) in [(0.3, -0.3), (1.0, 1.0), (-1.0, 1.0)] {
        let e = Material::effective(E, nu, 1.0, kappa).unwrap_err();
        assert!(
            matches!(&e, Error::InadmissibleMaterial(m) if !m.is_empty()),
            "nu = {nu}, kappa = {kappa}: {e:?}"
        );
    }
}

/// |c_a - c_b| from whichever of c, 1 - c is small.
fn edge_error(a: &dyn Profile, b: &dyn Profile) -> f64 {
    a.edge().distance(b.edge())
}

/// Method `s`'s error estimate at k: `numerical_error`, plus the model-error bound for the
/// approximations (None where the table gives none).
fn estimate(s: Solver, k: &Coupling, p: &dyn Profile) -> Option<f64> {
    let model = match s {
        Solver::Goodman => model_error::bound(Approximation::Goodman, k)?,
        Solver::Spence => model_error::bound(Approximation::Spence, k)?,
        Solver::Lcp | Solver::Coupled => 0.0,
    };
    Some(p.numerical_error() + model)
}

/// The reference stick edges at the points of `grid` (COUPLED at [`REFERENCE_TOL`]),
/// computed once for the four estimate checks that share them, spread over the machine's
/// cores.
fn grid_references(grid: Grid) -> &'static [((f64, f64), Option<StickEdge>)] {
    type Refs = OnceLock<Vec<((f64, f64), Option<StickEdge>)>>;
    static DIAGONAL: Refs = OnceLock::new();
    static FULL: Refs = OnceLock::new();
    let cache = match grid {
        Grid::Diagonal => &DIAGONAL,
        Grid::Full => &FULL,
    };
    cache.get_or_init(|| {
        parallel::map(&grid.points(), |&(b, mu)| {
            let k = Coupling { bp: b, bq: b, mu };
            (
                (b, mu),
                coupled::solve(&k, REFERENCE_TOL).ok().map(|r| r.edge()),
            )
        })
    })
}

/// Method `s`'s estimate against its true error at each (b*, mu~) of `grid` where it, its
/// estimate and the reference exist: (label, estimate, true error). The points are spread
/// over the machine's cores.
fn estimates_against_reference(s: Solver, grid: Grid) -> Vec<(String, f64, f64)> {
    parallel::map(grid_references(grid), |&((b, mu), reference)| {
        let k = Coupling { bp: b, bq: b, mu };
        let reference = reference?;
        let p = solve(s, &k, COUPLED_TOL).ok()?;
        Some((
            format!("b* = {b}, mu~ = {mu}"),
            estimate(s, &k, p.as_ref())?,
            p.edge().distance(reference),
        ))
    })
    .into_iter()
    .flatten()
    .collect()
}

fn check_bounds(s: Solver, grid: Grid, min_compared: usize) {
    let rows = estimates_against_reference(s, grid);
    for (label, est, err) in &rows {
        println!("{s:?} {label}: estimate {est:.2e}, true error {err:.2e}");
    }
    assert!(
        rows.len() >= min_compared,
        "{s:?}: only {} points with a reference",
        rows.len()
    );
    let missed: Vec<_> = rows
        .iter()
        .filter(|(_, est, err)| *err > est + REFERENCE_TOL)
        .collect();
    assert!(
        missed.is_empty(),
        "{s:?}: estimate below true error at {missed:?}"
    );
}

/// The grids of the estimate checks: b* = 0.1, 0.5, 0.9 against mu~ = 0.2, 1, 5, in full (the
/// slow tier) or along the diagonal (the fast tier).
#[derive(Clone, Copy, Debug)]
enum Grid {
    Diagonal,
    Full,
}

impl Grid {
    fn points(self) -> Vec<(f64, f64)> {
        let (bs, mus) = ([0.1, 0.5, 0.9], [0.2, 1.0, 5.0]);
        match self {
            Grid::Diagonal => bs.into_iter().zip(mus).collect(),
            Grid::Full => bs.into_iter().flat_map(|b| mus.map(|mu| (b, mu))).collect(),
        }
    }
}

#[test]
fn goodman_model_error_bound_holds() {
    check_bounds(Solver::Goodman, Grid::Diagonal, 2);
}

#[test]
fn spence_model_error_bound_holds() {
    check_bounds(Solver::Spence, Grid::Diagonal, 2);
}

#[test]
fn coupled_estimate_bounds_its_error() {
    check_bounds(Solver::Coupled, Grid::Diagonal, 2);
}

#[test]
fn lcp_estimate_bounds_its_error() {
    check_bounds(Solver::Lcp, Grid::Diagonal, 2);
}

/// The four estimate checks above on the whole 3 x 3 grid.
#[test]
#[ignore = "slow tier: the four estimate checks on the 3 x 3 grid (COUPLED references at 1e-12)"]
fn estimates_bound_their_errors_on_the_grid() {
    for s in SOLVERS {
        check_bounds(s, Grid::Full, 6);
    }
}

/// Near full stick with 1 - c ~ h (measured by the stability map, LCP on 200 panels: b* = 0.53,
/// mu~ = 100, true error 4.3e-3) the estimate must still bound the error.
#[test]
fn lcp_estimate_bounds_its_error_near_full_stick() {
    let k = Coupling {
        bp: 0.5273,
        bq: 0.5273,
        mu: 100.0,
    };
    let reference = coupled::solve(&k, REFERENCE_TOL).unwrap();
    let p = lcp::solve(&k, 200).unwrap();
    let err = edge_error(&p, &reference);
    assert!(
        err <= p.numerical_error(),
        "error {err:.2e}, estimate {:.2e}",
        p.numerical_error()
    );
}

/// For strong orthotropy (delta = 1e-3, mu = 0.3, i.e. b* = 0.35, mu~ = 300) the LCP can
/// converge to a non-physical branch (c = 0 with p(0) < 0, against COUPLED's c = 0.99996):
/// it must then say so (NoConvergence), not return that branch.
#[test]
fn lcp_on_the_physical_branch_for_strong_orthotropy() {
    let k = Material::effective(E, 0.3, 1e-3, 1.0)
        .unwrap()
        .coupling(0.3);
    let reference = coupled::solve(&k, REFERENCE_TOL).unwrap();
    let p = match lcp::solve(&k, LCP_PANELS) {
        Ok(p) => p,
        Err(orthoslip::Error::NoConvergence(m)) => {
            assert!(m.contains("non-physical"), "{m}");
            return;
        }
        Err(e) => panic!("unexpected error {e}"),
    };
    let negative: Vec<f64> = XS.into_iter().filter(|&x| p.tractions(x).0 < 0.0).collect();
    assert!(negative.is_empty(), "p < 0 at x = {negative:?}");
    let err = edge_error(&p, &reference);
    assert!(
        err <= p.numerical_error(),
        "error {err:.2e}, estimate {:.2e}",
        p.numerical_error()
    );
}
