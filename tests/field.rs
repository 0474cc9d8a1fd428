//! The stress field, edge intensity and slip (issue 10) checked by what any elastic field
//! must satisfy, independently of how it is computed: the resultant of the tractions on a
//! line y = -h is the punch load, differential equilibrium and strain compatibility with the
//! material's compliances hold (finite differences), the surface values are the tractions
//! and the field tends to them, the double root kappa = 1 is continuous with its
//! neighbours, the slip at mu = 0 is -(1 - nu) arcsin(x) / pi, and the edge intensity is
//! what a fit of p near the edge gives. In every material regime (kappa > 1, = 1, < 1) and
//! for every method.

use std::f64::consts::PI;

use faer::complex::Complex;
use orthoslip::{Contact, Material, Method, Solution};

type C = Complex<f64>;

/// The three regimes: the carbon/epoxy ply (kappa ~ 2.9), isotropic steel in plane strain
/// (kappa = 1, the double root) and a stiff-shear ply (kappa ~ 0.23, a complex pair).
fn materials() -> [(&'static str, Material); 3] {
    [
        (
            "ply (kappa > 1)",
            Material::plane_stress(181e9, 10.3e9, 7.17e9, 0.28).unwrap(),
        ),
        (
            "steel (kappa = 1)",
            Material::effective(210e9, 0.3 / 0.7, 1.0, 1.0).unwrap(),
        ),
        (
            "stiff shear (kappa < 1)",
            Material::plane_stress(100e9, 50e9, 80e9, 0.3).unwrap(),
        ),
    ]
}

fn solve(m: Material, mu: f64, method: Method) -> Solution {
    let mut c = Contact::new(m);
    c.set_friction(mu).unwrap();
    c.set_method(method);
    if method == Method::Lcp {
        c.set_tolerance(1e-2).unwrap();
    }
    c.solve().unwrap()
}

/// A solve at mu = 0.3 with c to 1e-12, so that the comparisons with quadratures of
/// `tractions` at depth 1e-6 below c see no error of the stick edge.
fn solve_tight(m: Material, method: Method) -> Solution {
    let mut contact = Contact::new(m);
    contact.set_friction(0.3).unwrap();
    contact.set_method(method);
    contact.set_tolerance(1e-12).unwrap();
    // c to 1e-12; the tractions to the field's own target (COUPLED's traction estimate
    // does not reach 1e-12)
    contact.set_traction_tolerance(1e-8).unwrap();
    contact.solve().unwrap()
}

const METHODS: [Method; 4] = [
    Method::Goodman,
    Method::Spence,
    Method::Coupled,
    Method::Lcp,
];

fn stress(s: &Solution, x: f64, y: f64) -> [f64; 3] {
    s.stresses(x, y).unwrap()
}

/// Gauss-Legendre nodes and weights on [a, b] (10 points).
fn gauss(a: f64, b: f64) -> impl Iterator<Item = (f64, f64)> {
    let (m, h) = (0.5 * (a + b), 0.5 * (b - a));
    gauss_legendre(10)
        .into_iter()
        .map(move |(t, w)| (m + h * t, h * w))
}

/// int syy dx = -1 and int sxy dx = 0 over y = -h (for LCP: the same on every line, the
/// equilibrium of the layer between them): 400 panels on |x| < 2, and beyond x = +-2/s (the
/// integrand decays like 1/x^2, smooth in s).
#[test]
fn resultant_on_a_line_is_the_punch_load() {
    for (name, m) in materials() {
        for method in METHODS {
            let s = solve(m, 0.3, method);
            let mut first: Option<(f64, f64)> = None;
            for h in [0.05, 0.7, 3.0] {
                let (mut fx, mut fy) = (0.0, 0.0);
                let mut add = |x: f64, w: f64| {
                    let st = stress(&s, x, -h);
                    fx += st[2] * w;
                    fy += st[1] * w;
                };
                for i in 0..400 {
                    let a = -2.0 + i as f64 / 100.0;
                    gauss(a, a + 0.01).for_each(|(x, w)| add(x, w));
                }
                for i in 0..20 {
                    let a = i as f64 / 20.0;
                    for (t, w) in gauss(a, a + 0.05) {
                        let (x, dx) = (2.0 / t, 2.0 / (t * t));
                        add(x, w * dx);
                        add(-x, w * dx);
                    }
                }
                // LCP's tractions (interpolated between its grid midpoints) carry a force
                // 1 + O(h^2) of their own: the lines must agree with each other
                let (load, allowed) = if method == Method::Lcp {
                    (*first.get_or_insert((fx, fy)), 1e-9)
                } else {
                    ((0.0, -1.0), 1e-9)
                };
                assert!(
                    (fy - load.1).abs() < allowed && (fx - load.0).abs() < allowed,
                    "{name} {method:?} h {h}: resultant ({fx:e}, {fy}) vs {load:?}"
                );
                if method == Method::Lcp {
                    assert!((fy + 1.0).abs() < 1e-3 && fx.abs() < 1e-12);
                }
            }
        }
    }
}

/// Fourth-order central differences of the field with step d.
fn derivative(f: &dyn Fn(f64) -> f64, v: f64, d: f64) -> f64 {
    (8.0 * (f(v + d) - f(v - d)) - (f(v + 2.0 * d) - f(v - 2.0 * d))) / (12.0 * d)
}

/// d/dx sxx + d/dy sxy = 0, d/dx sxy + d/dy syy = 0, and compatibility
/// d2 exx/dy2 + d2 eyy/dx2 = 2 d2 exy/dxdy with exx = s11 sxx + s12 syy,
/// eyy = s12 sxx + s22 syy, exy = s66 sxy (tensor shear strain, paper eq. (1)), relative to
/// the size of the terms, at points inside, near the surface, below the stick edge and the
/// punch edge.
#[test]
fn equilibrium_and_compatibility() {
    for (name, m) in materials() {
        let s11 = m.compliances();
        let (c11, c12, c22, c66) = (s11.s11, s11.s12, s11.s22, s11.s66);
        for method in [Method::Coupled, Method::Goodman, Method::Lcp] {
            let s = solve(m, 0.3, method);
            let c = s.c();
            for (x, y) in [
                (0.2, -0.3),
                (c, -0.01),
                (0.98, -0.02),
                (1.3, -0.1),
                (-0.6, -1.5f64),
            ] {
                let d = 1e-3 * y.abs().min(0.1);
                let s = &s;
                let dx = |i: usize| derivative(&|v| stress(s, v, y)[i], x, d);
                let dy = |i: usize| derivative(&|v| stress(s, x, v)[i], y, d);
                let scale = (0..3).map(|i| dx(i).abs() + dy(i).abs()).sum::<f64>();
                let e1 = (dx(0) + dy(2)).abs() / scale;
                let e2 = (dx(2) + dy(1)).abs() / scale;
                assert!(
                    e1 < 1e-8 && e2 < 1e-8,
                    "{name} {method:?} ({x}, {y}): {e1:e} {e2:e}"
                );
                // compatibility from second differences of the strains
                let strain = |xx: f64, yy: f64| {
                    let t = stress(s, xx, yy);
                    (c11 * t[0] + c12 * t[1], c12 * t[0] + c22 * t[1], c66 * t[2])
                };
                let h = 2.0 * d;
                let e = |i: i32, j: i32| strain(x + i as f64 * h, y + j as f64 * h);
                let exx_yy = (e(0, 1).0 - 2.0 * e(0, 0).0 + e(0, -1).0) / (h * h);
                let eyy_xx = (e(1, 0).1 - 2.0 * e(0, 0).1 + e(-1, 0).1) / (h * h);
                let exy_xy = (e(1, 1).2 - e(1, -1).2 - e(-1, 1).2 + e(-1, -1).2) / (4.0 * h * h);
                let size = exx_yy.abs() + eyy_xx.abs() + 2.0 * exy_xy.abs();
                let r = (exx_yy + eyy_xx - 2.0 * exy_xy).abs() / size;
                assert!(
                    r < 1e-4,
                    "{name} {method:?} ({x}, {y}): compatibility {r:e}"
                );
            }
        }
    }
}

/// At y = 0: syy = -p and sxy = q (each method's own tractions), and the field tends to its
/// surface values (continuity up to the surface, also across x = c).
#[test]
fn surface_limits() {
    for (name, m) in materials() {
        for method in METHODS {
            let s = solve(m, 0.3, method);
            let c = s.c();
            for x in [0.0, 0.3 * c, 0.9 * c, c, 0.5 * (1.0 + c), 0.99, -0.7, 1.2] {
                // COUPLED's field and tractions are the same series; the field's surface
                // values are limits of its Cauchy transforms (rounding ~1e-10 on the panels at c)
                let coupled = method == Method::Coupled;
                // at c the reference is the limit from the stick side, where p is smooth, and
                // q = mu p there; COUPLED's one-sided limits differ by its discretisation error
                // (~2e-8: the field at c takes their mean), the others' by rounding (LCP's
                // interpolated tractions are continuous, but q != mu p at its c)
                let (p, q, allowed) = if x == c && method != Method::Lcp {
                    let p = s.tractions(c - 1e-14).0;
                    (p, 0.3 * p, if coupled { 1e-7 } else { 1e-11 })
                } else {
                    let (p, q) = s.tractions(x);
                    (p, q, if coupled { 1e-9 } else { 1e-11 })
                };
                let st = stress(&s, x, 0.0);
                let scale = p.max(0.1);
                assert!(
                    (st[1] + p).abs() < allowed * scale && (st[2] - q).abs() < allowed * scale,
                    "{name} {method:?} x {x}: {st:?} vs p {p}, q {q}"
                );
                // approach: the difference falls at least like sqrt(depth) (like depth^g at c)
                let mut last = f64::INFINITY;
                for depth in [1e-4, 1e-6, 1e-8, 1e-10] {
                    let near = stress(&s, x, -depth);
                    let gap = (0..3).map(|i| (near[i] - st[i]).abs()).fold(0.0, f64::max);
                    assert!(
                        gap < 1e-5_f64.max(20.0 * depth.powf(0.4)),
                        "{name} {method:?} x {x} depth {depth}: {gap:e}"
                    );
                    assert!(
                        gap <= last * 1.01 + 1e-12,
                        "{name} {method:?} x {x}: not converging"
                    );
                    last = gap;
                }
            }
        }
    }
}

/// kappa = 1 (the double root, derivative form) is continuous with kappa = 1 -+ 1e-9 (a
/// complex pair and two real roots, divided differences).
#[test]
fn double_root_is_continuous() {
    let solve_kappa = |kappa: f64| {
        solve(
            Material::effective(1.0, 0.25, 1.3, kappa).unwrap(),
            0.4,
            Method::Coupled,
        )
    };
    let at_one = solve_kappa(1.0);
    for kappa in [1.0 - 1e-9, 1.0 + 1e-9, 1.0 - 1e-6, 1.0 + 1e-6] {
        let s = solve_kappa(kappa);
        for (x, y) in [
            (0.1, -1e-6),
            (0.5, -0.05),
            (0.99, -1e-3),
            (1.01, -1e-4),
            (0.0, -2.0),
            (3.0, -0.5),
        ] {
            let (a, b) = (stress(&at_one, x, y), stress(&s, x, y));
            let gap = (0..3).map(|i| (a[i] - b[i]).abs()).fold(0.0, f64::max);
            // the tractions themselves move by O(kappa - 1)
            let allowed = 1e-8 + 20.0 * (kappa - 1.0f64).abs();
            assert!(gap < allowed, "kappa {kappa} ({x}, {y}): {a:?} vs {b:?}");
        }
    }
}

/// Frictionless: c = 0, q = 0, p = 1 / (pi sqrt(1 - x^2)), so the slip is
/// -(1 - nu) int_0^x p = -(1 - nu) arcsin(x) / pi (per P/E, every material).
#[test]
fn frictionless_slip_is_arcsin() {
    for (name, m) in materials() {
        let nu = m.constants().nu;
        for method in [Method::Goodman, Method::Coupled] {
            let s = solve(m, 0.0, method);
            for x in [0.0, 0.2, -0.5, 0.9, 0.999999, 1.0] {
                let u = s.slip(x).unwrap();
                let exact = -(1.0 - nu) * x.asin() / PI;
                assert!(
                    (u - exact).abs() < 1e-12,
                    "{name} {method:?} x {x}: {u} vs {exact}"
                );
            }
        }
    }
}

/// The slip is 0 on the stick zone, negative on 0 < c < x < 1 (the solid slides inward),
/// odd, continuous at c (like (x - c)^(1 + g)) and at the punch edge.
#[test]
fn slip_shape() {
    for (name, m) in materials() {
        for method in METHODS {
            let s = solve(m, 0.3, method);
            let c = s.c();
            assert_eq!(s.slip(0.5 * c).unwrap(), 0.0);
            assert!(s.slip(c + 1e-9).unwrap().abs() < 1e-9, "{name} {method:?}");
            let mut last = 0.0;
            for i in 1..=40 {
                let x = c + (1.0 - c) * i as f64 / 40.0;
                let u = s.slip(x).unwrap();
                assert!(u < 0.0 && u <= last + 1e-12, "{name} {method:?} x {x}: {u}");
                assert_eq!(s.slip(-x).unwrap(), -u);
                last = u;
            }
            let edge = s.slip(1.0).unwrap();
            assert!((s.slip(1.0 - 1e-10).unwrap() - edge).abs() < 1e-4);
            assert!((s.slip(1.0 + 1e-10).unwrap() - edge).abs() < 1e-4);
        }
    }
}

/// The edge intensity against a fit of p near the edge: (1 - x)^g p(x) -> k, and the log
/// slope of p -> -g; GOODMAN's k = 1 / (pi sqrt 2) with g = 1/2.
#[test]
fn edge_intensity_matches_a_fit() {
    for (name, m) in materials() {
        for method in [Method::Goodman, Method::Spence, Method::Coupled] {
            let s = solve(m, 0.3, method);
            let (k, g) = s.edge_intensity();
            let (d1, d2) = (1e-8, 1e-9);
            let (p1, p2) = (s.tractions(1.0 - d1).0, s.tractions(1.0 - d2).0);
            let slope = (p2 / p1).ln() / (d2 / d1).ln();
            assert!(
                (slope + g).abs() < 1e-6,
                "{name} {method:?}: slope {slope} vs -g = {}",
                -g
            );
            let fit = p2 * d2.powf(g);
            assert!(
                (fit - k).abs() < 1e-7 * k,
                "{name} {method:?}: k {k} vs fit {fit}"
            );
            let (q, mu) = (s.tractions(1.0 - d2).1, 0.3);
            assert!((q - mu * p2).abs() < 1e-12 * p2);
            if method == Method::Goodman {
                assert!((k - 1.0 / (PI * 2f64.sqrt())).abs() < 1e-14 && g == 0.5);
            } else {
                let bp = s.coupling().bp;
                assert!((g - (0.5 - (bp * mu).atan() / PI)).abs() < 1e-15);
            }
        }
    }
}

/// sxx(x, 0) near the punch edge follows its documented singularity:
/// -k [delta^2 + delta sqrt(2 (1 + kappa)) mu cot(pi g)] (1 - x)^(-g).
#[test]
fn surface_sxx_edge_singularity() {
    for (name, m) in materials() {
        let e = m.constants();
        for method in [Method::Goodman, Method::Spence, Method::Coupled] {
            let s = solve(m, 0.3, method);
            let (k, g) = s.edge_intensity();
            let amp = -k
                * (e.delta * e.delta
                    + e.delta * (2.0 * (1.0 + e.kappa)).sqrt() * 0.3 / (PI * g).tan());
            let d = 1e-10;
            let sxx = stress(&s, 1.0 - d, 0.0)[0];
            let ratio = sxx / (amp * d.powf(-g));
            assert!(
                (ratio - 1.0).abs() < 1e-3,
                "{name} {method:?}: ratio {ratio}"
            );
        }
    }
}

#[test]
fn bad_points_are_rejected() {
    let s = solve(materials()[0].1, 0.3, Method::Goodman);
    assert!(s.stresses(f64::NAN, -1.0).is_err());
    assert!(s.stresses(0.0, 1e-300).is_err());
    assert!(s.stresses(0.0, f64::NEG_INFINITY).is_err());
    assert!(s.slip(f64::INFINITY).is_err());
    let edge = stress(&s, 1.0, 0.0);
    assert_eq!(edge, [f64::NEG_INFINITY, f64::NEG_INFINITY, f64::INFINITY]);
}

/// Gauss-Legendre rule with n points on [-1, 1] (Newton on the three-term recurrence).
fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    // P_n(t) and P_n'(t)
    let legendre = |t: f64| {
        let (mut p0, mut p1) = (1.0, t);
        for k in 1..n {
            let kf = k as f64;
            (p0, p1) = (p1, ((2.0 * kf + 1.0) * t * p1 - kf * p0) / (kf + 1.0));
        }
        (p1, n as f64 * (t * p1 - p0) / (t * t - 1.0))
    };
    (0..n)
        .map(|i| {
            let mut t = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            loop {
                let (p, dp) = legendre(t);
                t -= p / dp;
                if (p / dp).abs() < 1e-16 {
                    let dp = legendre(t).1;
                    return (t, 2.0 / ((1.0 - t * t) * dp * dp));
                }
            }
        })
        .collect()
}

/// Pieces of [lo, hi] graded geometrically (ratio 2, down to 2^-levels of each gap) towards
/// every break point from both sides; the last piece at each break point reaches it unless
/// `open` says that end stays open (then the last 2^-levels are left out).
fn graded(breaks: &[f64], lo: f64, hi: f64, levels: i32, open: f64) -> Vec<(f64, f64)> {
    let mut pts: Vec<f64> = breaks
        .iter()
        .copied()
        .filter(|&b| lo < b && b < hi)
        .collect();
    pts.extend([lo, hi]);
    pts.sort_by(f64::total_cmp);
    pts.dedup();
    let mut out = Vec::new();
    for pair in pts.windows(2) {
        let (u, v) = (pair[0], pair[1]);
        let m = 0.5 * (u + v);
        for k in 0..=levels {
            let far = (0.5f64).powi(k);
            let near = if k == levels { 0.0 } else { 0.5 * far };
            if k < levels || u != open {
                out.push((u + (m - u) * near, u + (m - u) * far));
            }
            if k < levels || v != open {
                out.push((v - (v - m) * far, v - (v - m) * near));
            }
        }
    }
    out
}

/// D = 1e-4 rounded to a distance from 1 that 1 - D holds exactly.
fn edge_width() -> f64 {
    1.0 - (1.0 - 1e-4)
}

/// int_{-1}^{1} f(x - t, p(t), q(t)) dt over the tractions of `s`, an independent quadrature
/// (x - t passed so that a kernel peaked at t = x next to a punch edge keeps its accuracy):
/// 20 Gauss points on each piece of [`graded`] towards every break point, on |t| < 1 - D with
/// D = 1e-4. On the last D at each punch edge, where the rounding of x = 1 - s would spoil p,
/// p = s^(-g) A(s) with g the method's exponent and A a cubic least-squares fit of p s^g at
/// 200 points of [D/8, D], and q = p q(1 - D)/p(1 - D) (q = mu p on a slip edge), integrated in
/// s the same way down to 2^-60 D and by the leading term below.
fn integral(
    s: &Solution,
    x: f64,
    breaks: &[f64],
    f: &dyn Fn(f64, f64, f64) -> [f64; 4],
) -> [f64; 4] {
    let rule = gauss_legendre(20);
    let k = s.coupling();
    let g = match s.method() {
        Method::Goodman => 0.5,
        _ => 0.5 - (k.bp * k.mu).atan() / PI,
    };
    let dist = |d: f64| 1.0 - (1.0 - d);
    let d0 = edge_width();
    let samples: Vec<(f64, f64)> = (0..200)
        .map(|j| {
            let d = dist(d0 * (0.125 + 0.875 * j as f64 / 199.0));
            (d / d0, s.tractions(1.0 - d).0 * d.powf(g))
        })
        .collect();
    let basis = nalgebra::DMatrix::from_fn(200, 4, |r, c| samples[r].0.powi(c as i32));
    let values = nalgebra::DVector::from_fn(200, |r, _| samples[r].1);
    let fit = basis.svd(true, true).solve(&values, 1e-15).unwrap();
    let model = |d: f64| {
        let u = d / d0;
        d.powf(-g) * (fit[0] + u * (fit[1] + u * (fit[2] + u * fit[3])))
    };
    let (p0, q0) = s.tractions(1.0 - d0);
    let ratio = q0 / p0;
    let mut sum = [0.0; 4];
    let mut pieces = |list: Vec<(f64, f64)>, node: &dyn Fn(f64) -> (f64, f64, f64)| {
        for (a, b) in list {
            let (c, h) = (0.5 * (a + b), 0.5 * (b - a));
            for &(t, w) in &rule {
                let (x, p, q) = node(c + h * t);
                let v = f(x, p, q);
                (0..4).for_each(|i| sum[i] += h * w * v[i]);
            }
        }
    };
    pieces(graded(breaks, d0 - 1.0, 1.0 - d0, 50, f64::NAN), &|t| {
        let (p, q) = s.tractions(t);
        (x - t, p, q)
    });
    // the edges, in s = 1 - |t|, graded towards s = 0 and the point's own distance
    let mut rest = [0.0; 4];
    for sign in [1.0, -1.0] {
        let own: Vec<f64> = breaks.iter().map(|b| 1.0 - sign * b).collect();
        pieces(graded(&own, 0.0, d0, 60, 0.0), &|d| {
            let p = model(d);
            ((x - sign) + sign * d, p, sign * ratio * p)
        });
        // what `graded` left open: [0, (first / 2) 2^-60], first the break point next to 0
        let first = own
            .iter()
            .copied()
            .filter(|&b| 0.0 < b && b < d0)
            .fold(d0, f64::min);
        let r = first * (0.5f64).powi(61);
        let mass = model(r) * r / (1.0 - g);
        let v = f(x - sign, mass, sign * ratio * mass);
        (0..4).for_each(|i| rest[i] += v[i]);
    }
    (0..4).for_each(|i| sum[i] += rest[i]);
    sum
}

/// Reference stresses by quadrature of the method's tractions, an independent route: the
/// Lekhnistskii potentials root by root (mu_k = i beta_k, F_k = (i/2) (a_k G_p + b_k G_q),
/// a_1 + a_2 = 1, mu_1 a_1 + mu_2 a_2 = 0, b_1 + b_2 = 0, mu_1 b_1 + mu_2 b_2 = 1) for
/// kappa != 1, and Flamant's line-load kernels for the isotropic material (kappa = delta = 1).
fn reference(s: &Solution, m: &Material, x: f64, y: f64) -> [f64; 3] {
    let e = m.constants();
    let c = s.c();
    let breaks = |re: f64| vec![-c, 0.0, c, re];
    if e.kappa == 1.0 {
        assert_eq!(e.delta, 1.0);
        let depth = -y;
        let v = integral(s, x, &breaks(x), &|r, p, q| {
            let d = (r * r + depth * depth).powi(2);
            let k = 2.0 / (PI * d);
            // normal load p (into the solid) and tangential load q (+x) at t
            [
                -k * (p * r * r * depth + q * r * r * r),
                -k * (p * depth.powi(3) + q * r * depth * depth),
                k * (p * r * depth * depth + q * r * r * depth),
                0.0,
            ]
        });
        return [v[0], v[1], v[2]];
    }
    let b = e.delta * (0.5 * (1.0 + e.kappa)).sqrt();
    let half = e.delta * C::new(0.5 * (e.kappa - 1.0), 0.0).sqrt();
    let i = C::new(0.0, 1.0);
    let mu = [i * (b + half), i * (b - half)];
    let a = [mu[1] / (mu[1] - mu[0]), -mu[0] / (mu[1] - mu[0])];
    let bb = [1.0 / (mu[0] - mu[1]), -1.0 / (mu[0] - mu[1])];
    let mut out = [0.0; 3];
    for k in 0..2 {
        // z = x + w, G_f(z) = (1/pi) int f(t) / ((x - t) + w) dt, real and imaginary parts
        let w = mu[k] * y;
        let v = integral(s, x, &breaks(x + w.re), &|r, p, q| {
            let w = 1.0 / (PI * (w + r));
            [p * w.re, p * w.im, q * w.re, q * w.im]
        });
        let f = 0.5 * i * (a[k] * C::new(v[0], v[1]) + bb[k] * C::new(v[2], v[3]));
        out[0] += 2.0 * (mu[k] * mu[k] * f).re;
        out[1] += 2.0 * f.re;
        out[2] -= 2.0 * (mu[k] * f).re;
    }
    out
}

/// Stresses to 1e-8 of p(0) at depth >= 1e-6: near the surface, below the stick edges and the
/// punch edges, inside and outside the punch, in every regime and for every method with
/// smooth tractions, against [`reference`].
#[test]
fn stresses_match_quadrature_of_the_tractions() {
    for (name, m) in materials() {
        for method in [Method::Goodman, Method::Spence, Method::Coupled] {
            let s = solve_tight(m, method);
            let c = s.c();
            let p0 = s.tractions(0.0).0;
            let mut worst: f64 = 0.0;
            for (x, y) in [
                (0.0, -1e-6),
                (0.3, -1e-6),
                (c, -1e-6),
                (-c, -1e-6),
                (c + 1e-6, -1e-6),
                (c, -1e-3),
                (0.999, -1e-6),
                (1.0, -1e-6),
                (-1.0, -1e-5),
                (1.000_001, -1e-6),
                (1.2, -1e-6),
                (0.7, -0.05),
                (0.5, -0.5),
                (-0.2, -2.0),
                (3.0, -1.0),
            ] {
                let (a, r) = (stress(&s, x, y), reference(&s, &m, x, y));
                let gap = (0..3).map(|i| (a[i] - r[i]).abs()).fold(0.0, f64::max) / p0;
                worst = worst.max(gap);
                assert!(
                    gap < 1e-8,
                    "{name} {method:?} ({x}, {y}): {a:?} vs {r:?}: {gap:e}"
                );
            }
            println!("{name} {method:?}: worst |field - quadrature| / p(0) = {worst:.1e}");
        }
    }
}

/// Frictionless, p = 1 / (pi sqrt(1 - x^2)) has the closed-form Cauchy transform
/// G(z) = 1 / (pi sqrt(z - 1) sqrt(z + 1)), so the Lekhnistskii potentials root by root give
/// the exact stresses (kappa != 1): to 1e-10 of p(0) (stresses up to ~300 there) right next to the punch edges and the
/// surface, for GOODMAN and COUPLED (whose mu = 0 solution is this p).
#[test]
fn frictionless_stresses_are_the_closed_form() {
    for (name, m) in materials() {
        let e = m.constants();
        if e.kappa == 1.0 {
            continue;
        }
        let b = e.delta * (0.5 * (1.0 + e.kappa)).sqrt();
        let half = e.delta * C::new(0.5 * (e.kappa - 1.0), 0.0).sqrt();
        let i = C::new(0.0, 1.0);
        let mu = [i * (b + half), i * (b - half)];
        let a = [mu[1] / (mu[1] - mu[0]), -mu[0] / (mu[1] - mu[0])];
        for method in [Method::Goodman, Method::Coupled] {
            let s = solve(m, 0.0, method);
            let p0 = 1.0 / PI;
            for (x, y) in [
                (0.0, -1e-6),
                (0.5, -1e-6),
                (0.999, -1e-6),
                (1.0, -1e-6),
                (-1.0, -1e-6),
                (1.000_001, -1e-6),
                (1.0, -1e-3),
                (-1.3, -0.2),
                (0.2, -3.0),
            ] {
                let mut exact = [0.0; 3];
                for k in 0..2 {
                    // z - 1 and z + 1 formed from x -+ 1 (exact here) and the offset mu y
                    let w = mu[k] * y;
                    let g = 1.0 / (PI * ((w + (x - 1.0)).sqrt() * (w + (x + 1.0)).sqrt()));
                    let f = 0.5 * i * a[k] * g;
                    exact[0] += 2.0 * (mu[k] * mu[k] * f).re;
                    exact[1] += 2.0 * f.re;
                    exact[2] -= 2.0 * (mu[k] * f).re;
                }
                let st = stress(&s, x, y);
                let gap = (0..3).map(|i| (st[i] - exact[i]).abs()).fold(0.0, f64::max) / p0;
                assert!(
                    gap < 1e-10,
                    "{name} {method:?} ({x}, {y}): {st:?} vs {exact:?}: {gap:e}"
                );
            }
        }
    }
}

/// sxx(x, 0) = -delta^2 p - delta sqrt(2 (1 + kappa)) H[q] on the punch (Lekhnistskii at the
/// surface), with H[q](x) by [`integral`]: (1/pi) int (q(t) - q(x)) / (x - t) dt on
/// |t| < 1 - D plus (q(x)/pi) ln((1 - D + x)/(1 - D - x)), and (1/pi) int q(t) / (x - t) dt
/// beyond. To 1e-8 of p(0) across the stick edges and up to 2e-4 from the punch edges.
#[test]
fn surface_sxx_matches_quadrature() {
    for (name, m) in materials() {
        let e = m.constants();
        let shear = e.delta * (2.0 * (1.0 + e.kappa)).sqrt();
        for method in [Method::Goodman, Method::Spence, Method::Coupled] {
            let s = solve_tight(m, method);
            let (c, p0) = (s.c(), s.tractions(0.0).0);
            let mut worst: f64 = 0.0;
            // COUPLED's `tractions` carry its wrong-c modes, ~1e-15 (c - x)^(g - 1) at this
            // tolerance: harmless in the field's quadrature but not in the subtracted
            // (q(t) - q(c)) / (c - t) at c itself, so that point is left to the others
            let at_c = if method == Method::Coupled {
                c + 1e-9
            } else {
                c
            };
            for x in [
                0.0,
                0.5 * c,
                c - 1e-6,
                at_c,
                c + 1e-6,
                -c - 1e-9,
                0.5 * (1.0 + c),
                0.99,
                0.9998,
                -0.9998,
            ] {
                let (p, q) = if x == c {
                    let p = s.tractions(c - 1e-14).0;
                    (p, 0.3 * p)
                } else {
                    s.tractions(x)
                };
                let inner = 1.0 - edge_width();
                let h = integral(&s, x, &[-c, 0.0, c, x], &|r, _, qt| {
                    let v = if r == 0.0 {
                        0.0
                    } else if (x - r).abs() < inner {
                        (qt - q) / (PI * r)
                    } else {
                        qt / (PI * r)
                    };
                    [v, 0.0, 0.0, 0.0]
                })[0]
                    + q / PI * ((inner + x) / (inner - x)).ln();
                let exact = -e.delta * e.delta * p - shear * h;
                let sxx = stress(&s, x, 0.0)[0];
                let gap = (sxx - exact).abs() / p0;
                worst = worst.max(gap);
                assert!(
                    gap < 1e-8,
                    "{name} {method:?} x {x}: {sxx} vs {exact}: {gap:e}"
                );
            }
            println!("{name} {method:?}: worst |sxx(x, 0) - quadrature| / p(0) = {worst:.1e}");
        }
    }
}

/// COUPLED's closed-form limit regimes have fields too: a stick zone far below the tolerance
/// (the ply at mu = 0.02: c ~ 3e-23, full slip with the central singularity |x|^(2g-1)) and
/// slip zones far below it (b* = 0.05 at mu = 10: 1 - c ~ 1e-40, the bonded punch). The
/// resultant on a line is the punch load and the surface values are the tractions.
#[test]
fn limit_regimes_have_fields() {
    let ply = Material::plane_stress(181e9, 10.3e9, 7.17e9, 0.28).unwrap();
    let low = Material::effective(1.0, 0.9, 1.0, 1.0).unwrap();
    for (name, m, mu, c_below, w_below) in [
        ("full slip", ply, 0.02, 1e-20, 1.0),
        ("bonded", low, 10.0, 1.0, 1e-30),
    ] {
        let s = solve(m, mu, Method::Coupled);
        assert!(
            s.c() <= c_below && s.one_minus_c() <= w_below,
            "{name}: c = {}",
            s.c()
        );
        let (mut fx, mut fy) = (0.0, 0.0);
        for i in 0..400 {
            let a = -2.0 + i as f64 / 100.0;
            for (x, w) in gauss(a, a + 0.01) {
                let st = stress(&s, x, -0.5);
                fx += st[2] * w;
                fy += st[1] * w;
            }
        }
        for i in 0..20 {
            let a = i as f64 / 20.0;
            for (t, w) in gauss(a, a + 0.05) {
                let (x, dx) = (2.0 / t, 2.0 / (t * t));
                for x in [x, -x] {
                    let st = stress(&s, x, -0.5);
                    fx += st[2] * w * dx;
                    fy += st[1] * w * dx;
                }
            }
        }
        assert!(
            (fy + 1.0).abs() < 1e-9 && fx.abs() < 1e-9,
            "{name}: resultant ({fx:e}, {fy})"
        );
        for x in [0.3, 0.7, -0.9, 0.99] {
            let (p, q) = s.tractions(x);
            let st = stress(&s, x, 0.0);
            assert!(
                (st[1] + p).abs() < 1e-9 * p && (st[2] - q).abs() < 1e-9 * p,
                "{name} x {x}: {st:?} vs p {p}, q {q}"
            );
        }
    }
}
