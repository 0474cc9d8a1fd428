//! The exact load path against independent references: the bp = 0 closed forms (T11),
//! (T13), (T15) by quadrature of their integrals and secant or Brent roots, mirror symmetry,
//! and the unchanged-on-failure contract. Its comparison with the grid LCP history under
//! refinement is in `crate::fretting::tests`.

use super::super::reload::tests::{t15, t15_root};
use super::super::tests::{goodman_integral, jacobi_integral, ply, t11};
use super::super::unload::tests::t13;
use super::*;
use crate::numerics::roots::secant;
use std::f64::consts::{LN_2, PI};

fn goodman() -> Coupling {
    Coupling { bp: 0.0, ..ply() }
}

/// Everything the path reports of its state, bit for bit.
fn snapshot(p: &ExactPath) -> Vec<u64> {
    let mut v = vec![p.q_over_p(), p.moment(), p.estimates().0, p.estimates().1];
    let (a, b) = p.stick_set();
    v.extend([a, b]);
    for x in [-0.99, -0.5, 0.0, 0.3, 0.97] {
        let (p, q) = p.tractions(1.0 + x, 1.0 - x);
        v.extend([p, q]);
    }
    v.into_iter().map(f64::to_bits).collect()
}

/// bp = 0 along 0 -> Q* -> 0 -> -0.6 Q* -> -0.8 Q* -> -Q* -> 0.5 Q* -> Q_r (past the
/// reloading's first slip): in the full-stick ranges ((T13a) at 0, (T15a) at 0.5 Q*) the
/// state is the closed form q = q_d + ((Q - Q_d)/P) p0 with p unchanged, the stick set the
/// whole contact, D by (T16) ([`stuck_against_closed_form`]); the stick set's moving end is
/// the root of (T11), (T13) and (T15) in turn.
#[test]
fn goodman_path_matches_the_closed_forms() {
    let k = goodman();
    let q_star = 0.18;
    let mut path = ExactPath::new(&k, 1e-11, 1e-9).unwrap();
    assert_eq!(path.stick_set().0, -path.normal.c);
    path.load(q_star).unwrap();
    let (c1, c2) = path.stick_set();
    let root = secant(|c2| t11(&k, c2) - q_star, c2 - 1e-3, c2 + 1e-3);
    assert_eq!(c1, -1.0);
    assert!((c2 - root).abs() < 1e-9, "c2 = {c2} against (T11)'s {root}");
    let Branch::Loading { m, .. } = &path.branch else {
        panic!("not loading")
    };
    let m = m.clone();
    // above the first slip the unloading sticks fully: (T13a)
    let loaded = path.clone();
    path.load(0.0).unwrap();
    stuck_against_closed_form(&path, &loaded);
    // the unloading, in steps that continue the branch ((T13)'s quadrature needs the loaded
    // state's kink c2* outside (-1, a1): at -0.6 Q* and -0.8 Q*, not at -Q*)
    for frac in [-0.6, -0.8] {
        let qp = frac * q_star;
        path.load(qp).unwrap();
        let (a1, a2) = path.stick_set();
        let root = secant(|a| t13(&*m, a) - (q_star - qp), a1 - 0.01, a1 + 0.01);
        assert_eq!(a2, 1.0);
        assert!(
            (a1 - root).abs() < 1e-9,
            "Q/Q* = {frac}: a1 = {a1} against (T13)'s {root}"
        );
    }
    path.load(-q_star).unwrap();
    // the reloading from -Q*, past its first slip (T15a): b2 is (T15)'s root
    let Branch::Unloading { u, .. } = &path.branch else {
        panic!("not unloading")
    };
    let u = u.clone();
    let (_, q) = u.tractions(2.0 - 1e-12, 1e-12);
    let p0 = 1.0 / (std::f64::consts::PI * (1e-12f64 * (2.0 - 1e-12)).sqrt());
    let q_s = u.qp + (k.mu - q / p0);
    let q_r = q_s + 0.3 * (k.mu - q_s);
    // below Q_s the reloading sticks fully: (T15a)
    let unloaded = path.clone();
    path.load(0.5 * q_star).unwrap();
    stuck_against_closed_form(&path, &unloaded);
    let Branch::Stuck { slip_at, .. } = path.branch else {
        panic!("not stuck")
    };
    assert!((slip_at - q_s).abs() < 1e-15, "{slip_at} against {q_s}");
    path.load(q_r).unwrap();
    let (b1, b2) = path.stick_set();
    let root = t15_root(&*u, q_r, b2);
    assert!(
        b1 == -1.0 && (b2 - root).abs() < 1e-9,
        "reloaded to {q_r}: ({b1}, {b2}) against (T15)'s b2 = {root} ({:e} there)",
        t15(&*u, root) - (q_r - u.qp)
    );
    assert!((path.q_over_p() - q_r).abs() == 0.0);
    let (ce, te) = path.estimates();
    assert!(ce < 1e-9 && te < 1e-8, "estimates {ce:e}, {te:e}");
}

/// A full-stick state `path` reached from the state `data` where the load reversed:
/// q = q_d + ((Q - Q_d)/P) p0 and p = p_d at points across the contact, with p0 the flat
/// punch's 1/(pi sqrt(1 - x^2)) ((T13a), (T15a)); the stick set [-1, 1]; no dissipation
/// since `data`; D by (T16) as the quadrature of the change of e at 9 points of the contact
/// (`surface_change`: e - e_d = -L[q - q_d], a different evaluation from the path's closed
/// form (Q - Q_d)/P ln 2 / pi); the moment unchanged.
fn stuck_against_closed_form(path: &ExactPath, data: &ExactPath) {
    let dq = path.q_over_p() - data.q_over_p();
    assert_eq!(path.stick_set(), (-1.0, 1.0));
    assert_eq!(path.dissipated, data.dissipated);
    assert_eq!(path.moment(), data.moment());
    for x in [-0.999999, -0.9, -0.5, -0.2, 0.0, 0.3, 0.7, 0.99, 0.9999999] {
        let (p, q) = path.tractions(1.0 + x, 1.0 - x);
        let (pd, qd) = data.tractions(1.0 + x, 1.0 - x);
        let p0 = 1.0 / (PI * ((1.0 + x) * (1.0 - x)).sqrt());
        assert_eq!(p, pd);
        assert!(
            (q - (qd + dq * p0)).abs() <= 1e-14 * p0,
            "x = {x}: q = {q} against {}",
            qd + dq * p0
        );
        assert!(q.abs() <= k_mu(path) * p, "x = {x}: |q| > mu p");
    }
    let spread = stick_spread(path, data, 10);
    println!(
        "stuck at Q/P = {}: D = {:.12}, (T16) by quadrature within {spread:.1e}",
        path.q_over_p(),
        path.punch
    );
    assert!(spread < 1e-9, "D against (T16): {spread:e}");
}

fn k_mu(path: &ExactPath) -> f64 {
    path.k.mu
}

/// bp = 0, a cycle on the path through the full-stick ranges: 0 -> Q* -> 0 (stuck,
/// (T13a)) -> -Q* (the slipping part, from the loaded state) -> Q* (stuck, (T15a)) -> -Q*:
/// the unloading's dissipation is section 15's W1 = 2.882525151e-3 pi B P^2 (mu int p0 s of
/// the unloading solver's slip, another evaluation than (T17)'s), the full-stick steps
/// dissipate nothing, and the second unloading returns to the unloaded state bit for bit
/// (shakedown). A load just past the reloading's first slip Q_s, where the zone at +1 is
/// far thinner than the bases resolve, is refused and leaves the path as it was.
#[test]
fn goodman_cycle_through_full_stick() {
    let k = goodman();
    let q_star = 0.18;
    let mut path = ExactPath::new(&k, 1e-11, 1e-9).unwrap();
    path.load(q_star).unwrap();
    let w0 = path.dissipated;
    path.load(0.0).unwrap();
    assert_eq!(path.dissipated, w0);
    let t = std::time::Instant::now();
    path.load(-q_star).unwrap();
    let w1 = path.dissipated - w0;
    println!("W1 through Q = 0: {w1:.12e} ({:?})", t.elapsed());
    assert!((w1 - 2.882525151e-3).abs() < 1e-11, "W1 = {w1:e}");
    let unloaded = snapshot(&path);
    let d_unloaded = path.punch;
    path.load(q_star).unwrap();
    assert!(matches!(path.branch, Branch::Stuck { .. }));
    assert_eq!(path.dissipated, w0 + w1);
    // D moves by (2 Q*/P) ln 2 / pi, the full-stick compliance of (T10)
    assert!((path.punch - d_unloaded - 2.0 * q_star * LN_2 / PI).abs() < 1e-15);
    path.load(-q_star).unwrap();
    assert_eq!(
        snapshot(&path),
        unloaded,
        "the second unloading is not the first's state"
    );
    assert_eq!(path.punch, d_unloaded);
    assert_eq!(path.dissipated, w0 + w1);
    // just past the reloading's first slip
    path.load(q_star).unwrap();
    let Branch::Stuck { slip_at, .. } = path.branch else {
        panic!("not stuck")
    };
    let before = snapshot(&path);
    let t = std::time::Instant::now();
    let r = path.load(slip_at + 1e-12);
    println!(
        "past Q_s by 1e-12: {:?} ({:?})",
        r.as_ref().err(),
        t.elapsed()
    );
    assert!(r.is_err());
    assert_eq!(snapshot(&path), before, "a refused load changed the path");
}

/// Q < 0 from the normal load is the mirror of Q > 0 (docs/theory_tangential.md section 5):
/// stick set [-c2, -c1], p(-x), -q(-x), the moment's sign turned.
#[test]
fn negative_loading_is_the_mirror() {
    let k = goodman();
    let mut up = ExactPath::new(&k, 1e-10, 1e-8).unwrap();
    let mut down = up.clone();
    up.load(0.1).unwrap();
    down.load(-0.1).unwrap();
    let ((a1, a2), (b1, b2)) = (up.stick_set(), down.stick_set());
    assert_eq!((b1, b2), (-a2, -a1));
    assert_eq!(down.moment(), -up.moment());
    for x in [-0.9, -0.2, 0.05, 0.6] {
        let (p, q) = up.tractions(1.0 + x, 1.0 - x);
        let (pm, qm) = down.tractions(1.0 - x, 1.0 + x);
        assert!((p - pm).abs() == 0.0 && (q + qm).abs() == 0.0, "x = {x}");
    }
}

/// (T16) for the loading at bp = 0: D = -(Q/P) ln(l/2)/pi - (1/pi) int_{c2}^{c} (mu p0 - q0)
/// arccosh(1 + (s - c2)/l) ds, l = (1 + c2)/2, by quadrature of Goodman's closed-form
/// tractions (arccosh(1 + u^2/l) = 2 asinh(u / sqrt(2 l)) in u = sqrt(s - c2)).
fn t16_loading(k: &Coupling, c2: f64, qp: f64) -> f64 {
    let l = 0.5 * (1.0 + c2);
    let i = goodman_integral(k, c2, |u, _| 2.0 * (u / (2.0 * l).sqrt()).asinh() * 2.0 * u);
    -qp * (0.5 * l).ln() / PI - i / PI
}

/// (T16) for the unloading at bp = 0 from the loaded state `m` (Q* = m.qp): D - D* =
/// ((Q* - Q)/P) ln(l/2)/pi + (1/pi) int_{-1}^{a1} (mu p0 + q*) arccosh(1 + (a1 - s)/l) ds,
/// l = (1 - a1)/2, by Gauss-Jacobi with (1 + s)^(-1/2) (p0's) and (a1 - s)^(1/2) (the
/// arccosh's) taken out; q* has no kink on (-1, a1) at the loads used.
fn t16_unloading<D: Start + ?Sized>(m: &D, a1: f64, qp: f64) -> f64 {
    let mu = m.coupling().mu;
    let l = 0.5 * (1.0 - a1);
    let i = jacobi_integral(0.0, 1.0 + a1, 0.5, -0.5, |opx| {
        let omx = 2.0 - opx;
        let p0 = 1.0 / (PI * (opx * omx).sqrt());
        let (_, q) = m.tractions(opx, omx);
        (mu * p0 + q) * (1.0 + (1.0 + a1 - opx) / l).acosh()
    });
    (m.qp() - qp) * (0.5 * l).ln() / PI + i / PI
}

/// The largest difference of e - e_ref - (D - D_ref) over `n` points of the stick set of
/// `path` (reached from `reference`): zero where (T16) holds, i.e. where (M2)/(U2) hold and
/// the quadrature of L[q] is right.
fn stick_spread(path: &ExactPath, reference: &ExactPath, n: usize) -> f64 {
    let (c1, c2) = path.stick_set();
    let d = path.punch - reference.punch;
    (1..n)
        .map(|i| {
            let x = c1 + (c2 - c1) * i as f64 / n as f64;
            (path.surface_change(reference, x) - d).abs()
        })
        .fold(0.0, f64::max)
}

/// bp = 0: the punch displacement D of the exact path (docs/theory_tangential.md (T16)) at
/// Q* and at -0.6 Q*, -0.8 Q* of the unloading equals the closed form by quadrature of
/// Goodman's tractions (loading) and of the loaded state's (unloading), and the surface of
/// the stick set moves rigidly with it.
#[test]
fn goodman_punch_matches_the_closed_form() {
    let k = goodman();
    let q_star = 0.18;
    let mut path = ExactPath::new(&k, 1e-11, 1e-9).unwrap();
    assert_eq!(path.punch, 0.0);
    let normal = path.clone();
    let t = std::time::Instant::now();
    path.load(q_star).unwrap();
    println!("loaded in {:?}", t.elapsed());
    let (_, c2) = path.stick_set();
    let reference = t16_loading(&k, c2, q_star);
    let spread = stick_spread(&path, &normal, 8);
    println!(
        "D(Q*) = {:.12} against (T16) {reference:.12} ({:.1e}); spread {spread:.1e}",
        path.punch,
        path.punch - reference
    );
    assert!((path.punch - reference).abs() < 1e-9 && spread < 1e-9);
    let Branch::Loading { m, .. } = &path.branch else {
        panic!("not loading")
    };
    let m = m.clone();
    let d_star = path.punch;
    for frac in [-0.6, -0.8] {
        let qp = frac * q_star;
        let before = path.clone();
        let t = std::time::Instant::now();
        path.load(qp).unwrap();
        let (a1, _) = path.stick_set();
        let reference = d_star + t16_unloading(&*m, a1, qp);
        let spread = stick_spread(&path, &before, 8);
        println!(
            "Q/Q* = {frac}: D = {:.12} against (T16) {reference:.12} ({:.1e}); spread {spread:.1e} \
             ({:?})",
            path.punch,
            path.punch - reference,
            t.elapsed()
        );
        assert!((path.punch - reference).abs() < 1e-9 && spread < 1e-9);
    }
}

/// The ply (mu = 0.3), loaded to Q* = 0.6 mu P and unloaded to -Q*: the surface of the stick
/// set moves rigidly with the punch displacement D of (T16) (to the tractions' accuracy,
/// 1e-5 asked), D against the grid LCP history is in `crate::fretting::tests`.
#[test]
fn ply_stick_set_moves_rigidly() {
    let k = ply();
    let mut path = ExactPath::new(&k, 1e-8, 1e-5).unwrap();
    let normal = path.clone();
    path.load(0.18).unwrap();
    let loaded = path.clone();
    let t = std::time::Instant::now();
    let spread = stick_spread(&path, &normal, 10);
    println!("one (T16): {:?}", t.elapsed() / 9);
    println!("D(Q*) = {:.10}, spread {spread:.1e}", path.punch);
    assert!(spread < 1e-7);
    path.load(-0.18).unwrap();
    let spread = stick_spread(&path, &loaded, 10);
    println!("D(-Q*) = {:.10}, spread {spread:.1e}", path.punch);
    assert!(spread < 1e-7);
}

/// The step of (T16a): the equilibrium density w = 1/(pi sqrt((x - lo)(hi - x))) of
/// I = (lo, hi) has the log potential (1/pi) int_I w(x) ln|x - t| dx = (ln(l/2) +
/// arccosh(|t - m|/l)) / pi (the arccosh only outside I), against Gauss-Chebyshev quadrature
/// (smooth outside I; inside, the logarithm makes it converge like 1/n).
#[test]
fn equilibrium_density_potential() {
    let (lo, hi) = (-1.0, -0.28);
    let (m, l) = (0.5 * (lo + hi), 0.5 * (hi - lo));
    let potential = |t: f64, n: usize| {
        (0..n)
            .map(|i| {
                let x = m + l * (PI * (i as f64 + 0.5) / n as f64).cos();
                (x - t).abs().ln() / n as f64
            })
            .sum::<f64>()
            / PI
    };
    for t in [-0.9, -0.5, -0.3, -0.2, 0.4, 1.0] {
        let xi = ((t - m) / l).abs();
        let closed = ((0.5 * l).ln() + if xi > 1.0 { xi.acosh() } else { 0.0 }) / PI;
        let (n, tol) = if xi > 1.0 {
            (400, 1e-12)
        } else {
            (200_001, 1e-4)
        };
        let d = (potential(t, n) - closed).abs();
        assert!(d < tol, "t = {t}: {d:e}");
    }
}

/// The grid LCP history's dissipation (T8) along 0 -> loads[0] -> loads[1] ..., `steps` grid
/// steps per load, at n panels per half-width: the sum at each load.
fn grid_dissipation(k: &Coupling, n: usize, loads: &[f64], steps: usize) -> Vec<f64> {
    let mut h = crate::lcp::history::History::new(k, n).unwrap();
    let mut w = 0.0;
    loads
        .iter()
        .map(|&q| {
            w += h
                .load(q, steps)
                .unwrap()
                .iter()
                .map(|s| s.dissipation)
                .sum::<f64>();
            w
        })
        .collect()
}

/// bp = 0: the exact path's dissipation (T17) does not depend on the load steps (p = p0
/// throughout, so the slip's work telescopes), and the grid's (backward Euler, also step
/// independent here) approaches it as it refines: the loading 0 -> Q* and
/// the unloading Q* -> -Q* (section 15's table: 2.882525151e-3 pi B P^2 for the latter).
#[test]
fn goodman_dissipation_against_the_grid() {
    let k = goodman();
    let q_star = 0.18;
    let mut one = ExactPath::new(&k, 1e-11, 1e-9).unwrap();
    let mut three = one.clone();
    one.load(q_star).unwrap();
    for q in [0.06, 0.12, 0.18] {
        three.load(q).unwrap();
    }
    let w0 = one.dissipated;
    println!(
        "W0 {w0:.12e} (one step), {:.12e} (three), estimate {:.1e}",
        three.dissipated, one.dissipated_error
    );
    assert!((three.dissipated - w0).abs() < 1e-10 * w0);
    let t = std::time::Instant::now();
    one.load(-q_star).unwrap();
    let w1 = one.dissipated - w0;
    println!("W1 {w1:.12e} ({:?})", t.elapsed());
    assert!((w1 - 2.882525151e-3).abs() < 1e-11);
    // the grid's error is not monotone in n here (section 15): it is asked to lie within
    // 5e-5 of W at n = 100 and 200 (its first-order error in c1 and c2 is 1e-3 there)
    for n in [25, 50, 100, 200] {
        let g = grid_dissipation(&k, n, &[q_star, -q_star], 2);
        let d = [(g[0] - w0).abs() / w0, (g[1] - g[0] - w1).abs() / w1];
        println!(
            "n = {n}: W0 {:.10e} ({:.1e}), W1 {:.10e} ({:.1e})",
            g[0],
            d[0],
            g[1] - g[0],
            d[1]
        );
        if n == 100 || n == 200 {
            assert!(d[0] < 5e-5 && d[1] < 5e-5, "n = {n}: {d:?}");
        }
    }
}

/// The ply (mu = 0.3): the dissipation of the first loading 0 -> Q* = 0.6 mu P, exact path
/// in K equal load steps (T17, second order in 1/K) against the grid's backward Euler in S
/// steps (first order in 1/S) at n = 100, 200, 400 panels. Prints the table of
/// docs/theory_tangential.md section 17.
/// A measurement, not a check: compiled with the `measure` feature only (`cargo test
/// --release --features measure -- --ignored measure_ply`), so that the slow tier does not
/// spend its minutes on it.
#[cfg(feature = "measure")]
#[test]
#[ignore = "measurement: 1-2 min"]
fn measure_ply_loading_dissipation() {
    let k = ply();
    let q_star = 0.18;
    let steps: Vec<usize> = std::env::var("ORTHOSLIP_EXACT_STEPS")
        .map(|v| v.split(',').map(|s| s.parse().unwrap()).collect())
        .unwrap_or(vec![1, 2, 4, 8]);
    for kk in steps {
        let t = std::time::Instant::now();
        let mut path = ExactPath::new(&k, 1e-8, 1e-5).unwrap();
        for i in 1..=kk {
            path.load(q_star * i as f64 / kk as f64).unwrap();
        }
        println!(
            "exact K = {kk}: W0 = {:.10e} (estimate {:.1e}), D = {:.10}, {:?}",
            path.dissipated,
            path.dissipated_error,
            path.punch,
            t.elapsed()
        );
    }
    for n in [100, 200, 400] {
        for s in [10, 20, 40, 80] {
            let t = std::time::Instant::now();
            let g = grid_dissipation(&k, n, &[q_star], s);
            println!(
                "grid n = {n}, S = {s}: W0 = {:.10e}, {:?}",
                g[0],
                t.elapsed()
            );
        }
    }
}

/// The ply (mu = 0.3), first loading 0 -> Q* = 0.6 mu P in 2 and 4 equal load steps: the
/// exact path's dissipation (T17) approaches the grid's, extrapolated in its steps (40, 80:
/// backward Euler is first order) at n = 100, faster than first order in the load step
/// (docs/theory_tangential.md section 17: K = 8 and the grid at n = 200, 400 in
/// `measure_ply_loading_dissipation`).
#[test]
fn ply_loading_dissipation_approaches_the_grid() {
    let k = ply();
    let q_star = 0.18;
    let g40 = grid_dissipation(&k, 100, &[q_star], 40)[0];
    let g80 = grid_dissipation(&k, 100, &[q_star], 80)[0];
    let reference = 2.0 * g80 - g40;
    let mut w = Vec::new();
    for kk in [2, 4] {
        let mut path = ExactPath::new(&k, 1e-8, 1e-5).unwrap();
        for i in 1..=kk {
            path.load(q_star * i as f64 / kk as f64).unwrap();
        }
        w.push(path.dissipated);
    }
    let (d2, d4) = ((w[0] - reference).abs(), (w[1] - reference).abs());
    println!(
        "W0 {:.10e}, {:.10e} against the grid's {reference:.10e}",
        w[0], w[1]
    );
    assert!(d4 < d2 / 2.5 && d4 < 4e-6, "{d2:e} {d4:e}");
}

/// The ply (mu = 0.3, Q* = 0.6 mu P): the first unloading Q* -> -Q* on the exact path, its
/// first step to -0.5 Q* (one step across the corner phase above -0.47945 Q*, which
/// `ply_corner_phase_dissipation_against_the_grid` steps through), then equal steps to -Q*; prints W1 per refinement of the later steps (against
/// section 14's 2.4678765e-3 over -0.485 Q* .. -Q* and the grid's 2.4684e-3 for the branch;
/// section 21 refines both).
/// A measurement, not a check, as [`measure_ply_loading_dissipation`]: `measure` feature only.
#[cfg(feature = "measure")]
#[test]
#[ignore = "measurement: 1-6 min"]
fn measure_ply_unloading_dissipation() {
    let k = ply();
    let q_star = 0.18;
    let mut loaded = ExactPath::new(&k, 1e-8, 1e-5).unwrap();
    loaded.load(q_star).unwrap();
    for kk in [1, 2, 4] {
        let t = std::time::Instant::now();
        let mut path = loaded.clone();
        path.load(-0.5 * q_star).unwrap();
        let first = path.dissipated - loaded.dissipated;
        for i in 1..=kk {
            path.load(-q_star * (0.5 + 0.5 * i as f64 / kk as f64))
                .unwrap();
        }
        println!(
            "steps after -0.5 Q*: {kk}: W1 = {:.10e} (first step {first:.6e}, estimate {:.1e}), \
             D(-Q*) = {:.10}, {:?}",
            path.dissipated - loaded.dissipated,
            path.dissipated_error,
            path.punch,
            t.elapsed()
        );
    }
}

/// The NaN slip of docs/theory_tangential.md section 15 (section 18 has its sources): points
/// near the unloading trailing zone's stick end a2, on the ply unloaded to -Q* (tolerances
/// 1e-8, 1e-5). Points within a few ulps of a2 on either side are located by their own
/// offset 1 - x (the rounded left offset 2 - (1 - x) misplaces some of them, the first
/// source, fixed in `Frame::locate`), their tractions are finite, their slip is 0 on the
/// stick side; the slip at 1 - x = w2 (1 - f) for f from 4 eps to 1e-2, where the graded
/// rule's nodes rounded onto a2 (the second source: H[q] is NaN at a zone end), and at
/// every check fraction of the zone down to 1 - x = 1.4e-14, is a negative number.
#[test]
fn ply_slip_near_the_trailing_zone_end_is_a_number() {
    let k = ply();
    let mut path = ExactPath::new(&k, 1e-8, 1e-5).unwrap();
    path.load(0.18).unwrap();
    path.load(-0.18).unwrap();
    let Branch::Unloading { u, .. } = &path.branch else {
        panic!("not unloading")
    };
    let w2 = u.level.w2.expect("a trailing zone");
    let frame = &u.level.state.frame;
    let last = frame.zone_count() - 1;
    let mut misplaced = 0;
    for j in 1..=4 {
        for side in [1.0, -1.0] {
            let omx = w2 * (1.0 + side * j as f64 * f64::EPSILON);
            let opx = 2.0 - omx;
            let l = frame.locate(opx, omx);
            // the stick side (1 - x > w2) must be in the stick zone before the trailing one
            let want = if omx > w2 { last - 1 } else { last };
            assert_eq!(l.zone, want, "1 - x = w2 (1 {side:+} {j} eps)");
            // what the left offset alone says: 1 + x against the trailing zone's start
            if (opx < 2.0 - w2) != (omx > w2) {
                misplaced += 1;
            }
            let (p, q) = u.tractions(opx, omx);
            assert!(p.is_finite() && q.is_finite(), "{p} {q}");
            if omx > w2 {
                assert_eq!(u.slip(opx, omx), 0.0);
            }
        }
    }
    println!("the left offset misplaces {misplaced} of 8 points within 4 ulps of a2");
    assert!(misplaced > 0);
    let mut slips = Vec::new();
    for f in [
        4.0 * f64::EPSILON,
        1e-14,
        1e-12,
        1e-10,
        1e-8,
        1e-6,
        1e-4,
        1e-2,
    ] {
        let omx = w2 * (1.0 - f);
        slips.push((f, u.slip(2.0 - omx, omx)));
    }
    println!("slip at 1 - x = w2 (1 - f): {slips:?}");
    assert!(slips.iter().all(|(_, s)| s.is_finite() && *s <= 0.0));
    // and the right number: bounded tractions with the stick end's exponent g make the slip
    // grow like (a2 - x)^(1 + g) there (section 13's local exponents); from f = 1e-8 to 1e-4
    let order = (slips[6].1 / slips[4].1).ln() / 1e4f64.ln();
    let g = edge_exponent(&k);
    println!(
        "slip's exponent at a2: {order:.4} against 1 + g = {:.4}",
        1.0 + g
    );
    assert!((order - 1.0 - g).abs() < 1e-2);
    let (_, trailing) = u.zone_slips();
    println!("trailing zone's slips: {trailing:?}");
    assert!(trailing.iter().all(|(_, s)| s.is_finite() && *s < 0.0));
}

/// bp = 0: the unloading solver's slip since Q* (`Unloading::slip`, a graded integral of the
/// slope H[q] + bq p - r* from a1) equals (T16)'s e(x) - e*(x) - (D - D*) (`surface_change`,
/// a quadrature of L[q] and S[p]) in the leading zone, near a1 and at the corner, at -0.6 Q*,
/// -0.8 Q* and -Q*, and the loading's slip since the normal load (`Monotonic::slip`) at Q*
/// (docs/theory_tangential.md section 18: with the graded rules' right-end grading reversed
/// they were 1e-5 apart).
#[test]
fn goodman_slip_matches_t16() {
    let k = goodman();
    let q_star = 0.18;
    let mut loaded = ExactPath::new(&k, 1e-11, 1e-9).unwrap();
    let normal = loaded.clone();
    loaded.load(q_star).unwrap();
    // the loading's slip since the normal load (`Monotonic::slip`, graded from c2) likewise
    let Branch::Loading { m, .. } = &loaded.branch else {
        panic!("not loading")
    };
    let (_, c2) = loaded.stick_set();
    for x in [c2 + 1e-4, c2 + 0.01, 0.5, 0.9975] {
        let t16 = loaded.surface_change(&normal, x) - loaded.punch;
        let s = m.slip(1.0 + x, 1.0 - x);
        println!("Q = Q*, x = {x:.6}: slip {s:.12e}, (T16) {t16:.12e}");
        assert!(s < 0.0 && (s - t16).abs() < 1e-13, "{s:e} {t16:e}");
    }
    for frac in [-0.6, -0.8, -1.0] {
        let mut path = loaded.clone();
        path.load(frac * q_star).unwrap();
        let Branch::Unloading { u, .. } = &path.branch else {
            panic!("not unloading")
        };
        let (a1, _) = path.stick_set();
        for x in [-0.9975, a1 - 0.01, a1 - 1e-4] {
            let t16 = path.surface_change(&loaded, x) - (path.punch - loaded.punch);
            let s = u.slip(1.0 + x, 1.0 - x);
            println!("Q/Q* = {frac}, x = {x:.6}: slip {s:.12e}, (T16) {t16:.12e}");
            // (T16) differences e - e* of size 1e-2: its rounding is 1e-17 .. 1e-15 absolute
            // (measured 3e-17 .. 2e-14); the reversed grading was 3.5e-10 off at a1 - 0.01
            assert!(s > 0.0 && (s - t16).abs() < 1e-13, "{s:e} {t16:e}");
        }
    }
}

/// bp = 0 with the contact's tolerances at 1e-12, the exact run's unloading step from
/// -0.9 Q* to -0.95 Q* (20 steps per quarter cycle, Q* = 0.18 P): the loaded state's stick
/// end c2* lies 9.7e-6 inside the new leading zone (-1, a1), a cut of the slip's graded
/// rule, whose node next to it rounds to 1 + x = 1 + c2* + 1 ulp, where 2 - (1 + x) rounds
/// onto 1 - c2*. The loaded frame places that point past c2* by 1 + x and must measure its
/// offset by 1 + x too (`Frame::locate`): measured by 1 - x it was 0, the loaded forcing
/// NaN there and the step refused ("slip NaN at 1 + x = 0.661"). The step's state: its
/// forcing finite at that point, every check slip positive, the slip since Q* next to c2*
/// on both sides, near a1 and at the corner, and the step's slip ((T18a), `step_slip`) at
/// the run's nodes of n = 100 in the leading zone, each equal to (T16)'s
/// e - e_ref - (D - D_ref) (`surface_change`, a quadrature of L[q]).
#[test]
fn goodman_slip_next_to_the_loaded_stick_end_is_a_number() {
    let k = goodman();
    let q_star = 0.18;
    let mut loaded = ExactPath::new(&k, 1e-12, 1e-12).unwrap();
    loaded.load(q_star).unwrap();
    let (_, c2) = loaded.stick_set();
    let mut before = loaded.clone();
    // the run's loads: Q* + (-2 Q*) i / 40 for i = 38, 39
    before.load(q_star - 2.0 * q_star * 38.0 / 40.0).unwrap();
    let mut path = before.clone();
    path.load(q_star - 2.0 * q_star * 39.0 / 40.0).unwrap();
    let Branch::Unloading { u, .. } = &path.branch else {
        panic!("not unloading")
    };
    let (a1, _) = path.stick_set();
    println!("a1 - c2* = {:e}", a1 - c2);
    assert!(a1 > c2 && a1 - c2 < 1e-5);
    // the point next to c2* as the graded rule gives it
    let opx = (1.0 + c2).next_up();
    let omx = 2.0 - opx;
    assert_eq!(omx, 1.0 - c2);
    assert!(u.loaded.forcing(opx, omx).is_finite());
    let (leading, _) = u.zone_slips();
    assert!(leading.iter().all(|&(_, s)| s > 0.0), "{leading:?}");
    // (T16) differences e - e* of size 1e-2: rounding 1e-17 .. 1e-15 absolute
    for x in [
        -0.9975,
        0.9 * (1.0 + a1) - 1.0,
        c2 - 1e-6,
        c2 + 1e-6,
        a1 - 1e-7,
    ] {
        let s = u.slip(1.0 + x, 1.0 - x);
        let t16 = path.surface_change(&loaded, x) - (path.punch - loaded.punch);
        println!("x = {x:.9}: slip since Q* {s:.12e}, (T16) {t16:.12e}");
        assert!(s > 0.0 && (s - t16).abs() < 1e-13, "{s:e} {t16:e}");
    }
    let n = 100;
    let nodes: Vec<(f64, f64)> = (0..n)
        .map(|i| {
            (
                (i as f64 + 0.5) / n as f64,
                2.0 - (i as f64 + 0.5) / n as f64,
            )
        })
        .filter(|&(o, _)| o < 1.0 + a1)
        .collect();
    let steps = path.step_slip(&before, &nodes);
    let worst = nodes
        .iter()
        .zip(&steps)
        .map(|(&(o, _), &step)| {
            let t16 = path.surface_change(&before, o - 1.0) - (path.punch - before.punch);
            assert!(step > 0.0, "{step:e} at 1 + x = {o}");
            (step - t16).abs()
        })
        .fold(0.0, f64::max);
    println!(
        "the step's slip at {} nodes: (T16) to {worst:e} (largest {:e})",
        nodes.len(),
        steps[0]
    );
    assert!(worst < 1e-13);
}

/// The ply (mu = 0.3, Q* = 0.6 mu P): the dissipation of the first unloading's corner phase,
/// Q* -> -0.485 Q*, on the exact path (the corner's outer model down to the hand-over at
/// -0.47945 Q*, the three-zone pattern after; docs/theory_tangential.md section 21), with
/// two refinements of the load steps, against the grid LCP history: the grid's W1 over the
/// whole branch less the exact three-zone part over -0.485 Q* .. -Q*. The figures are
/// `lcp::history::tests::measure_ply_unloading_dissipation_on_the_grid` and
/// `unload::tests::measure_three_zone_phase_dissipation` (`measure` feature), each limit
/// bracketed between the geometric tails of its last two differences at the last observed
/// ratio and at the asymptotic one:
/// - the grid at N = 200, S = 160, 320, 640 steps (first order in 1/S, the differences'
///   ratio 1.954, 1.965): W1(200, inf) within [d, d / (r - 1)] of W1(200, 640);
/// - the grid's N-error at S = 160: W1(800) - W1(200) = -3.72e-8, and W1(800) - W1(400) =
///   9.3e-9 kept as the N-error left at N = 800 (the differences change sign; the steps'
///   increments agree between N = 200, 400 and 800 to 4e-10, so the steps' tail of N = 200
///   serves N = 800);
/// - the three-zone part at 8, 16, 32 steps ((T14), second order; the ratio 3.42): within
///   [d / 3, d / (r - 1)] of the 32 steps' sum.
#[test]
#[ignore = "slow: about 3.5 min, 24 loads on the ply's first unloading"]
fn ply_corner_phase_dissipation_against_the_grid() {
    let k = ply();
    let q_star = 0.18;
    // the grid at N = 200, S = 160, 320, 640, and at N = 400, 800, S = 160
    let (g160, g320, g640) = (2.4679219389e-3, 2.4681773483e-3, 2.4683073276e-3);
    let (g400, g800): (f64, f64) = (2.4678754170e-3, 2.4678847576e-3);
    let d = g640 - g320;
    let r = (g320 - g160) / d;
    let shift = g800 - g160;
    let n_left = (g800 - g400).abs();
    let grid = [
        g640 + d + shift - n_left,
        g640 + d / (r - 1.0) + shift + n_left,
    ];
    // the exact three-zone part at 8, 16, 32 steps
    let (t8, t16, t32) = (2.4680502443e-3, 2.4678929795e-3, 2.4678469721e-3);
    let dt = t16 - t32;
    let rt = (t8 - t16) / dt;
    let three_zone = [t32 - dt / (rt - 1.0), t32 - dt / 3.0];
    let (low, high) = (grid[0] - three_zone[1], grid[1] - three_zone[0]);
    println!(
        "the grid's W1 {:.7e} .. {:.7e}, the three-zone part {:.7e} .. {:.7e}: the corner \
         phase {low:.4e} .. {high:.4e}",
        grid[0], grid[1], three_zone[0], three_zone[1]
    );
    let reference = 0.5 * (low + high);
    let mut loaded = ExactPath::new(&k, 1e-8, 1e-5).unwrap();
    loaded.load(q_star).unwrap();
    let coarse = [0.9, 0.5, 0.0, -0.3, -0.45, -0.47, -0.478, -0.485];
    let fine = [
        0.9, 0.7, 0.5, 0.25, 0.0, -0.15, -0.3, -0.4, -0.45, -0.46, -0.47, -0.475, -0.478, -0.48,
        -0.4825, -0.485,
    ];
    let mut ws = Vec::new();
    for loads in [&coarse[..], &fine[..]] {
        let t = std::time::Instant::now();
        let mut path = loaded.clone();
        for f in loads {
            path.load(f * q_star).unwrap();
        }
        let w = path.dissipated - loaded.dissipated;
        println!(
            "{} loads: W(Q* -> -0.485 Q*) = {w:.6e} (estimate {:.1e}; the grid's middle \
             {reference:.4e}, apart {:.1e}), {:?}",
            loads.len(),
            path.dissipated_error,
            w - reference,
            t.elapsed()
        );
        ws.push(w);
    }
    assert!(ws.iter().all(|w| *w > low && *w < high), "{ws:?}");
}
