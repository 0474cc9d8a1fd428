//! Stability map: where each method fails. c depends only on (b*, mu~) (docs/theory.md (R2)),
//! so the methods are swept over that plane (b* in [0.005, 0.99], mu~ in [1e-6, 1e6], and
//! mu = 0) and over
//! the engineering-constant extremes that lead to its edges (section 5: mu -> 0 and -> infinity,
//! kappa -> -nu, kappa = 1, delta far from 1, nu -> 1 i.e. A -> 0, near-incompressible plane
//! strain, auxetic nu -> -1 i.e. b* -> 1). For every scene and method (GOODMAN, SPENCE, LCP on
//! 200 panels, COUPLED as METHOD_COUPLED runs it: c and the tractions to 1e-10) it records
//! the status (converged, or the error kind), the LCP Newton iterations or the COUPLED order,
//! c, 1 - c, the error in c against the COUPLED reference and the method's own estimate
//! against that error (`numerical_error`, plus `model_error::bound` for GOODMAN and SPENCE,
//! +infinity where the table gives none, as `Contact` reports it), and the same for the
//! tractions (`traction_error` plus `model_error::traction_bound`, against the reference's
//! tractions in the norm of `problem::traction_distance`); COUPLED itself is checked against
//! a tighter COUPLED run (c and tractions to 1e-12). The plane's scenes are spread over the
//! cores (one solve per core at a time, so the times are one core's).
//!
//! Run: `cargo run --release --example stability_map` (writes docs/stability_map.csv,
//! docs/stability_{goodman,spence,lcp,coupled,status}.svg and prints a failure summary).

mod support;

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::time::Instant;

use orthoslip::model_error::{self, Approximation};
use orthoslip::problem::traction_distance;
use orthoslip::{
    Contact, Coupling, Error, Material, Method, Profile, StickEdge, coupled, goodman, lcp, spence,
};
use support::parallel;
use support::plot::{Scale, Series, chart, heatmap};

/// The methods mapped, in CSV order.
const METHODS: [Method; 4] = [
    Method::Goodman,
    Method::Spence,
    Method::Lcp,
    Method::Coupled,
];
/// LCP panels per half-width.
const LCP_PANELS: usize = 200;
/// Tolerance of the COUPLED runs: the mapped one (also the reference of the other methods)
/// and the tighter one that checks it.
const COUPLED_TOL: f64 = 1e-10;
const TIGHT_TOL: f64 = 1e-12;
/// The tolerances (on c and on the tractions) at which METHOD_COUPLED and METHOD_AUTO are
/// also run, on every other row of b* and every third column of mu~, against the map's
/// COUPLED at `COUPLED_TOL`.
const SWEEP_TOLS: [f64; 6] = [1e-1, 1e-2, 1e-4, 1e-6, 1e-8, 1e-9];
/// The rounding floor of a traction distance (relative to p(0)), below which a true
/// traction error is not compared with an estimate: two evaluations of the same bonded-punch
/// tractions (b* = 0.05, mu~ >= 10, estimates ~1e-20) differed by 9.1e-18.
const TRACTION_ROUNDING: f64 = 1e-15;
/// What one solve gave.
enum Outcome {
    Solved {
        edge: StickEdge,
        estimate: f64,
        /// The traction estimate (the profile's own plus the model error's bound).
        traction_estimate: f64,
        /// The solution, for the traction comparisons.
        profile: Box<dyn Profile>,
        /// LCP Newton iterations on the finest grid, or the COUPLED order per panel.
        iterations: Option<usize>,
    },
    Failed {
        status: &'static str,
        message: String,
    },
}

/// One solve and its wall time.
struct Run {
    outcome: Outcome,
    seconds: f64,
}

impl Run {
    fn edge(&self) -> Option<StickEdge> {
        match self.outcome {
            Outcome::Solved { edge, .. } => Some(edge),
            Outcome::Failed { .. } => None,
        }
    }

    fn profile(&self) -> Option<&dyn Profile> {
        match &self.outcome {
            Outcome::Solved { profile, .. } => Some(profile.as_ref()),
            Outcome::Failed { .. } => None,
        }
    }

    fn traction_estimate(&self) -> Option<f64> {
        match self.outcome {
            Outcome::Solved {
                traction_estimate, ..
            } => Some(traction_estimate),
            Outcome::Failed { .. } => None,
        }
    }

    fn status(&self) -> &'static str {
        match &self.outcome {
            Outcome::Solved { .. } => "ok",
            Outcome::Failed { status, .. } => status,
        }
    }
}

fn error_kind(e: &Error) -> &'static str {
    match e {
        Error::InvalidArgument(_) => "InvalidArgument",
        Error::InadmissibleMaterial(_) => "InadmissibleMaterial",
        Error::NoConvergence(_) => "NoConvergence",
        Error::ToleranceNotMet { .. } => "ToleranceNotMet",
        Error::NoAdmissibleSolution(_) => "NoAdmissibleSolution",
        Error::Internal(_) => "Internal",
    }
}

/// The model-error bounds of an approximation (c, tractions), +infinity where none is
/// tabulated.
fn model(a: Approximation, k: &Coupling) -> (f64, f64) {
    (
        model_error::bound(a, k).unwrap_or(f64::INFINITY),
        model_error::traction_bound(a, k).unwrap_or(f64::INFINITY),
    )
}

/// A solved profile with its estimates (`numerical_error` and `traction_error` plus the
/// model's bounds), unless its edge breaks
/// the contract: c in [0, 1] (c = 1 only as the rounding of 1 - w for w < 2^-53), 1 - c in
/// (0, 1], an estimate >= 0 (+infinity: no bound known). A slip width that underflows to 0 is
/// reported as `SlipUnderflow`.
fn solved<P: Profile + 'static>(p: P, model: (f64, f64), iterations: Option<usize>) -> Outcome {
    let edge = p.edge();
    let estimate = p.numerical_error() + model.0;
    let traction_estimate = p.traction_error() + model.1;
    let w = edge.one_minus_c;
    let valid = (0.0..=1.0).contains(&edge.c)
        && (edge.c < 1.0 || w <= f64::EPSILON)
        && ((edge.c + w) - 1.0).abs() <= 4.0 * f64::EPSILON
        && w > 0.0
        && w <= 1.0
        && estimate >= 0.0;
    let status = if valid {
        return Outcome::Solved {
            edge,
            estimate,
            traction_estimate,
            profile: Box::new(p),
            iterations,
        };
    } else if w == 0.0 && edge.c == 1.0 {
        "SlipUnderflow"
    } else {
        "InvalidResult"
    };
    Outcome::Failed {
        status,
        message: format!("edge {edge:?}, estimate {estimate:e}"),
    }
}

/// Solves `k` by `method` (COUPLED to `tol` in c and in the tractions), catching errors and
/// panics.
fn run(method: Method, k: &Coupling, tol: f64) -> Run {
    let start = Instant::now();
    let result = catch_unwind(AssertUnwindSafe(|| -> orthoslip::Result<Outcome> {
        Ok(match method {
            Method::Goodman => solved(goodman::solve(k)?, model(Approximation::Goodman, k), None),
            Method::Spence => solved(spence::solve(k)?, model(Approximation::Spence, k), None),
            Method::Lcp => {
                let s = lcp::solve(k, LCP_PANELS)?;
                let n = s.newton_iterations();
                solved(s, (0.0, 0.0), Some(n))
            }
            Method::Coupled => {
                let s = coupled::solve_to(k, tol, tol)?;
                let n = s.order();
                solved(s, (0.0, 0.0), Some(n))
            }
            Method::Auto => {
                // the reduced coupling's material (delta = 1: b* = (1 - nu) / 2, mu = mu~)
                let (r, _) = k.reduced();
                let mut contact =
                    Contact::new(Material::effective(1.0, 1.0 - 2.0 * r.bp, 1.0, 1.0)?);
                contact.set_friction(r.mu)?;
                contact.set_tolerance(tol)?;
                let s = contact.solve()?;
                return Ok(Outcome::Solved {
                    edge: s.edge(),
                    estimate: s.error_estimate(),
                    traction_estimate: s.traction_error_estimate(),
                    iterations: None,
                    profile: Box::new(AutoAnswer(s)),
                });
            }
        })
    }));
    let outcome = match result {
        Ok(Ok(o)) => o,
        Ok(Err(e)) => Outcome::Failed {
            status: error_kind(&e),
            message: e.to_string(),
        },
        Err(_) => Outcome::Failed {
            status: "panic",
            message: "the solver panicked".into(),
        },
    };
    Run {
        outcome,
        seconds: start.elapsed().as_secs_f64(),
    }
}

/// AUTO's answer as a profile (its method's own, the solution owning it).
#[derive(Debug)]
struct AutoAnswer(orthoslip::Solution);

impl Profile for AutoAnswer {
    fn coupling(&self) -> Coupling {
        self.0.profile().coupling()
    }

    fn edge(&self) -> StickEdge {
        self.0.profile().edge()
    }

    fn numerical_error(&self) -> f64 {
        self.0.profile().numerical_error()
    }

    fn half_line_tractions(&self, x: f64) -> (f64, f64) {
        self.0.profile().half_line_tractions(x)
    }
}

/// A point of the map: where it comes from and its coupling.
#[derive(Clone)]
struct Scene {
    family: &'static str,
    label: String,
    k: Coupling,
}

impl Scene {
    fn b_star(&self) -> f64 {
        self.k.b_star()
    }

    /// mu~ = mu / delta with delta = sqrt(bq / bp) (mu when bp = 0).
    fn mu_tilde(&self) -> f64 {
        if self.k.bp > 0.0 {
            self.k.mu / (self.k.bq / self.k.bp).sqrt()
        } else {
            self.k.mu
        }
    }
}

/// Grid of the (b*, mu~) plane: b* from 0.005 to 0.99 (denser near the ends and around
/// b* = 0.1, where the slip zones at large friction are thinnest that the panels must
/// resolve), mu~ log from 1e-6 to 1e6 in thirds of a decade (mu = 0 is mapped apart).
fn plane_axes() -> (Vec<f64>, Vec<f64>) {
    let b = vec![
        0.005, 0.02, 0.05, 0.08, 0.1, 0.12, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95,
        0.99,
    ];
    let mu: Vec<f64> = (0..37).map(|i| 10f64.powf(-6.0 + i as f64 / 3.0)).collect();
    (b, mu)
}

/// The engineering-constant extremes, each at a few friction coefficients.
fn engineering_scenes() -> orthoslip::Result<Vec<Scene>> {
    let e = 100e9;
    let frictions = [1e-2, 0.3, 10.0];
    let steel = Material::effective(e, 0.3, 1.0, 1.0)?;
    let mut materials: Vec<(&'static str, String, Material)> = Vec::new();
    for eps in [1e-3, 1e-6, 1e-9, 1e-12] {
        materials.push((
            "kappa->-nu",
            format!("nu=0.3 kappa=-nu+{eps:e}"),
            Material::effective(e, 0.3, 1.0, -0.3 + eps)?,
        ));
    }
    for delta in [1.0, 3.0] {
        materials.push((
            "kappa=1",
            format!("nu=0.3 delta={delta} kappa=1"),
            Material::effective(e, 0.3, delta, 1.0)?,
        ));
    }
    for delta in [1e-3, 1e-2, 1e-1, 10.0, 1e2, 1e3] {
        materials.push((
            "delta",
            format!("nu=0.3 kappa=1 delta={delta:e}"),
            Material::effective(e, 0.3, delta, 1.0)?,
        ));
    }
    for eps in [1e-3, 1e-6, 1e-9] {
        materials.push((
            "nu->1",
            format!("nu=1-{eps:e} kappa=1"),
            Material::effective(e, 1.0 - eps, 1.0, 1.0)?,
        ));
    }
    materials.push((
        "plane-strain-nu0.499",
        "isotropic plane strain nu=0.499".into(),
        Material::plane_strain(e, e, e, e / (2.0 * 1.499), 0.499, 0.499, 0.499)?,
    ));
    for eps in [1e-2, 1e-4, 1e-6, 1e-9, 1e-12] {
        materials.push((
            "auxetic",
            format!("nu=-1+{eps:e} kappa=1"),
            Material::effective(e, -1.0 + eps, 1.0, 1.0)?,
        ));
    }
    let mut scenes: Vec<Scene> = [1e-4, 1e-3, 1e-2, 1e-1, 1.0, 10.0, 1e2, 1e3]
        .into_iter()
        .map(|mu| Scene {
            family: "friction",
            label: format!("steel nu=0.3 mu={mu:e}"),
            k: steel.coupling(mu),
        })
        .collect();
    for (family, name, m) in materials {
        for mu in frictions {
            scenes.push(Scene {
                family,
                label: format!("{name} mu={mu}"),
                k: m.coupling(mu),
            });
        }
    }
    Ok(scenes)
}

/// One scene solved by every method, with the references.
struct Solved {
    scene: Scene,
    runs: Vec<Run>,
    /// COUPLED to `TIGHT_TOL` (not run where COUPLED to `COUPLED_TOL` failed).
    tight: Option<Run>,
    /// Per method, the traction distance from its reference's tractions, where both exist.
    traction_errors: Vec<Option<f64>>,
}

impl Solved {
    /// Every method, then the tighter COUPLED run where COUPLED converged.
    fn new(scene: Scene) -> Self {
        let runs: Vec<Run> = METHODS
            .iter()
            .map(|&m| run(m, &scene.k, COUPLED_TOL))
            .collect();
        let tight = match runs[METHODS.len() - 1].outcome {
            Outcome::Solved { .. } => Some(run(Method::Coupled, &scene.k, TIGHT_TOL)),
            Outcome::Failed { .. } => None,
        };
        let mut s = Self {
            scene,
            runs,
            tight,
            traction_errors: Vec::new(),
        };
        s.traction_errors = (0..METHODS.len())
            .map(|i| {
                let reference = s.reference_run(i)?.profile()?;
                Some(traction_distance(s.runs[i].profile()?, reference))
            })
            .collect();
        s
    }

    /// The COUPLED run at `COUPLED_TOL`.
    fn coupled(&self) -> &Run {
        &self.runs[METHODS.len() - 1]
    }

    /// The reference run of method i: COUPLED, or the tighter COUPLED for COUPLED itself.
    fn reference_run(&self, i: usize) -> Option<&Run> {
        if METHODS[i] == Method::Coupled {
            self.tight.as_ref()
        } else {
            Some(self.coupled())
        }
    }

    /// The reference edge of method i.
    fn reference(&self, i: usize) -> Option<StickEdge> {
        self.reference_run(i)?.edge()
    }

    /// |c - c_ref| of method i, where both exist.
    fn true_error(&self, i: usize) -> Option<f64> {
        Some(self.runs[i].edge()?.distance(self.reference(i)?))
    }

    /// The traction distance of method i from its reference, where both exist.
    fn traction_true_error(&self, i: usize) -> Option<f64> {
        self.traction_errors[i]
    }

    /// Whether method i's traction estimate misses its true traction error by more than the
    /// reference's own traction estimate (None where there is nothing to compare).
    fn underestimates_tractions(&self, i: usize) -> Option<bool> {
        let slack = self
            .reference_run(i)?
            .traction_estimate()?
            .max(TRACTION_ROUNDING);
        Some(self.traction_true_error(i)? > self.runs[i].traction_estimate()? + slack)
    }

    /// Accuracy of method i's reference.
    fn reference_tol(i: usize) -> f64 {
        if METHODS[i] == Method::Coupled {
            TIGHT_TOL
        } else {
            COUPLED_TOL
        }
    }

    /// Whether method i's estimate misses its true error by more than the reference's own
    /// accuracy (None where there is nothing to compare).
    fn underestimates(&self, i: usize) -> Option<bool> {
        match self.runs[i].outcome {
            Outcome::Solved { estimate, .. } => {
                Some(self.true_error(i)? > estimate + Self::reference_tol(i))
            }
            Outcome::Failed { .. } => None,
        }
    }
}

/// One CSV row: run `r` of scene `s`, compared with its reference where it is method i's run
/// (the tight COUPLED run has none).
fn csv_row(csv: &mut String, s: &Solved, name: &str, r: &Run, method: Option<usize>) {
    let sc = &s.scene;
    let opt = |v: Option<f64>| v.map_or(String::new(), |v| format!("{v:e}"));
    let reference_edge = method.and_then(|i| s.reference(i));
    let (iterations, c, w, estimate, message) = match &r.outcome {
        Outcome::Solved {
            edge,
            estimate,
            iterations,
            ..
        } => (
            iterations.map_or(String::new(), |n| n.to_string()),
            Some(edge.c),
            Some(edge.one_minus_c),
            Some(*estimate),
            String::new(),
        ),
        Outcome::Failed { message, .. } => (String::new(), None, None, None, message.clone()),
    };
    let err = r.edge().zip(reference_edge).map(|(a, b)| a.distance(b));
    let ratio = estimate.zip(err).map(|(e, t)| e / t);
    let t_est = r.traction_estimate();
    let t_err = method.and_then(|i| s.traction_true_error(i));
    let _ = writeln!(
        csv,
        "{},\"{}\",{:e},{:e},{:e},{:e},{:e},{name},{},{iterations},{},{},{},{},{},{},{},{},{},{:.3e},\"{}\"",
        sc.family,
        sc.label,
        sc.b_star(),
        sc.mu_tilde(),
        sc.k.bp,
        sc.k.bq,
        sc.k.mu,
        r.status(),
        opt(c),
        opt(w),
        opt(estimate),
        opt(reference_edge.map(|e| e.c)),
        opt(reference_edge.map(|e| e.one_minus_c)),
        opt(err),
        opt(ratio),
        opt(t_est),
        opt(t_err),
        r.seconds,
        message.replace('"', "'"),
    );
}

const CSV_HEADER: &str = "family,scene,b_star,mu_tilde,bp,bq,mu,method,status,iterations,c,\
one_minus_c,estimate,reference_c,reference_one_minus_c,true_error,estimate_over_true,\
traction_estimate,traction_true_error,seconds,message\n";

fn method_name(m: Method) -> &'static str {
    match m {
        Method::Goodman => "GOODMAN",
        Method::Spence => "SPENCE",
        Method::Lcp => "LCP",
        Method::Coupled => "COUPLED",
        Method::Auto => "AUTO",
    }
}

/// A heat-map value per plane cell (rows over b*, columns over mu~).
fn grid_of(plane: &[Solved], n_mu: usize, f: impl Fn(&Solved) -> Option<f64>) -> Vec<Vec<f64>> {
    plane
        .chunks(n_mu)
        .map(|row| row.iter().map(|s| f(s).unwrap_or(f64::NAN)).collect())
        .collect()
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    std::fs::create_dir_all("docs")?;
    let t0 = Instant::now();
    let (b_axis, mu_axis) = plane_axes();
    let solve_all = |scenes: &[Scene]| parallel::map(scenes, |s| Solved::new(s.clone()));
    let plane_scenes: Vec<Scene> = b_axis
        .iter()
        .flat_map(|&b| {
            mu_axis.iter().map(move |&mu| Scene {
                family: "plane",
                label: format!("b*={b:.4} mu~={mu:.3e}"),
                k: Coupling { bp: b, bq: b, mu },
            })
        })
        .collect();
    let plane = solve_all(&plane_scenes);
    eprintln!("plane: {:.1} s", t0.elapsed().as_secs_f64());
    tolerance_sweep(&plane, mu_axis.len())?;
    eprintln!("tolerance sweep: {:.1} s", t0.elapsed().as_secs_f64());
    let mut engineering_list: Vec<Scene> = b_axis
        .iter()
        .map(|&b| Scene {
            family: "plane-mu0",
            label: format!("b*={b:.4} mu=0"),
            k: Coupling {
                bp: b,
                bq: b,
                mu: 0.0,
            },
        })
        .collect();
    engineering_list.extend(engineering_scenes()?);
    let engineering = solve_all(&engineering_list);
    eprintln!("engineering scenes: {:.1} s", t0.elapsed().as_secs_f64());

    let mut csv = String::from(CSV_HEADER);
    for s in plane.iter().chain(&engineering) {
        for (i, &m) in METHODS.iter().enumerate() {
            csv_row(&mut csv, s, method_name(m), &s.runs[i], Some(i));
        }
        if let Some(t) = &s.tight {
            csv_row(&mut csv, s, "COUPLED_TIGHT", t, None);
        }
    }
    std::fs::write("docs/stability_map.csv", csv)?;

    // Heat maps over the plane.
    let n_mu = mu_axis.len();
    let axes = (
        ("friction mu~ = mu / delta", &mu_axis[..]),
        ("b*", &b_axis[..]),
    );
    for (i, file) in [(0, "goodman"), (1, "spence")] {
        heatmap(
            &format!("docs/stability_{file}.svg"),
            &format!(
                "{}: |c - c_COUPLED| (contours 1e-2, 1e-4, 1e-6; grey: no reference)",
                method_name(METHODS[i])
            ),
            axes.0,
            axes.1,
            &grid_of(&plane, n_mu, |s| s.true_error(i)),
            &[1e-2, 1e-4, 1e-6],
        )?;
    }
    heatmap(
        "docs/stability_lcp.svg",
        "LCP (200 panels): |c - c_COUPLED| (grey: LCP failed or no reference)",
        axes.0,
        axes.1,
        &grid_of(&plane, n_mu, |s| s.true_error(2)),
        &[1e-2, 1e-3, 1e-4],
    )?;
    heatmap(
        "docs/stability_coupled.svg",
        "COUPLED (tol 1e-10): |c - c(tol 1e-12)| (grey: failed; contours 1e-10, 1e-12)",
        axes.0,
        axes.1,
        &grid_of(&plane, n_mu, |s| match s.coupled().outcome {
            Outcome::Solved { .. } => s.true_error(3).map(|t| t.max(1e-16)),
            Outcome::Failed { .. } => None,
        }),
        &[1e-10, 1e-12],
    )?;
    // COUPLED's estimate over its true error, both floored at the tight run's accuracy
    // (differences below it are not resolved): one series per b*.
    let floor = TIGHT_TOL;
    let ratios: Vec<Series> = plane
        .chunks(n_mu)
        .map(|row| Series {
            name: format!("b* = {:.3}", row[0].scene.b_star()),
            points: row
                .iter()
                .filter_map(|s| {
                    let Outcome::Solved { estimate, .. } = s.coupled().outcome else {
                        return None;
                    };
                    let t = s.true_error(3)?;
                    Some((s.scene.mu_tilde(), estimate.max(floor) / t.max(floor)))
                })
                .collect(),
            line: true,
        })
        .collect();
    chart(
        "docs/stability_coupled_ratio.svg",
        "COUPLED (tol 1e-10): estimate / |c - c(tol 1e-12)|, floored at 1e-12 (< 1: missed)",
        ("friction mu~ = mu / delta", Scale::Log),
        ("estimate / true error", Scale::Log),
        &ratios,
        Some(&Series {
            name: "ratio 1".into(),
            points: vec![(mu_axis[0], 1.0), (mu_axis[n_mu - 1], 1.0)],
            line: true,
        }),
    )?;
    // Where each method fails on the plane (markers, one series per method and status).
    let mut failures: BTreeMap<String, Vec<(f64, f64)>> = BTreeMap::new();
    for s in &plane {
        for (i, &m) in METHODS.iter().enumerate() {
            if let Outcome::Failed { status, .. } = s.runs[i].outcome {
                // offset markers of different methods a little in b* so they do not hide
                let y = s.scene.b_star() + 0.008 * (i as f64 - 1.5);
                failures
                    .entry(format!("{} {status}", method_name(m)))
                    .or_default()
                    .push((s.scene.mu_tilde(), y));
            }
        }
    }
    let mut series: Vec<Series> = failures
        .into_iter()
        .map(|(name, points)| Series {
            name,
            points,
            line: false,
        })
        .collect();
    // the corners of the plane, so that the axes cover it
    series.push(Series {
        name: "(plane corners)".into(),
        points: vec![
            (mu_axis[0], b_axis[0]),
            (mu_axis[n_mu - 1], b_axis[b_axis.len() - 1]),
        ],
        line: false,
    });
    chart(
        "docs/stability_status.svg",
        "failures on the (mu~, b*) plane (markers offset in b* by method)",
        ("friction mu~ = mu / delta", Scale::Log),
        ("b*", Scale::Linear),
        &series,
        None,
    )?;

    for i in 0..METHODS.len() {
        text_map(&plane, &b_axis, &mu_axis, i);
    }
    summary(&plane, &engineering);
    println!(
        "wrote docs/stability_map.csv and docs/stability_*.svg in {:.1} s",
        t0.elapsed().as_secs_f64()
    );
    Ok(())
}

/// METHOD_COUPLED and METHOD_AUTO at every tolerance of `SWEEP_TOLS` (c and tractions) on a
/// sub-grid of the plane (every other b*, every third mu~), against the plane's COUPLED run
/// at `COUPLED_TOL`: writes docs/stability_tolerances.csv and prints, per method and
/// tolerance, the failures, the answers whose estimates exceed the tolerance, and those whose
/// true errors exceed their estimates beyond the reference's (c: `COUPLED_TOL`; tractions: its
/// traction estimate, at least `TRACTION_ROUNDING`).
fn tolerance_sweep(plane: &[Solved], n_mu: usize) -> std::io::Result<()> {
    let picks: Vec<&Solved> = plane
        .iter()
        .enumerate()
        .filter(|(i, _)| (i / n_mu).is_multiple_of(2) && (i % n_mu).is_multiple_of(3))
        .map(|(_, s)| s)
        .collect();
    let jobs: Vec<(usize, Method, f64)> = (0..picks.len())
        .flat_map(|p| {
            SWEEP_TOLS
                .iter()
                .flat_map(move |&t| [Method::Coupled, Method::Auto].map(|m| (p, m, t)))
        })
        .collect();
    let runs = parallel::map(&jobs, |&(p, m, t)| run(m, &picks[p].scene.k, t));
    let mut csv = String::from(
        "b_star,mu_tilde,method,tolerance,status,c,one_minus_c,estimate,true_error,\
         traction_estimate,traction_true_error,seconds,message\n",
    );
    // per (method, tolerance): runs, failures, estimates above the tolerance, misses
    let mut tally: BTreeMap<(&str, String), [usize; 4]> = BTreeMap::new();
    for (&(p, m, t), r) in jobs.iter().zip(&runs) {
        let s = picks[p];
        let reference = s.coupled();
        let err = r.edge().zip(reference.edge()).map(|(a, b)| a.distance(b));
        let t_err = r
            .profile()
            .zip(reference.profile())
            .map(|(a, b)| traction_distance(a, b));
        let (estimate, t_est) = match &r.outcome {
            Outcome::Solved {
                estimate,
                traction_estimate,
                ..
            } => (Some(*estimate), Some(*traction_estimate)),
            Outcome::Failed { .. } => (None, None),
        };
        let over = estimate.zip(t_est).is_some_and(|(e, te)| e > t || te > t);
        let missed = estimate.zip(err).is_some_and(|(e, x)| x > e + COUPLED_TOL)
            || t_est
                .zip(t_err)
                .zip(reference.traction_estimate())
                .is_some_and(|((e, x), slack)| x > e + slack.max(TRACTION_ROUNDING));
        let counts = tally
            .entry((method_name(m), format!("{t:.0e}")))
            .or_default();
        counts[0] += 1;
        counts[1] += usize::from(estimate.is_none());
        counts[2] += usize::from(over);
        counts[3] += usize::from(missed);
        let opt = |v: Option<f64>| v.map_or(String::new(), |v| format!("{v:e}"));
        let message = match &r.outcome {
            Outcome::Failed { message, .. } => message.replace('"', "'"),
            Outcome::Solved { .. } => String::new(),
        };
        let _ = writeln!(
            csv,
            "{:e},{:e},{},{t:e},{},{},{},{},{},{},{},{:.3e},\"{message}\"",
            s.scene.b_star(),
            s.scene.mu_tilde(),
            method_name(m),
            r.status(),
            opt(r.edge().map(|e| e.c)),
            opt(r.edge().map(|e| e.one_minus_c)),
            opt(estimate),
            opt(err),
            opt(t_est),
            opt(t_err),
            r.seconds,
        );
    }
    std::fs::write("docs/stability_tolerances.csv", csv)?;
    println!(
        "== tolerance sweep: {} plane points (every other b*, every third mu~)",
        picks.len()
    );
    for ((m, t), [n, failed, over, missed]) in tally {
        println!(
            "{m:8} tol {t}: {failed} of {n} failed, {over} estimates above the tolerance, {missed} \
             true errors above the estimates"
        );
    }
    Ok(())
}

/// Failure counts per method and status, with the range of (b*, mu~) where they happen, and
/// how often the method's estimate misses its true error.
fn summary(plane: &[Solved], engineering: &[Solved]) {
    for (what, set) in [("plane", plane), ("engineering extremes", engineering)] {
        println!("== {what}: {} scenes", set.len());
        for (i, &m) in METHODS.iter().enumerate() {
            let mut by_status: BTreeMap<&str, Vec<&Scene>> = BTreeMap::new();
            for s in set {
                if let Outcome::Failed { status, .. } = s.runs[i].outcome {
                    by_status.entry(status).or_default().push(&s.scene);
                }
            }
            let checks: Vec<bool> = set.iter().filter_map(|s| s.underestimates(i)).collect();
            let worst = set
                .iter()
                .filter_map(|s| s.true_error(i))
                .fold(0.0, f64::max);
            let t_checks: Vec<bool> = set
                .iter()
                .filter_map(|s| s.underestimates_tractions(i))
                .collect();
            let t_worst = set
                .iter()
                .filter_map(|s| s.traction_true_error(i))
                .fold(0.0, f64::max);
            println!(
                "{:8} {:.1} s; estimate below true error (beyond the reference's accuracy) in \
                 {} of {} compared; largest true error {worst:.2e}",
                method_name(m),
                set.iter().map(|s| s.runs[i].seconds).sum::<f64>(),
                checks.iter().filter(|&&u| u).count(),
                checks.len(),
            );
            println!(
                "         tractions: estimate below true error (beyond the reference's estimate \
                 or 1e-15) in {} of {} compared; largest true error {t_worst:.2e}",
                t_checks.iter().filter(|&&u| u).count(),
                t_checks.len(),
            );
            for (status, scenes) in by_status {
                let range = |f: fn(&Scene) -> f64| {
                    scenes
                        .iter()
                        .map(|s| f(s))
                        .fold((f64::INFINITY, 0.0), |(a, b), v| (a.min(v), f64::max(b, v)))
                };
                let (b0, b1) = range(Scene::b_star);
                let (m0, m1) = range(Scene::mu_tilde);
                let mut families: Vec<&str> = scenes.iter().map(|s| s.family).collect();
                families.dedup();
                println!(
                    "    {status}: {} scenes, b* in [{b0:.3e}, {b1:.3}], mu~ in [{m0:.2e}, \
                     {m1:.2e}] ({})",
                    scenes.len(),
                    families.join(", ")
                );
            }
        }
        let tight_fail = set
            .iter()
            .filter(|s| {
                matches!(
                    s.tight,
                    Some(Run {
                        outcome: Outcome::Failed { .. },
                        ..
                    })
                )
            })
            .count();
        println!("COUPLED_TIGHT (1e-12) failed in {tight_fail} of the scenes COUPLED solved");
    }
}

/// The plane as text for method i: one line per b*, one character per mu~: `.` solved with
/// the estimates covering the true errors, `u` solved but the estimate of c misses its error,
/// `t` the traction estimate misses the traction error, `i` solved
/// with an infinite estimate (no bound known), `o` solved without a reference, or the first
/// letter of the failure status.
fn text_map(plane: &[Solved], b_axis: &[f64], mu_axis: &[f64], i: usize) {
    println!(
        "{} over mu~ = {:.0e} .. {:.0e} (columns) and b* (rows):",
        method_name(METHODS[i]),
        mu_axis[0],
        mu_axis[mu_axis.len() - 1]
    );
    for (row, b) in plane.chunks(mu_axis.len()).zip(b_axis).rev() {
        let line: String = row
            .iter()
            .map(|s| match (&s.runs[i].outcome, s.underestimates(i)) {
                (Outcome::Failed { status, .. }, _) => status.chars().next().unwrap_or('?'),
                (Outcome::Solved { estimate, .. }, _) if estimate.is_infinite() => 'i',
                (Outcome::Solved { .. }, Some(true)) => 'u',
                (Outcome::Solved { .. }, _) if s.underestimates_tractions(i) == Some(true) => 't',
                (Outcome::Solved { .. }, Some(false)) => '.',
                (Outcome::Solved { .. }, None) => 'o',
            })
            .collect();
        println!("  b* = {b:.3}  {line}");
    }
}
