//! Checks of Spence's approximation against independent references: tanh-sinh quadrature of
//! the defining integrals, Goodman's equation through `ellip::ellipk`, the (E2) residual of
//! q_S by quadrature, and the reduction (R2) of docs/theory.md.

use super::*;
use crate::error::Error;
use crate::goodman;

/// Adaptive tanh-sinh quadrature of f on [a, b]; f receives the node t and its distances
/// t - a and b - t (exact even where t rounds to an end). The step is halved until two
/// successive estimates agree to `tol` (relative).
fn tanh_sinh(f: &dyn Fn(f64, f64, f64) -> f64, a: f64, b: f64, tol: f64) -> f64 {
    let len = b - a;
    let mut prev = f64::NAN;
    for level in 0..14 {
        let h = 0.5f64.powi(level);
        let kmax = (6.5 / h) as i64;
        let mut sum = 0.0;
        for k in -kmax..=kmax {
            let t = k as f64 * h;
            let u = 0.5 * PI * t.sinh();
            let e = (-2.0 * u.abs()).exp();
            // sech^2(u) = 4 e / (1 + e)^2; distances to the ends (b - a) / (1 + exp(-+2u)).
            let w = 0.5 * len * h * 0.5 * PI * t.cosh() * 4.0 * e / ((1.0 + e) * (1.0 + e));
            let (dl, dr) = if u < 0.0 {
                (len * e / (1.0 + e), len / (1.0 + e))
            } else {
                (len / (1.0 + e), len * e / (1.0 + e))
            };
            if w == 0.0 || dl == 0.0 || dr == 0.0 {
                continue;
            }
            let x = if dl < dr { a + dl } else { b - dr };
            sum += w * f(x, dl, dr);
        }
        if level >= 3 && (sum - prev).abs() <= tol * sum.abs() {
            return sum;
        }
        prev = sum;
    }
    panic!("tanh-sinh did not converge on [{a}, {b}]: last {prev}");
}

/// int_0^c (1 - x^2)^(-g) / sqrt(c^2 - x^2) dx, with 1 - c given exactly.
fn left_integral(g: f64, c: f64, one_minus_c: f64) -> f64 {
    let f = |x: f64, _: f64, dr: f64| {
        let one_m_x = one_minus_c + dr;
        (one_m_x * (2.0 - one_m_x)).powf(-g) / (dr.sqrt() * (c + x).sqrt())
    };
    tanh_sinh(&f, 0.0, c, 1e-15)
}

/// int_c^1 (1 - t^2)^(-g) / sqrt(t^2 - c^2) dt.
fn right_integral(g: f64, c: f64) -> f64 {
    let f = |t: f64, dl: f64, dr: f64| {
        (dr.powf(-g) * (1.0 + t).powf(-g)) / (dl.sqrt() * (t + c).sqrt())
    };
    tanh_sinh(&f, c, 1.0, 1e-15)
}

fn steel() -> f64 {
    let nu = 0.3;
    (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu))
}

#[test]
fn compatibility_sides_match_quadrature() {
    for h in [0.0, 1e-9, 0.03, 0.25, 0.49] {
        let ln_beta = ln_gamma(0.5 + h) + 0.5 * PI.ln() - ln_gamma(1.0 + h);
        let comp = Compatibility::new(1.0, 1.0, h, ln_beta);
        // c exactly representable, so that the quadrature sees the same c as the series.
        for c in [
            1e-9,
            0.05,
            0.4,
            0.7,
            0.9,
            0.999,
            1.0 - 1.0 / 1024.0 / 1024.0 / 256.0,
        ] {
            let one_minus_c = 1.0 - c;
            let m1 = one_minus_c * (1.0 + c);
            let v = Split {
                m: c * c,
                m1,
                ln_m: 2.0 * c.ln(),
                ln_m1: m1.ln(),
            };
            let ((fl, _), (fr, _)) = comp.factors(&v);
            let left = 0.5 * PI * fl;
            let right = 0.5 * (ln_beta + h * v.ln_m1).exp() * fr;
            let (ql, qr) = (
                left_integral(0.5 - h, c, one_minus_c),
                right_integral(0.5 - h, c),
            );
            assert!(
                (left / ql - 1.0).abs() < 2e-14,
                "h {h} c {c}: left {left} vs {ql}"
            );
            assert!(
                (right / qr - 1.0).abs() < 2e-14,
                "h {h} c {c}: right {right} vs {qr}"
            );
        }
    }
}

/// The root c found by Newton's method satisfies the compatibility condition with both sides
/// by quadrature: bq int_0^c p / sqrt(c^2 - x^2) = mu int_c^1 p / sqrt(t^2 - c^2).
#[test]
fn root_satisfies_compatibility_by_quadrature() {
    for (bp, bq, mu) in [
        (steel(), steel(), 0.1),
        (steel(), steel(), 0.3),
        (steel(), steel(), 1.0),
        (0.162, 0.68, 0.3),
        (0.9, 0.9, 3.0),
        (0.03, 3.2, 1.0),
        (0.5, 0.1, 0.05),
    ] {
        let s = solve(&Coupling { bp, bq, mu }).unwrap();
        let (g, e) = (s.edge_exponent(), s.edge());
        let left = bq * left_integral(g, e.c, e.one_minus_c);
        let right = mu * right_integral(g, e.c);
        assert!(
            (left / right - 1.0).abs() < 1e-13,
            "bp {bp} bq {bq} mu {mu}: c = {}, {left} vs {right}",
            e.c
        );
    }
}

#[test]
fn reduces_to_goodman_at_zero_bp() {
    for (bq, mu) in [
        (0.2857, 0.1),
        (0.2857, 0.3),
        (0.2857, 1.0),
        (0.5, 0.2),
        (0.05, 0.3),
    ] {
        let k = Coupling { bp: 0.0, bq, mu };
        let s = solve(&k).unwrap();
        assert_eq!(s.edge_exponent(), 0.5);
        let c = goodman::c_by_bisection(bq / mu);
        let e = s.edge();
        assert!((e.c - c).abs() < 1e-12, "bq {bq} mu {mu}: {} vs {c}", e.c);
        assert!(s.numerical_error() < 1e-13 && s.numerical_error() > 0.0);
    }
    // Relative accuracy of c and 1 - c at the extremes, against the theta-function closed form.
    for ratio in [0.02, 0.1, 1.0, 7.0, 40.0] {
        let s = solve(&Coupling {
            bp: 0.0,
            bq: ratio,
            mu: 1.0,
        })
        .unwrap();
        let (e, r) = (s.edge(), goodman::stick_edge(ratio));
        // Relative error of c ~ EPSILON |ln c^2| (c = exp(s/2)): 1e-13 at c ~ 1e-27.
        assert!(
            (e.c - r.c).abs() <= s.numerical_error(),
            "ratio {ratio}: c {} vs {}",
            e.c,
            r.c
        );
        assert!(s.numerical_error() <= 1e-12 * e.c);
        let rel = (e.one_minus_c / r.one_minus_c - 1.0).abs();
        assert!(
            rel < 1e-13,
            "ratio {ratio}: 1 - c {} vs {}",
            e.one_minus_c,
            r.one_minus_c
        );
    }
}

/// H[q](x) = (1/pi) PV int q(t) / (x - t) dt for |x| < c: the stick part of the given q by
/// subtracting q(x), the slip parts q = mu p sgn t with p = (1 - t^2)^(-g) / norm.
fn hilbert_of_shear(s: &SpenceSolution, mu: f64, norm: f64, x: f64) -> f64 {
    let c = s.edge().c;
    let g = s.edge_exponent();
    let qx = s.tractions(x).1;
    // x - t from the exact distances: dr on [-c, x], -dl on [x, c].
    let below = |t: f64, _: f64, dr: f64| (s.tractions(t).1 - qx) / dr;
    let above = |t: f64, dl: f64, _: f64| (qx - s.tractions(t).1) / dl;
    let stick = tanh_sinh(&below, -c, x, 1e-14)
        + tanh_sinh(&above, x, c, 1e-14)
        + qx * ((c + x) / (c - x)).ln();
    // -mu int_c^1 p(t) 2t / (t^2 - x^2) dt
    let slip = |t: f64, _: f64, dr: f64| {
        -mu * (dr * (1.0 + t)).powf(-g) / norm * 2.0 * t / ((t - x) * (t + x))
    };
    (stick + tanh_sinh(&slip, c, 1.0, 1e-14)) / PI
}

/// int_{-1}^{1} (1 - t^2)^(-g) dt by quadrature.
fn pressure_mass(g: f64) -> f64 {
    2.0 * tanh_sinh(
        &|t: f64, _, dr: f64| (dr * (1.0 + t)).powf(-g),
        0.0,
        1.0,
        1e-15,
    )
}

#[test]
fn stick_shear_solves_e2() {
    let b = steel();
    let cases = [
        Coupling {
            bp: b,
            bq: b,
            mu: 0.1,
        },
        Coupling {
            bp: b,
            bq: b,
            mu: 0.3,
        },
        Coupling {
            bp: b,
            bq: b,
            mu: 1.0,
        },
        Coupling {
            bp: 0.0,
            bq: b,
            mu: 0.4,
        },
        Coupling {
            bp: 0.2,
            bq: 0.8,
            mu: 0.6,
        },
        Coupling {
            bp: 0.9,
            bq: 0.9,
            mu: 3.0,
        },
    ];
    for k in cases {
        let s = solve(&k).unwrap();
        let norm = pressure_mass(s.edge_exponent());
        let c = s.edge().c;
        for frac in [0.0, 0.3, 0.7, 0.95, 0.999] {
            let x = frac * c;
            let p = (1.0 - x * x).powf(-s.edge_exponent()) / norm;
            let residual = hilbert_of_shear(&s, k.mu, norm, x) + k.bq * p;
            assert!(
                residual.abs() < 1e-12 * k.bq * p,
                "{k:?} x = {x}: H[q] + bq p = {residual:e}"
            );
        }
    }
}

#[test]
fn shear_continuous_at_stick_edge() {
    let b = steel();
    for k in [
        Coupling {
            bp: b,
            bq: b,
            mu: 0.3,
        },
        Coupling {
            bp: b,
            bq: b,
            mu: 10.0,
        },
        Coupling {
            bp: 0.5,
            bq: 0.1,
            mu: 0.05,
        },
    ] {
        let s = solve(&k).unwrap();
        let e = s.edge();
        let d = 1e-9 * e.one_minus_c.min(e.c);
        let (p_in, q_in) = s.tractions(e.c - d);
        let (p_out, q_out) = s.tractions(e.c + d);
        assert!(
            (q_in / q_out - 1.0).abs() < 1e-4,
            "{k:?}: {q_in} vs {q_out}"
        );
        assert!((p_in / p_out - 1.0).abs() < 1e-8);
        assert!((q_out - k.mu * p_out).abs() <= 1e-15 * q_out);
    }
}

#[test]
fn pressure_is_normalised() {
    // int p = 1 with p from `tractions` on [0, 1 - d] and the edge form
    // p = A (1 - x^2)^(-g) (A fitted at 1 - d) on [1 - d, 1].
    for k in [
        Coupling {
            bp: 0.0,
            bq: 0.3,
            mu: 0.3,
        },
        Coupling {
            bp: 0.3,
            bq: 0.3,
            mu: 0.5,
        },
        Coupling {
            bp: 0.9,
            bq: 0.5,
            mu: 100.0,
        },
    ] {
        let s = solve(&k).unwrap();
        let g = s.edge_exponent();
        let d = 1e-3;
        let inner = tanh_sinh(&|t, _, _| s.tractions(t).0, 0.0, 1.0 - d, 1e-15);
        let a = s.tractions(1.0 - d).0 * (d * (2.0 - d)).powf(g);
        let tail = tanh_sinh(
            &|t: f64, _, dr: f64| a * (dr * (1.0 + t)).powf(-g),
            1.0 - d,
            1.0,
            1e-15,
        );
        let total = 2.0 * (inner + tail);
        assert!((total - 1.0).abs() < 1e-13, "{k:?}: int p = {total}");
    }
}

#[test]
fn reduction_to_isotropic_form() {
    for (bp, bq, mu) in [(0.2, 0.8, 0.4), (0.9, 0.1, 2.0), (0.05, 0.6, 0.02)] {
        let k = Coupling { bp, bq, mu };
        let (kr, delta) = k.reduced();
        let (s, sr) = (solve(&k).unwrap(), solve(&kr).unwrap());
        let (e, er) = (s.edge(), sr.edge());
        let tol = s.numerical_error() + sr.numerical_error();
        assert!((e.c - er.c).abs() <= tol, "{k:?}: {} vs {}", e.c, er.c);
        assert!(tol < 1e-12 * e.c, "{k:?}: error estimate {tol}");
        assert!((e.one_minus_c / er.one_minus_c - 1.0).abs() < 1e-13);
        for x in [0.0, 0.2, -0.5, 0.9 * e.c, e.c + 0.5 * e.one_minus_c, -0.999] {
            let ((p, q), (pr, qr)) = (s.tractions(x), sr.tractions(x));
            assert!((p - pr).abs() <= 1e-14 * p, "{k:?} x {x}: p {p} vs {pr}");
            assert!(
                (q - delta * qr).abs() <= 1e-12 * p * mu,
                "{k:?} x {x}: q {q} vs {}",
                delta * qr
            );
        }
    }
}

#[test]
fn zero_friction_is_frictionless() {
    let s = solve(&Coupling {
        bp: 0.4,
        bq: 0.4,
        mu: 0.0,
    })
    .unwrap();
    assert_eq!(s.edge(), StickEdge::from_c(0.0));
    assert_eq!(s.numerical_error(), 0.0);
    let (p, q) = s.tractions(0.5);
    assert!((p - 1.0 / (PI * 0.75f64.sqrt())).abs() < 1e-15);
    assert_eq!(q, 0.0);
}

#[test]
fn invalid_couplings_are_rejected() {
    for (bp, bq, mu) in [
        (-0.1, 0.3, 0.3),
        (0.3, 0.0, 0.3),
        (0.3, 0.3, -1.0),
        (f64::NAN, 0.3, 0.3),
    ] {
        assert!(matches!(
            solve(&Coupling { bp, bq, mu }),
            Err(Error::InvalidArgument(_))
        ));
    }
}

#[test]
fn extremes_stay_finite() {
    let xs = [0.0, 1e-30, 0.3, 0.9, 1.0 - 1e-9, -(1.0 - 1e-15)];
    for b in [1e-3, 0.05, steel(), 0.7, 0.95] {
        for mu in [1e-4, 1e-3, 0.01, 0.1, 1.0, 10.0, 100.0, 1e3] {
            let k = Coupling { bp: b, bq: b, mu };
            let s = solve(&k).unwrap();
            let e = s.edge();
            // c is the nearest double: it is 1.0 only where 1 - c < 2^-53, carried by
            // one_minus_c (which underflows to 0 below 1e-308, e.g. b* = 1e-3, mu = 1).
            assert!(
                e.c >= 0.0 && e.c <= 1.0 && e.one_minus_c >= 0.0,
                "{k:?}: {e:?}"
            );
            assert!(e.c < 1.0 || e.one_minus_c < f64::EPSILON, "{k:?}: {e:?}");
            assert!(
                e.one_minus_c > 0.0 || b * mu >= 1e-3 && mu / b > 500.0,
                "{k:?}: {e:?}"
            );
            assert!(s.numerical_error().is_finite() && s.numerical_error() <= 1e-12);
            let mut probe: Vec<f64> = xs.to_vec();
            probe.extend([0.5 * e.c, e.c * (1.0 - 1e-12), e.c + 0.5 * e.one_minus_c]);
            for x in probe.into_iter().filter(|x| x.abs() < 1.0) {
                let (p, q) = s.tractions(x);
                assert!(
                    p.is_finite() && p > 0.0 && q.is_finite(),
                    "{k:?} x {x}: {p} {q}"
                );
            }
        }
    }
}

/// Below mu ~ 3e-7 b* the root of the compatibility condition lies beyond
/// ln(c^2 / (1 - c^2)) = -1e7, so c^2 < exp(-1e7): c is 0 in floating point, as Goodman's c
/// (theta functions) is there, and the tractions are the full-slip ones, q = mu p.
#[test]
fn stick_zone_below_the_smallest_double_is_empty() {
    for b in [0.05, 0.5, 0.99] {
        for mu in [1e-7 * b, 1e-12, 1e-300, f64::MIN_POSITIVE] {
            let k = Coupling { bp: b, bq: b, mu };
            let s = solve(&k).unwrap_or_else(|e| panic!("{k:?}: {e}"));
            assert_eq!(goodman::solve(&k).unwrap().edge().c, 0.0, "{k:?}");
            let e = s.edge();
            assert!(e.c == 0.0 && e.one_minus_c == 1.0, "{k:?}: {e:?}");
            assert_eq!(s.numerical_error(), 0.0);
            for x in [0.3, -0.9, 1.0 - 1e-12] {
                let (p, q) = s.tractions(x);
                let g = s.edge_exponent();
                let p_s = ((1.0 - x) * (1.0 + x)).powf(-g) / pressure_mass(g);
                assert!(
                    (p - p_s).abs() <= 1e-12 * p_s,
                    "{k:?} x {x}: p {p}, p_S {p_s}"
                );
                assert_eq!(q, mu * p * x.signum(), "{k:?} x {x}");
            }
        }
    }
}

#[test]
fn stick_shear_is_admissible() {
    // |q| <= mu p on the stick zone (docs/theory.md (I1)), on a grid refined towards c.
    for b in [0.05, steel(), 0.7, 0.95] {
        for mu in [0.01, 0.1, 0.3, 1.0, 10.0, 1e3] {
            let s = solve(&Coupling { bp: b, bq: b, mu }).unwrap();
            let e = s.edge();
            let uniform = (1..200).map(|i| e.c * i as f64 / 200.0);
            let towards_c = (1..60).map(|k| e.c - e.c * 0.5f64.powi(k));
            for x in uniform.chain(towards_c).filter(|&x| x < e.c) {
                let (p, q) = s.tractions(x);
                assert!(
                    q.abs() <= mu * p * (1.0 + 1e-13),
                    "b {b} mu {mu} x {x}: {q} vs {}",
                    mu * p
                );
            }
        }
    }
}
