//! No NaN or infinity ever comes with status OK (issue 8, point 2): over the reduced plane
//! (b* = 0.01 .. 0.99, mu~ = 0 and 1e-3 .. 1e6; docs/theory.md (R2): the material
//! `effective(1, 1 - 2 b*, 1, 1)` with mu = mu~) and at extreme engineering materials, every
//! method through `Contact`, whenever it returns Ok: c and 1 - c are finite and in [0, 1],
//! the error estimates on c and on the tractions are not NaN (+infinity only for a closed
//! form beyond its model-error table), and the tractions at many x in (-1, 1) (also within
//! 1e-15 of the stick edge and of the punch edges) are finite. The documented p = +inf,
//! q = +-inf at x = +-1 are checked as such.

use orthoslip::{Contact, Material, Method};

const B_STAR: [f64; 10] = [0.01, 0.05, 0.1, 0.2, 0.3, 0.45, 0.6, 0.8, 0.9, 0.99];
const MU_TILDE: [f64; 11] = [0.0, 1e-3, 1e-2, 0.1, 1.0, 10.0, 100.0, 1e3, 1e4, 1e5, 1e6];
const METHODS: [Method; 5] = [
    Method::Goodman,
    Method::Spence,
    Method::Coupled,
    Method::Lcp,
    Method::Auto,
];

/// The points: a spread over (-1, 1), and points within 1e-15 .. 1e-3 of +-c and of +-1.
fn points(c: f64, one_minus_c: f64) -> Vec<f64> {
    let mut xs: Vec<f64> = (1..200).map(|i| -1.0 + i as f64 / 100.0).collect();
    for d in [1e-15, 1e-12, 1e-9, 1e-6, 1e-3] {
        for x in [c * (1.0 - d), c + one_minus_c * d, 1.0 - d] {
            if x.abs() < 1.0 {
                xs.extend([x, -x]);
            }
        }
    }
    xs
}

/// What is wrong with the answer of `contact`, if anything (a refusal is fine).
fn check(contact: &Contact, method: Method, scene: &str, solved: &mut usize) -> Vec<String> {
    let Ok(s) = contact.solve() else {
        return Vec::new();
    };
    *solved += 1;
    let closed_form = matches!(s.method(), Method::Goodman | Method::Spence);
    let (c, w) = (s.c(), s.one_minus_c());
    let (ec, et) = (s.error_estimate(), s.traction_error_estimate());
    let mut bad = Vec::new();
    let at = format!("{scene}, {method:?} (as {:?})", s.method());
    if !(c.is_finite() && w.is_finite() && (0.0..=1.0).contains(&c) && (0.0..=1.0).contains(&w)) {
        bad.push(format!("{at}: c = {c}, 1 - c = {w}"));
    }
    for (what, e) in [("c", ec), ("traction", et)] {
        if !(e >= 0.0 && (e.is_finite() || closed_form)) {
            bad.push(format!("{at}: {what} error estimate {e}"));
        }
    }
    for x in points(c, w) {
        let (p, q) = s.tractions(x);
        if !(p.is_finite() && q.is_finite()) {
            bad.push(format!("{at}: tractions ({p}, {q}) at x = {x:e}"));
            break;
        }
    }
    let (p, q) = s.tractions(1.0);
    let mu = s.coupling().mu;
    if p != f64::INFINITY || q != if mu == 0.0 { 0.0 } else { f64::INFINITY } {
        bad.push(format!("{at}: ({p}, {q}) at x = 1"));
    }
    bad
}

fn sweep(scenes: Vec<(String, Material, f64)>) {
    let mut bad = Vec::new();
    let mut solved = 0;
    for (scene, m, mu) in &scenes {
        for method in METHODS {
            let mut contact = Contact::new(*m);
            contact.set_friction(*mu).unwrap();
            contact.set_method(method);
            // the LCP at its coarsest estimated grid: its answers, not its accuracy, are tested
            let tol = if method == Method::Lcp { 0.5 } else { 1e-6 };
            contact.set_tolerance(tol).unwrap();
            if method == Method::Lcp {
                contact.set_traction_tolerance(f64::INFINITY).unwrap();
            }
            bad.extend(check(&contact, method, scene, &mut solved));
        }
    }
    println!(
        "{solved} answers of {} solves checked",
        scenes.len() * METHODS.len()
    );
    assert!(
        bad.is_empty(),
        "{} bad answers:\n{}",
        bad.len(),
        bad.join("\n")
    );
}

/// The scenes of the reduced plane at these b* and mu~.
fn reduced_plane_at(b_star: &[f64], mu_tilde: &[f64]) {
    let mut scenes = Vec::new();
    for &b in b_star {
        let m = Material::effective(1.0, 1.0 - 2.0 * b, 1.0, 1.0).unwrap();
        for &mu in mu_tilde {
            scenes.push((format!("b* = {b}, mu~ = {mu:e}"), m, mu));
        }
    }
    sweep(scenes);
}

/// The fast tier's part of the plane: every other b* and mu~ of the slow tier's grid, the
/// corners among them.
#[test]
fn reduced_plane() {
    let every_other = |v: &[f64]| -> Vec<f64> {
        let mut kept: Vec<f64> = v.iter().step_by(2).copied().collect();
        kept.push(v[v.len() - 1]);
        kept.dedup();
        kept
    };
    reduced_plane_at(&every_other(&B_STAR), &every_other(&MU_TILDE));
}

#[test]
#[ignore = "slow tier: the reduced plane's whole grid, 110 scenes by every method"]
fn reduced_plane_wide() {
    reduced_plane_at(&B_STAR, &MU_TILDE);
}

#[test]
fn extreme_materials() {
    let e = |nu: f64, delta: f64, kappa: f64| Material::effective(70e9, nu, delta, kappa).unwrap();
    let materials = [
        ("nu = 1 - 1e-9", e(1.0 - 1e-9, 1.0, 1.0)),
        ("kappa = -nu + 1e-12", e(0.3, 1.0, -0.3 + 1e-12)),
        ("delta = 1e-3", e(0.3, 1e-3, 1.0)),
        ("delta = 1e3", e(0.3, 1e3, 1.0)),
        ("auxetic nu = -0.98", e(-0.98, 1.0, 1.0)),
        (
            "plane strain nu = 0.499",
            Material::plane_strain(70e9, 70e9, 70e9, 70e9 / 2.998, 0.499, 0.499, 0.499).unwrap(),
        ),
        (
            "carbon/epoxy ply",
            Material::plane_stress(181e9, 10.3e9, 7.17e9, 0.28).unwrap(),
        ),
    ];
    let mut scenes = Vec::new();
    for (name, m) in materials {
        for mu in [0.0, 1e-3, 0.3, 10.0, 1e4] {
            scenes.push((format!("{name}, mu = {mu:e}"), m, mu));
        }
    }
    sweep(scenes);
}

/// What the hostile-input test (tests/c/hostile.c, issue 26) found, each at its root:
/// - friction next to 0 (down to the smallest subnormal, 4.9e-324): COUPLED and AUTO take the
///   full-slip limit, whose stick-zone pressure p_fs(c) = c^(2g - 1) / ... had ln c = -inf
///   times 2g - 1 = 0 (NaN at x = 0); the product is now formed as one, and tends to
///   1 / (pi (1 - b*^2));
/// - large friction (the extrapolation in 1/mu~) exactly at x = c: p < 0 and q ~ -mu;
/// - stresses at depths beyond ~1e154 (|z|^2 overflows) and at -DBL_MAX: NaN;
/// - the slip within a subnormal distance of c = 0: NaN;
/// - moduli whose compliances overflow (subnormal E): accepted with A = +inf;
/// - stresses where delta < 1e-154 (seeds 7 and 11 of the C program): NaN at every depth.
#[test]
fn hostile_extremes() {
    let steel = Material::effective(1.0, 0.3, 1.0, 1.0).unwrap();
    let b = steel.b_star();
    for mu in [f64::from_bits(1), 1e-310, 1e-300, 1e-100, 1e-20] {
        for method in [
            Method::Coupled,
            Method::Auto,
            Method::Goodman,
            Method::Spence,
        ] {
            let mut k = Contact::new(steel);
            k.set_friction(mu).unwrap();
            k.set_method(method);
            let s = k.solve().unwrap();
            let (p, q) = s.tractions(0.0);
            assert!(
                p.is_finite() && p > 0.0 && q == 0.0,
                "{method:?} mu = {mu:e}: p(0) = {p}"
            );
            if method == Method::Coupled {
                let limit = 1.0 / (std::f64::consts::PI * (1.0 - b * b));
                assert!(
                    (p / limit - 1.0).abs() < 1e-12,
                    "mu = {mu:e}: p(0) = {p}, {limit}"
                );
            }
            for x in [f64::from_bits(1), 1e-300, 0.5] {
                let u = s.slip(x).unwrap();
                assert!(!u.is_nan(), "{method:?} mu = {mu:e}: slip({x:e}) = {u}");
            }
        }
    }
    // the extrapolation in 1/mu~ at its own stick edge, and the next doubles
    let m =
        Material::effective(1.0, -0.581_344_605_779_446_2, 1.0, 0.581_345_057_387_163_7).unwrap();
    for mu in [1e7, 1e300] {
        let mut k = Contact::new(m);
        k.set_friction(mu).unwrap();
        k.set_method(Method::Coupled);
        let s = k.solve().unwrap();
        let c = s.c();
        for x in [c.next_down(), c, c.next_up(), c + 1e-15] {
            let (p, q) = s.tractions(x);
            assert!(
                p >= 0.0 && (0.0..100.0).contains(&q),
                "mu = {mu:e}, x - c = {:e}: ({p}, {q})",
                x - c
            );
        }
        for y in [-1e160, -f64::MAX] {
            for x in [0.0, c, 1.0, 3.0] {
                let st = s.stresses(x, y).unwrap();
                assert!(
                    st.iter().all(|v| v.is_finite()),
                    "stresses at ({x}, {y:e}): {st:?}"
                );
            }
        }
    }
    // delta ~ 1e-300: the characteristic roots ~ delta put the points x + i beta y of any
    // finite depth within 1e-300 of the axis, where the stresses are their surface limits,
    // infinite under the punch edges (hostile draws of seeds 7 and 11: NaN at every depth);
    // delta = 1e-200 at a depth that the surface limit does not take (1e-200 |y| = 1e-55):
    // finite (NaN before, through 1 / (beta1 - beta2))
    for (nu, delta, kappa, mu) in [
        (0.999_999_999_999, 1e-300, -0.999_996_418_586_739_7, 0.0),
        (
            -0.493_298_062_786_569_5,
            f64::MIN_POSITIVE,
            0.493_298_063_609_631_8,
            1.3e5,
        ),
        (0.3, 1e-250, 3.0, 0.3),
    ] {
        let m = Material::effective(1.0, nu, delta, kappa).unwrap();
        let mut k = Contact::new(m);
        k.set_friction(mu).unwrap();
        let s = k.solve().unwrap();
        for x in [0.0, 0.3, 0.99] {
            let surface = s.stresses(x, 0.0).unwrap();
            for y in [-1e-3, -0.5, -1e10] {
                let st = s.stresses(x, y).unwrap();
                assert!(
                    st == surface,
                    "delta = {delta:e}, stresses at ({x}, {y:e}): {st:?}, surface {surface:?}"
                );
            }
        }
        for y in [-1e-3, -0.5, -1e10] {
            let st = s.stresses(1.0, y).unwrap();
            assert!(
                st[0] == f64::NEG_INFINITY && st[1] == f64::NEG_INFINITY && !st[2].is_nan(),
                "delta = {delta:e}, stresses at (1, {y:e}): {st:?}"
            );
        }
    }
    let m = Material::effective(1.0, 0.3, 1e-200, 0.5).unwrap();
    let mut k = Contact::new(m);
    k.set_friction(0.3).unwrap();
    let s = k.solve().unwrap();
    for x in [0.0, 0.5, 1.0, 3.0] {
        for y in [-1e145, -1e160, -f64::MAX] {
            let st = s.stresses(x, y).unwrap();
            assert!(
                st.iter().all(|v| v.is_finite()),
                "delta = 1e-200, stresses at ({x}, {y:e}): {st:?}"
            );
        }
    }
    // compliances beyond the double range are refused, not reported as infinite
    for e in [f64::from_bits(1), 1e-310] {
        assert!(matches!(
            Material::effective(e, 0.3, 1.0, 1.0),
            Err(orthoslip::Error::InvalidArgument(_))
        ));
    }
}

/// What 1000 hostile draws (seed 2026, tolerances next to 0) found beyond the slow tier's
/// 250, each at its root (issue 26):
/// - mu = 1.8e308 (edge exponent g = 2.2e-309): NaN stresses and slip next to x = +-1, the
///   near-field transform dividing by sin(pi g) (draw 518);
/// - the near-bonded regime with its slip layer below the panels' resolution: a negative
///   edge intensity read off the bonded field (draw 657);
/// - COUPLED for c alone (traction tolerance +infinity): OK with a traction estimate of
///   +infinity (draws 593, 880);
/// - stresses at the punch edge at depths below 1e-150 (taken as the surface): sxx = -inf
///   beside a finite syy for delta = 1e150 (draw 761);
/// - tolerances below what the solvers can meet: solves of many minutes (draw 843: 305 s at
///   1e-16), now worked to [`orthoslip::TOLERANCE_FLOOR`] and refused naming it.
#[test]
fn hostile_thousand() {
    let m =
        Material::effective(1.0, -0.581_344_605_779_446_2, 1.0, 0.581_345_057_387_163_7).unwrap();
    let mut k = Contact::new(m);
    k.set_friction(f64::MAX).unwrap();
    k.set_method(Method::Coupled);
    let s = k.solve().unwrap();
    for x in [1.0 - 1e-15, 1.0f64.next_down(), (-1.0f64).next_up()] {
        for y in [0.0, -f64::from_bits(1), -1e-300] {
            let st = s.stresses(x, y).unwrap();
            assert!(st.iter().all(|v| v.is_finite()), "({x}, {y:e}): {st:?}");
        }
        assert!(s.slip(x).unwrap().is_finite(), "slip at {x}");
    }

    let ply = Material::plane_stress(
        116_377_763.537_167_98,
        16_928.902_393_884_968,
        23_147.972_022_880_655,
        2.147_772_744_294_554_2,
    )
    .unwrap();
    let mut k = Contact::new(ply);
    k.set_friction(561_850_230.505_563_4).unwrap();
    k.set_tolerance(0.9).unwrap();
    let s = k.solve().unwrap();
    let (kk, g) = s.edge_intensity();
    assert!(s.one_minus_c() < 1e-15, "1 - c = {:e}", s.one_minus_c());
    assert!(kk.is_finite() && kk > 0.0, "k = {kk}");
    assert_eq!(g, s.coupling().edge_exponent());
    // a layer whose k exceeds the double range (1 - c = 0 in doubles): the bonded field's
    let m = Material::effective(
        0.001_494_116_741_265_517_7,
        0.999_999_999_999,
        0.000_486_351_101_641_479_1,
        -0.999_999_995_666_719_3,
    )
    .unwrap();
    let mut k = Contact::new(m);
    k.set_friction(41.986_720_455_961_54).unwrap();
    k.set_method(Method::Coupled);
    k.set_tolerance(0.003).unwrap();
    let (kk, g) = k.solve().unwrap().edge_intensity();
    assert!(kk.is_finite() && kk > 0.0 && g == 0.5, "k = {kk}, g = {g}");

    let m = Material::effective(
        0.080_446_735_035_804_25,
        -0.502_803_943_615_720_1,
        0.596_794_376_277_849_8,
        0.502_803_943_617_944_6,
    )
    .unwrap();
    let mut k = Contact::new(m);
    k.set_friction(278_062_693.589_523_4).unwrap();
    k.set_method(Method::Coupled);
    k.set_traction_tolerance(f64::INFINITY).unwrap();
    let s = k.solve().unwrap();
    assert!(s.traction_error_estimate().is_finite());

    // the punch edge at depths that take the surface values (below 1e-150): the edge's
    // infinities, not sxx = -inf (delta^2 = 1e300 times ~1e150) beside a finite syy
    let m = Material::effective(
        0.004_289_966_311_589_816,
        0.483_862_651_392_763_74,
        1e150,
        -0.483_842_191_197_848_55,
    )
    .unwrap();
    let mut k = Contact::new(m);
    k.set_method(Method::Spence);
    let s = k.solve().unwrap();
    for y in [0.0, -f64::from_bits(1), -1e-300] {
        for x in [-1.0, 1.0] {
            let st = s.stresses(x, y).unwrap();
            assert_eq!(
                st,
                [f64::NEG_INFINITY, f64::NEG_INFINITY, 0.0],
                "({x}, {y:e})"
            );
        }
    }

    let carbon = Material::plane_stress(181e9, 10.3e9, 7.17e9, 0.28).unwrap();
    for method in [Method::Coupled, Method::Lcp] {
        let mut k = Contact::new(carbon);
        k.set_friction(0.3).unwrap();
        k.set_method(method);
        k.set_tolerance(1e-100).unwrap();
        let start = std::time::Instant::now();
        match k.solve() {
            Err(orthoslip::Error::ToleranceNotMet { detail, .. }) => {
                assert!(detail.contains("tolerance floor 1e-12"), "{detail}")
            }
            other => panic!("{method:?} at 1e-100: {other:?}"),
        }
        assert!(
            start.elapsed().as_secs() < 60,
            "{method:?}: {:?}",
            start.elapsed()
        );
    }
}
