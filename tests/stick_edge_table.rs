//! The tabulated exact stick edge (orthoslip::stick_edge_table) against fresh COUPLED
//! solves: at nodes of the committed patches (re-solving part of what the generator solved:
//! the interpolant must reproduce them), at random points off the nodes (seeds the
//! generator never used), continuity across the patches' shared edges, coverage of the
//! documented range (a union of rectangles: below b* = 0.25 the strips stop short of the
//! thin slip zones), and the c-alone path of the public API taking it.

use orthoslip::stick_edge_table::{coordinates, coupling_at, evaluate, lookup, nodes, patches};
use orthoslip::{Contact, Coupling, Material, Method, Profile, StickEdge, coupled};

/// COUPLED's stick edge, to a relative accuracy of about 1e-12 in lc: the panels' own root
/// search (`coupled::solve`), which never looks at the table (`coupled::solve_panels_to`
/// would: it solves the panels at the tabulated c where the table's bound meets the
/// tolerance).
fn reference(b: f64, mu: f64) -> StickEdge {
    let k = Coupling { bp: b, bq: b, mu };
    let e = coupled::solve(&k, 1e-8).expect("guess").edge();
    let tol = 4e-12 * e.c.min(e.one_minus_c);
    coupled::solve(&k, tol)
        .or_else(|_| coupled::solve(&k, 100.0 * tol))
        .expect("reference")
        .edge()
}

/// |c - c'| for the table's lc and an edge.
fn distance(lc: f64, e: StickEdge) -> f64 {
    StickEdge::from_logit(lc).distance(e)
}

#[test]
#[ignore = "slow tier: COUPLED references at two nodes of every third patch"]
fn patches_reproduce_coupled_at_their_nodes() {
    patches_reproduce_coupled_at(3, 2);
}

/// The fast tier's share of [`patches_reproduce_coupled_at_their_nodes`]: one node of every
/// twelfth patch.
#[test]
fn patches_reproduce_coupled_at_a_few_nodes() {
    patches_reproduce_coupled_at(12, 1);
}

/// `per_patch` random nodes of every `step`-th patch against COUPLED.
fn patches_reproduce_coupled_at(step: usize, per_patch: usize) {
    let mut rng = fastrand::Rng::with_seed(20261123);
    let mut worst: f64 = 0.0;
    for p in patches().iter().step_by(step) {
        let all = nodes(p.beta, p.zeta, p.rows, p.cols);
        for _ in 0..per_patch {
            let (beta, zeta) = all[rng.usize(..all.len())];
            let (b, mu) = coupling_at(beta, zeta);
            let lc = evaluate(p.coef, (p.rows, p.cols), (p.beta, p.zeta), (beta, zeta));
            let d = distance(lc, reference(b, mu));
            assert!(d <= p.bound, "node b* {b} mu~ {mu}: {d:e} > {:e}", p.bound);
            worst = worst.max(d / p.bound);
        }
    }
    eprintln!("nodes: worst error / bound {worst:.3}");
}

#[test]
#[ignore = "slow tier: a random point in every patch against COUPLED"]
fn bounds_hold_off_the_nodes() {
    bounds_hold_off_the_nodes_of(1);
}

/// The fast tier's share of [`bounds_hold_off_the_nodes`]: every eighth patch.
#[test]
fn bounds_hold_off_the_nodes_of_a_few_patches() {
    bounds_hold_off_the_nodes_of(8);
}

/// A random point in every `step`-th patch against COUPLED.
fn bounds_hold_off_the_nodes_of(step: usize) {
    let mut rng = fastrand::Rng::with_seed(97);
    let mut worst: f64 = 0.0;
    for p in patches().iter().step_by(step) {
        let beta = p.beta[0] + rng.f64() * (p.beta[1] - p.beta[0]);
        let zeta = p.zeta[0] + rng.f64() * (p.zeta[1] - p.zeta[0]);
        let (b, mu) = coupling_at(beta, zeta);
        let (lc, bound) = lookup(b, mu).expect("inside a patch");
        let d = distance(lc, reference(b, mu));
        assert!(d <= bound, "b* {b} mu~ {mu}: {d:e} > {bound:e}");
        assert!(bound <= 2e-11, "bound {bound:e} at b* {b} mu~ {mu}");
        worst = worst.max(d / bound);
    }
    eprintln!("random points: worst error / bound {worst:.3}");
}

/// Where two patches share an edge, both interpolants agree there within their bounds.
#[test]
fn no_jumps_between_patches() {
    let ps = patches();
    let mut pairs = 0;
    for (i, p) in ps.iter().enumerate() {
        for q in &ps[i + 1..] {
            let overlap = |a: [f64; 2], b: [f64; 2]| (a[0].max(b[0]), a[1].min(b[1]));
            let (b_lo, b_hi) = overlap(p.beta, q.beta);
            let (z_lo, z_hi) = overlap(p.zeta, q.zeta);
            if b_lo > b_hi || z_lo > z_hi {
                continue;
            }
            for t in [0.1, 0.5, 0.9] {
                let at = (b_lo + t * (b_hi - b_lo), z_lo + t * (z_hi - z_lo));
                let v1 = evaluate(p.coef, (p.rows, p.cols), (p.beta, p.zeta), at);
                let v2 = evaluate(q.coef, (q.rows, q.cols), (q.beta, q.zeta), at);
                let d = distance(v1, StickEdge::from_logit(v2));
                assert!(d <= p.bound + q.bound, "edge at {at:?}: {d:e}");
            }
            pairs += 1;
        }
    }
    assert!(pairs >= patches().len() - 1, "{pairs} shared edges");
}

/// The strips below b* = 0.25 as documented (docs/theory.md (T5)): (b* from, b* to,
/// zeta top), each from zeta = 0.75.
const BELOW: [(f64, f64, f64); 3] = [(0.02, 0.1, 4.0), (0.1, 0.175, 4.25), (0.175, 0.25, 4.5)];

/// The documented range is covered: b* from 0.25 to 0.99, from the full-slip law's c = 1e-11
/// up to mu~ = 4e6 (the large-friction extrapolation's last friction); below b* = 0.25 the
/// strips of [`BELOW`], and nothing outside them there (COUPLED starts from Spence's stick
/// edge there).
#[test]
fn covers_the_documented_range() {
    for i in 0..=40 {
        let b = 0.25 + (0.99 - 0.25) * i as f64 / 40.0;
        let lower = coupling_at(b.atanh(), 0.0).1;
        for j in 0..=40 {
            let mu = lower * (4e6 / lower).powf(j as f64 / 40.0);
            assert!(lookup(b, mu).is_some(), "b* {b} mu~ {mu}");
        }
        assert!(coordinates(b, lower).1.abs() < 1e-12);
    }
    for (b0, b1, top) in BELOW {
        for i in 0..=20 {
            let beta = b0.atanh() + (b1.atanh() - b0.atanh()) * i as f64 / 20.0;
            for j in 0..=20 {
                let zeta = 0.75 + (top - 0.75) * j as f64 / 20.0;
                let (b, mu) = coupling_at(beta, zeta);
                assert!(lookup(b, mu).is_some(), "b* {b} mu~ {mu}");
            }
            if i < 20 {
                // the edges of the strips (b* < 0.25: the table above starts at zeta = 0)
                for zeta in [0.7, top + 0.05] {
                    let (b, mu) = coupling_at(beta, zeta);
                    assert!(lookup(b, mu).is_none(), "b* {b} zeta {zeta}: tabulated");
                }
            }
        }
    }
    let (b, mu) = coupling_at(0.019f64.atanh(), 2.0);
    assert!(lookup(b, mu).is_none(), "b* {b} mu~ {mu}: tabulated");
}

/// Every patch below b* = 0.25 (the strips of [`BELOW`]), where `per_patch` random points of
/// each are checked against the panels' root search (`reference`): the error within the
/// patch's bound.
fn strips_below_hold_at(per_patch: usize, step: usize, seed: u64) {
    let mut rng = fastrand::Rng::with_seed(seed);
    let (mut worst, mut n): (f64, usize) = (0.0, 0);
    let below: Vec<_> = patches()
        .iter()
        .filter(|p| p.beta[1] <= 0.25f64.atanh() + 1e-12)
        .collect();
    assert!(below.len() >= BELOW.len(), "{} patches below", below.len());
    for p in below.iter().step_by(step) {
        for _ in 0..per_patch {
            let beta = p.beta[0] + rng.f64() * (p.beta[1] - p.beta[0]);
            let zeta = p.zeta[0] + rng.f64() * (p.zeta[1] - p.zeta[0]);
            let (b, mu) = coupling_at(beta, zeta);
            let (lc, bound) = lookup(b, mu).expect("inside a patch");
            let d = distance(lc, reference(b, mu));
            assert!(d <= bound, "b* {b} mu~ {mu}: {d:e} > {bound:e}");
            assert!(bound <= 2e-11, "bound {bound:e} at b* {b} mu~ {mu}");
            worst = worst.max(d / bound);
            n += 1;
        }
    }
    eprintln!("{n} points below b* = 0.25: worst error / bound {worst:.3}");
}

#[test]
#[ignore = "slow tier: two random points in every patch below b* = 0.25 against the panels"]
fn strips_below_hold_at_random_points() {
    strips_below_hold_at(2, 1, 20261127);
}

/// The fast tier's share of [`strips_below_hold_at_random_points`]: one point in every third
/// patch below b* = 0.25.
#[test]
fn strips_below_hold_at_a_few_random_points() {
    strips_below_hold_at(1, 3, 27);
}

/// Beyond mu~ = 1e7 c alone is the table's extrapolation in 1/mu~; it agrees with the
/// panels' own (three panel solves) within the two estimates, and within 1e-10.
#[test]
fn large_friction_from_the_table() {
    for b in [0.3, 0.6, 0.95] {
        for mu in [1e8, 1e12] {
            let k = Coupling { bp: b, bq: b, mu };
            let table = coupled::solve_to(&k, 1e-10, f64::INFINITY).unwrap();
            assert_eq!(table.unknowns(), 0, "b* {b} mu~ {mu}: not the table");
            let panels = coupled::solve(&k, 1e-10).unwrap();
            let d = table.edge().distance(panels.edge());
            let both = table.numerical_error() + panels.numerical_error();
            assert!(d <= both && d <= 1e-10, "b* {b} mu~ {mu}: {d:e} ({both:e})");
        }
    }
}

/// c alone through the public API (traction tolerance +infinity): the table's answer, its
/// estimate within the tolerance and c within it of COUPLED with its tractions.
#[test]
fn c_alone_takes_the_table() {
    let ply = Material::plane_stress(181e9, 10.3e9, 7.17e9, 0.28).unwrap();
    for mu in [0.1, 0.3, 1.0, 30.0] {
        let mut k = Contact::new(ply);
        k.set_friction(mu).unwrap();
        k.set_method(Method::Coupled);
        k.set_tolerance(1e-10).unwrap();
        k.set_traction_tolerance(f64::INFINITY).unwrap();
        let s = k.solve().unwrap();
        assert!(s.error_estimate() <= 1e-10);
        let full = coupled::solve(&ply.coupling(mu), 1e-12).unwrap();
        let d = s.edge().distance(full.edge());
        assert!(d <= 1e-10, "mu {mu}: {d:e}");
        let (p, q) = s.tractions(0.5);
        assert!(p > 0.0 && q.is_finite());
    }
}
