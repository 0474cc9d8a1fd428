//! Tests of the LCP method against independent references: Goodman's closed-form
//! condition at bp = 0, refinement of its own sequence (Richardson) for the coupled case,
//! the complementarity and friction inequalities, force balance and the reduction of
//! docs/theory.md (R2).

use super::*;
use crate::goodman::c_by_bisection;

/// Isotropic plane strain, nu = 0.3: bp = bq = (1 - 2 nu) / (2 (1 - nu)).
const STEEL: f64 = 0.4 / 1.4;

/// Carbon/epoxy ply, plane stress (docs/theory.md (M3)): (bp, bq).
pub(super) fn carbon_epoxy() -> (f64, f64) {
    let (e11, e22, g12, nu12): (f64, f64, f64, f64) = (181.0, 10.3, 7.17, 0.28);
    let e = (e11 * e22).sqrt();
    let nu = (nu12 * nu12 * e22 / e11).sqrt();
    let delta = (e11 / e22).powf(0.25);
    let kappa = e / (2.0 * g12) - nu;
    let a = (1.0 - nu) / e;
    let root = (2.0 * (1.0 + kappa)).sqrt();
    let b = root / (PI * delta * e);
    let c = delta * root / (PI * e);
    (a / (PI * c), a / (PI * b))
}

use std::f64::consts::PI;

/// Observed order from the largest errors at successive doublings of n.
fn orders(errors: &[f64]) -> Vec<f64> {
    errors.windows(2).map(|w| (w[0] / w[1]).log2()).collect()
}

#[test]
fn goodman_is_reproduced_at_bp_zero_with_first_order_convergence() {
    // bp = 0 decouples p (= p0), so c must converge to Goodman's root. The error depends
    // on the position of c within its cell, so the convergence table uses the worst error
    // over several friction coefficients (several cell positions).
    let mus = [0.12, 0.17, 0.22, 0.27, 0.33, 0.4];
    let ns = [100, 200, 400, 800];
    let mut worst = vec![0.0f64; ns.len()];
    for &mu in &mus {
        let k = Coupling {
            bp: 0.0,
            bq: STEEL,
            mu,
        };
        let exact = c_by_bisection(k.bq / mu);
        for (w, &n) in worst.iter_mut().zip(&ns) {
            let s = solve(&k, n).unwrap();
            let err = (s.edge().c - exact).abs();
            assert!(
                err <= s.numerical_error(),
                "mu {mu} n {n}: error {err:.3e} > estimate"
            );
            assert!(
                err <= 0.3 / n as f64,
                "mu {mu} n {n}: error {err:.3e} > 0.3 h"
            );
            *w = w.max(err);
        }
    }
    let ord = orders(&worst);
    println!("Goodman (bp = 0), worst |c - c_G| over mu in {mus:?}:");
    for (i, n) in ns.iter().enumerate() {
        println!(
            "  n {n:5}  {:.3e}  order {:?}",
            worst[i],
            ord.get(i.wrapping_sub(1))
        );
    }
    let overall = (worst[0] / worst[3]).log2() / 3.0;
    assert!((0.85..1.2).contains(&overall), "order {overall}: {worst:?}");
}

#[test]
fn coupled_edge_converges_to_the_richardson_limit_of_its_own_sequence() {
    // Steel, mu = 0.3. Reference: first-order Richardson 2 c_1600 - c_800.
    let k = Coupling {
        bp: STEEL,
        bq: STEEL,
        mu: 0.3,
    };
    let ns = [100, 200, 400, 800, 1600];
    let sols: Vec<LcpSolution> = ns.iter().map(|&n| solve(&k, n).unwrap()).collect();
    let c: Vec<f64> = sols.iter().map(|s| s.edge().c).collect();
    let reference = 2.0 * c[4] - c[3];
    let errors: Vec<f64> = c[..4].iter().map(|ci| (ci - reference).abs()).collect();
    println!("steel mu 0.3: c {c:?}, Richardson reference {reference:.7}");
    println!(
        "  errors (n = 100..800) {errors:?}, orders {:?}",
        orders(&errors)
    );
    for (s, e) in sols.iter().zip(&errors) {
        assert!(
            *e <= s.numerical_error(),
            "n {}: {e:.3e} > estimate",
            s.panels()
        );
    }
    assert!(errors[3] < errors[0] / 3.0, "{errors:?}");
    // Goodman neglects the coupling: a few 1e-2 above (docs/theory.md §7).
    let gap = c_by_bisection(k.bq / k.mu) - reference;
    assert!((0.01..0.1).contains(&gap), "Goodman - coupled = {gap}");
}

#[test]
fn converged_solution_is_complementary_admissible_and_balanced() {
    for (bp, bq, mu) in [(STEEL, STEEL, 0.3), (0.16228, 0.68026, 1.0)] {
        let k = Coupling { bp, bq, mu };
        let s = solve(&k, 200).unwrap();
        let (p, q) = s.panel_tractions();
        let h = 1.0 / s.panels() as f64;
        // (E4): int p = 1 (p even).
        assert!((2.0 * h * p.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        let slip_scale = s.slip().iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for i in 0..s.panels() {
            let reserve = mu * p[i] - q[i];
            let slip = s.slip()[i];
            // Complementarity: both >= 0, one of them 0 (to the Newton tolerance).
            assert!(
                slip >= -1e-10 * slip_scale && reserve >= -1e-10 * mu,
                "point {i}"
            );
            assert!(
                slip.min(reserve / mu) <= 1e-10,
                "point {i}: {slip} {reserve}"
            );
            assert!(p[i] > 0.0);
            if i < s.stick_points() {
                // Stick: |q| <= mu p (the lower bound is not imposed by the LCP).
                assert!(q[i] >= -mu * p[i], "point {i}: q {} < -mu p", q[i]);
                assert!(slip.abs() <= 1e-10 * slip_scale);
            } else {
                assert!((q[i] - mu * p[i]).abs() <= 1e-10 * mu * p[i]);
            }
        }
        // The edge lies between the last stick and the first slip midpoint.
        let e = s.edge();
        let nodes = s.nodes();
        let k_st = s.stick_points();
        assert!(k_st > 0 && k_st < s.panels());
        assert!(nodes[k_st - 1] <= e.c && e.c <= nodes[k_st]);
        assert!((e.c + e.one_minus_c - 1.0).abs() < 1e-15);
    }
}

#[test]
fn reduction_to_the_isotropic_form_gives_the_same_edge() {
    let (bp, bq) = carbon_epoxy();
    for mu in [0.3, 1.0] {
        let k = Coupling { bp, bq, mu };
        let (red, delta) = k.reduced();
        let (s, r) = (solve(&k, 100).unwrap(), solve(&red, 100).unwrap());
        assert!((s.edge().c - r.edge().c).abs() < 1e-10, "mu {mu}");
        let x = 0.5 * s.edge().c;
        let ((p1, q1), (p2, q2)) = (s.tractions(x), r.tractions(x));
        assert!((p1 - p2).abs() < 1e-10 * p1 && (q1 - delta * q2).abs() < 1e-10 * p1);
    }
}

#[test]
fn tractions_interpolate_the_bp_zero_pressure_and_the_slip_law() {
    let k = Coupling {
        bp: 0.0,
        bq: STEEL,
        mu: 0.3,
    };
    let s = solve(&k, 400).unwrap();
    for &x in &[-0.97, -0.6, -0.1, 0.0, 0.05, 0.33, 0.8, 0.99, 0.999] {
        let (p, q) = s.tractions(x);
        let p0 = 1.0 / (PI * (1.0 - x * x).sqrt());
        // The last panel (1 - |x| < h) is ~5 % low: the edge mass is not resolved there.
        let tol = if x.abs() < 0.99 { 0.02 } else { 0.06 };
        assert!((p - p0).abs() < tol * p0, "x {x}: p {p} vs {p0}");
        if x.abs() > s.edge().c + 0.01 {
            assert!((q - k.mu * p * x.signum()).abs() < 1e-9 * p, "x {x}");
        }
        let (pm, qm) = s.tractions(-x);
        assert!(pm == p && qm == -q);
    }
}

#[test]
fn no_friction_gives_no_stick_zone_and_no_shear() {
    let k = Coupling {
        bp: 0.3,
        bq: 0.3,
        mu: 0.0,
    };
    let s = solve(&k, 100).unwrap();
    assert_eq!(s.edge().c, 0.0);
    assert_eq!(s.numerical_error(), 0.0);
    assert!(s.panel_tractions().1.iter().all(|&q| q == 0.0));
    assert!((s.tractions(0.0).0 - 1.0 / PI).abs() < 2e-3);
    assert_eq!(s.tractions(0.4).1, 0.0);
}

#[test]
fn extremes_give_a_status_never_nan() {
    for b_star in [0.05, 0.5, 0.9] {
        for delta in [0.5, 2.0] {
            for mu in [1e-3, 1e-2, 0.1, 1.0, 10.0, 100.0] {
                let k = Coupling {
                    bp: b_star / delta,
                    bq: b_star * delta,
                    mu,
                };
                match solve(&k, 100) {
                    Ok(s) => {
                        let e = s.edge();
                        assert!((0.0..=1.0).contains(&e.c) && e.one_minus_c >= 0.0, "{k:?}");
                        assert!(s.numerical_error().is_finite() && s.numerical_error() > 0.0);
                        let (p, q) = s.tractions(0.7);
                        assert!(p.is_finite() && q.is_finite());
                        let (pp, qq) = s.panel_tractions();
                        for i in 0..s.stick_points() {
                            assert!(qq[i] >= -mu * pp[i], "{k:?}: q < -mu p at point {i}");
                        }
                    }
                    Err(Error::NoConvergence(m)) => println!("{k:?}: {m}"),
                    Err(e) => panic!("{k:?}: unexpected {e}"),
                }
            }
        }
    }
}

#[test]
fn large_friction_stays_on_the_branch_continuous_from_small_friction() {
    // Without the continuation in mu the LCP for b* = 0.5, mu = 100 converged to full
    // slip (c = 0); the physical branch approaches full stick with a finite slip zone.
    let mut previous = 0.0;
    for mu in [0.3, 1.0, 10.0, 100.0] {
        let s = solve(
            &Coupling {
                bp: 0.5,
                bq: 0.5,
                mu,
            },
            100,
        )
        .unwrap();
        assert!(
            s.edge().c >= previous - s.numerical_error(),
            "mu {mu}: {:?}",
            s.edge()
        );
        previous = s.edge().c;
    }
    assert!(previous > 0.99);
}

#[test]
fn invalid_arguments_and_tolerance_control() {
    let ok = Coupling {
        bp: STEEL,
        bq: STEEL,
        mu: 0.3,
    };
    for bad in [
        Coupling { bp: -0.1, ..ok },
        Coupling { bq: 0.0, ..ok },
        Coupling { mu: f64::NAN, ..ok },
        Coupling {
            bp: 1.2,
            bq: 1.0,
            mu: 0.3,
        },
    ] {
        assert!(matches!(solve(&bad, 100), Err(Error::InvalidArgument(_))));
    }
    assert!(matches!(solve(&ok, 99), Err(Error::InvalidArgument(_))));
    assert!(matches!(
        solve_to_tolerance(&ok, 0.0, f64::INFINITY),
        Err(Error::InvalidArgument(_))
    ));
    let s = solve_to_tolerance(&ok, 3e-3, f64::INFINITY).unwrap();
    assert!(s.numerical_error() <= 3e-3 && s.panels() >= 100);
    match solve_to_tolerance(&ok, 1e-5, f64::INFINITY) {
        Err(Error::ToleranceNotMet { estimate, .. }) => assert!(estimate > 1e-5),
        other => panic!("expected ToleranceNotMet, got {other:?}"),
    }
}
