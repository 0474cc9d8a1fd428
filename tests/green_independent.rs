//! Independent checks of `src/material.rs` (docs/theory.md §1-§2, paper eqs. (1)-(5)):
//!
//! 1. the Green's function constants A, B, C against a numerical Lekhnistskii solution of the
//!    half-plane (characteristic roots from a companion-matrix eigen-solve, never the closed
//!    forms), and near the double root kappa = 1 against a Chebyshev interpolant of that
//!    solution across the degeneracy; the isotropic limits against Johnson eq. (2.25);
//! 2. the plane-strain reduction of paper eq. (3) against inverting the 3x3 normal-stress
//!    compliance, taking the in-plane stiffness block (eps_33 = 0) and inverting it back;
//! 3. admissibility against positive definiteness of the compliance (scaled eigenvalues);
//! 4. b*, bp and bq (docs/theory.md (R1)).
//!
//! Each test prints its measured maximum differences (`--nocapture`).

use std::f64::consts::PI;

use nalgebra::{Complex, DMatrix, Matrix2, Matrix3, Matrix4, SMatrix, Schur, Vector2};
use orthoslip::{Error, Material};

type C64 = Complex<f64>;

/// In-plane compliances of paper eq. (1) from the effective constants, engineering shear:
/// (s11, s22, s12, s66_eng = 2 (kappa + nu) / E = 1 / G12).
fn eq1_compliances(e: f64, nu: f64, delta: f64, kappa: f64) -> [f64; 4] {
    [
        1.0 / (delta * delta * e),
        delta * delta / e,
        -nu / e,
        2.0 * (kappa + nu) / e,
    ]
}

/// Green's constants from the numerical half-plane solution, as complex numbers (their
/// imaginary parts must vanish), with A obtained twice (from u0' under f_y and from w0'
/// under f_x: reciprocity).
struct NumericalGreen {
    a_from_u: C64,
    a_from_w: C64,
    b: C64,
    c: C64,
}

/// The two characteristic roots mu with Im mu < 0 of s11 mu^4 + (2 s12 + s66) mu^2 + s22 = 0
/// (Lekhnistskii, orthotropic axes), from the eigenvalues of the companion matrix of the
/// polynomial scaled to unit root product (mu = rho m, rho = (s22 / s11)^(1/4): a generic
/// balancing, nalgebra's Schur does none). The companion matrix is shifted by SHIFT I before
/// the Schur decomposition: nalgebra's Francis iteration has no exceptional shifts and never
/// converges on the unshifted matrix when the four roots share one modulus (all kappa < 1).
fn lower_roots(s11: f64, s22: f64, s12: f64, s66: f64) -> [C64; 2] {
    const SHIFT: f64 = 0.3;
    let rho = (s22 / s11).sqrt().sqrt();
    // m^4 + t m^2 + 1 = 0.
    let t = (2.0 * s12 + s66) * rho * rho / s22;
    #[rustfmt::skip]
    let companion = Matrix4::new(
        0.0, 0.0, 0.0, -1.0,
        1.0, 0.0, 0.0, 0.0,
        0.0, 1.0, 0.0, -t,
        0.0, 0.0, 1.0, 0.0,
    );
    let eig = Schur::try_new(companion + Matrix4::identity() * SHIFT, f64::EPSILON, 1000)
        .unwrap_or_else(|| panic!("Schur decomposition failed for t = {t}"))
        .complex_eigenvalues();
    let lower: Vec<C64> = eig
        .iter()
        .map(|m| m - SHIFT)
        .filter(|m| m.im < 0.0)
        .map(|m| m * rho)
        .collect();
    assert_eq!(lower.len(), 2, "roots {eig:?} (t = {t})");
    [lower[0], lower[1]]
}

/// Lekhnistskii's solution for the half-plane y < 0 under one Fourier mode of surface
/// traction, sigma_yy(x, 0) = -F_y e^{ikx}, sigma_xy(x, 0) = F_x e^{ikx} with k > 0
/// (F_y: pressure into the solid, F_x: shear on the solid in +x; a concentrated force is their
/// superposition). Potentials phi_j'(z_j) = c_j e^{i k z_j}, z_j = x + mu_j y, decay as
/// y -> -inf iff Im mu_j < 0. Stresses sigma_yy = sum c_j e, sigma_xy = -sum mu_j c_j e;
/// displacement gradients along the surface u' = sum p_j c_j e, v' = sum q_j c_j e with
/// p_j = s11 mu_j^2 + s12, q_j = s12 mu_j + s22 / mu_j (from eps_xx = u_x, eps_yy = v_y; the
/// shear strain condition is the characteristic equation). With
/// PV int e^{iks} / (x - s) ds = -i pi e^{ikx}, eqs. (4)-(5) (w0 = -v0, into the solid) read
/// -u' = A F_y - i pi B F_x and -w' = -i pi C F_y - A F_x.
fn numerical_green(s: [f64; 4]) -> NumericalGreen {
    let [s11, s22, s12, s66] = s;
    let mu = lower_roots(s11, s22, s12, s66);
    let one = C64::new(1.0, 0.0);
    let lhs = Matrix2::new(one, one, mu[0], mu[1]).lu();
    let p = mu.map(|m| m * m * s11 + s12);
    let q = mu.map(|m| m * s12 + s22 / m);
    // Surface gradients (u', w') for tractions (F_x, F_y).
    let gradients = |fx: f64, fy: f64| {
        let c = lhs
            .solve(&Vector2::new(C64::from(-fy), C64::from(-fx)))
            .expect("distinct roots");
        let du = p[0] * c[0] + p[1] * c[1];
        let dw = -(q[0] * c[0] + q[1] * c[1]);
        (du, dw)
    };
    let i_pi = C64::new(0.0, PI);
    let (du_y, dw_y) = gradients(0.0, 1.0);
    let (du_x, dw_x) = gradients(1.0, 0.0);
    NumericalGreen {
        a_from_u: -du_y,
        c: dw_y / i_pi,
        b: du_x / i_pi,
        a_from_w: dw_x,
    }
}

/// Largest relative difference of the numerical constants from (a, b, c), imaginary parts
/// included.
fn green_difference(num: &NumericalGreen, a: f64, b: f64, c: f64) -> f64 {
    [(num.a_from_u, a), (num.a_from_w, a), (num.b, b), (num.c, c)]
        .iter()
        .map(|&(z, x)| (z - x).norm() / x.abs())
        .fold(0.0, f64::max)
}

fn log_uniform(rng: &mut fastrand::Rng, lo: f64, hi: f64) -> f64 {
    (lo.ln() + (hi.ln() - lo.ln()) * rng.f64()).exp()
}

fn uniform(rng: &mut fastrand::Rng, lo: f64, hi: f64) -> f64 {
    lo + (hi - lo) * rng.f64()
}

/// Random (E, nu, delta) over the ranges of the brief: E in [1e6, 1e12], nu in [-0.9, 0.9],
/// delta in [1e-3, 1e3].
fn random_e_nu_delta(rng: &mut fastrand::Rng) -> (f64, f64, f64) {
    (
        log_uniform(rng, 1e6, 1e12),
        uniform(rng, -0.9, 0.9),
        log_uniform(rng, 1e-3, 1e3),
    )
}

/// Check 1 away from the double root: kappa > 1 (gap 1e-3 .. 1e3), -nu < kappa < 1 (distance
/// >= 1e-3 from 1), sorted into bins of |kappa - 1|.
#[test]
fn green_constants_match_numerical_lekhnistskii() {
    let mut rng = fastrand::Rng::with_seed(0x6e11);
    let edges = [1e-3, 1e-2, 1e-1, 1.0, f64::INFINITY];
    let mut worst = [0.0f64; 4];
    let mut count = [0usize; 4];
    for i in 0..6000 {
        let (e, nu, delta) = random_e_nu_delta(&mut rng);
        let kappa = if i % 2 == 0 {
            1.0 + log_uniform(&mut rng, 1e-3, 1e3)
        } else {
            // Uniform in (-nu, 1 - 1e-3), with every tenth sample close to -nu.
            let span = 1.0 - 1e-3 + nu;
            let u = if i % 20 == 1 {
                log_uniform(&mut rng, 1e-9, 1e-2)
            } else {
                rng.f64().max(1e-12)
            };
            -nu + span * u
        };
        let m = Material::effective(e, nu, delta, kappa).expect("admissible by construction");
        let g = m.green();
        let d = green_difference(
            &numerical_green(eq1_compliances(e, nu, delta, kappa)),
            g.a,
            g.b,
            g.c,
        );
        let bin = edges.iter().position(|&t| (kappa - 1.0).abs() < t).unwrap() - 1;
        worst[bin] = worst[bin].max(d);
        count[bin] += 1;
    }
    for (bin, (w, n)) in worst.iter().zip(count).enumerate() {
        println!(
            "check 1: |kappa - 1| in [{:.0e}, {:.0e}): {n} samples, max relative difference {w:.2e}",
            edges[bin],
            edges[bin + 1]
        );
    }
    assert!(count.iter().all(|&n| n > 100));
    assert!(worst.iter().all(|&w| w < 5e-12), "worst {worst:?}");
}

/// Check 1 at and next to the double root kappa = 1 (exactly, and 1e-12 .. 1e-6 on either
/// side): the closed forms against the numerical solution continued across the degeneracy by
/// Chebyshev interpolation in kappa (16 first-kind nodes on [1 - h, 1 + h], none closer than
/// 0.098 h to 1; A, B, C are analytic in kappa for kappa > -1, so the interpolation error is
/// negligible and the result inherits the numerical route's accuracy at |kappa - 1| >= 0.098 h).
#[test]
fn green_constants_are_accurate_at_the_double_root() {
    const N: usize = 16;
    const H: f64 = 0.05;
    let theta = |j: usize| (2 * j + 1) as f64 * PI / (2 * N) as f64;
    let nodes: Vec<f64> = (0..N).map(|j| theta(j).cos()).collect();
    let weights: Vec<f64> = (0..N)
        .map(|j| if j % 2 == 0 { 1.0 } else { -1.0 } * theta(j).sin())
        .collect();
    let mut rng = fastrand::Rng::with_seed(0x6e12);
    let (mut worst_interp, mut worst_direct) = (0.0f64, 0.0f64);
    for i in 0..300 {
        let (e, nu, delta) = random_e_nu_delta(&mut rng);
        let kappa = match i % 3 {
            0 => 1.0,
            1 => 1.0 + log_uniform(&mut rng, 1e-12, 1e-6),
            _ => 1.0 - log_uniform(&mut rng, 1e-12, 1e-6),
        };
        let values: Vec<[f64; 3]> = nodes
            .iter()
            .map(|x| {
                let n = numerical_green(eq1_compliances(e, nu, delta, 1.0 + H * x));
                [n.a_from_u.re, n.b.re, n.c.re]
            })
            .collect();
        // Barycentric formula at t = (kappa - 1) / h (not a node).
        let t = (kappa - 1.0) / H;
        let mut interp = [0.0; 3];
        let mut denom = 0.0;
        for j in 0..N {
            let w = weights[j] / (t - nodes[j]);
            denom += w;
            for (acc, v) in interp.iter_mut().zip(values[j]) {
                *acc += w * v;
            }
        }
        let g = Material::effective(e, nu, delta, kappa).unwrap().green();
        for (v, x) in interp.iter().zip([g.a, g.b, g.c]) {
            worst_interp = worst_interp.max((v / denom - x).abs() / x);
        }
        let direct = numerical_green(eq1_compliances(e, nu, delta, kappa));
        worst_direct = worst_direct.max(green_difference(&direct, g.a, g.b, g.c));
    }
    println!(
        "check 1: |kappa - 1| <= 1e-6 (300 samples, 100 at kappa = 1): closed forms vs interpolated \
         numerical solution {worst_interp:.2e}; the direct numerical solution there is off by \
         up to {worst_direct:.2e}"
    );
    assert!(worst_interp < 1e-11, "{worst_interp:e}");
}

/// Check 1, isotropic limits: plane strain A = (1 - 2 nu)(1 + nu) / E, B = C = 2 (1 - nu^2) /
/// (pi E) (Johnson eq. 2.25) and plane stress A = (1 - nu) / E, B = C = 2 / (pi E).
#[test]
fn isotropic_green_constants_match_johnson() {
    let mut rng = fastrand::Rng::with_seed(0x6e13);
    let (mut strain, mut stress) = (0.0f64, 0.0f64);
    let rel = |x: f64, y: f64| (x - y).abs() / y.abs();
    for _ in 0..2000 {
        let e = log_uniform(&mut rng, 1e6, 1e12);
        let nu = uniform(&mut rng, -0.9, 0.499);
        let g = e / (2.0 * (1.0 + nu));
        let m = Material::plane_strain(e, e, e, g, nu, nu, nu)
            .unwrap()
            .green();
        let b = 2.0 * (1.0 - nu * nu) / (PI * e);
        strain = strain
            .max(rel(m.a, (1.0 - 2.0 * nu) * (1.0 + nu) / e))
            .max(rel(m.b, b))
            .max(rel(m.c, b));
        let m = Material::plane_stress(e, e, g, nu).unwrap().green();
        let b = 2.0 / (PI * e);
        stress = stress
            .max(rel(m.a, (1.0 - nu) / e))
            .max(rel(m.b, b))
            .max(rel(m.c, b));
    }
    println!(
        "check 1: isotropic (2000 samples, nu in [-0.9, 0.499]): plane strain max relative \
         difference {strain:.2e}, plane stress {stress:.2e}"
    );
    // A = (1 - 2 nu)(1 + nu) / E loses relative accuracy as nu -> 1/2 in either route.
    assert!(strain < 1e-12 && stress < 1e-14, "{strain:e} {stress:e}");
}

/// The 3x3 normal-stress compliance of an orthotropic solid (nu_ij = -eps_j / eps_i under
/// stress along i, so s_ij = -nu_ij / E_i).
fn normal_compliance(e: [f64; 3], nu12: f64, nu13: f64, nu23: f64) -> Matrix3<f64> {
    let (s12, s13, s23) = (-nu12 / e[0], -nu13 / e[0], -nu23 / e[1]);
    Matrix3::new(
        1.0 / e[0],
        s12,
        s13,
        s12,
        1.0 / e[1],
        s23,
        s13,
        s23,
        1.0 / e[2],
    )
}

/// A random admissible 3-D orthotropic material (E1, E2, E3, G12, nu12, nu13, nu23).
fn random_orthotropic(rng: &mut fastrand::Rng) -> ([f64; 3], f64, [f64; 3]) {
    loop {
        let e = [0; 3].map(|_| log_uniform(rng, 1e8, 1e12));
        let g12 = log_uniform(rng, 1e7, 1e11);
        let mut r = || uniform(rng, -0.95, 0.95);
        let nu = [
            r() * (e[0] / e[1]).sqrt(),
            r() * (e[0] / e[2]).sqrt(),
            r() * (e[1] / e[2]).sqrt(),
        ];
        if positive_definite_margin(&normal_compliance(e, nu[0], nu[1], nu[2])) > 1e-6 {
            return (e, g12, nu);
        }
    }
}

/// Check 2: plane strain (eps_33 = 0) by inverting the normal compliance, keeping the in-plane
/// stiffness block and inverting it back, against `compliances()`.
#[test]
fn plane_strain_reduction_matches_stiffness_inversion() {
    let mut rng = fastrand::Rng::with_seed(0x6e20);
    let mut worst = 0.0f64;
    let mut worst_incompressible = 0.0f64;
    for i in 0..3000 {
        let (e, g12, nu) = if i % 10 == 0 {
            let e = log_uniform(&mut rng, 1e6, 1e12);
            ([e; 3], e / (2.0 * 1.499), [0.499; 3])
        } else {
            random_orthotropic(&mut rng)
        };
        let stiffness = normal_compliance(e, nu[0], nu[1], nu[2])
            .lu()
            .try_inverse()
            .expect("positive definite");
        let reduced = stiffness
            .fixed_view::<2, 2>(0, 0)
            .into_owned()
            .try_inverse()
            .expect("positive definite block");
        let s = Material::plane_strain(e[0], e[1], e[2], g12, nu[0], nu[1], nu[2])
            .unwrap()
            .compliances();
        let scale = (reduced[(0, 0)] * reduced[(1, 1)]).sqrt();
        let d = [
            (s.s11 - reduced[(0, 0)]).abs() / reduced[(0, 0)],
            (s.s22 - reduced[(1, 1)]).abs() / reduced[(1, 1)],
            (s.s12 - reduced[(0, 1)]).abs() / scale,
            (s.s66 - 0.5 / g12).abs() * 2.0 * g12,
        ]
        .into_iter()
        .fold(0.0, f64::max);
        if i % 10 == 0 {
            worst_incompressible = worst_incompressible.max(d);
        } else {
            worst = worst.max(d);
        }
    }
    println!(
        "check 2: plane-strain compliances vs stiffness-block inversion: 2700 random orthotropic \
         {worst:.2e}, 300 isotropic nu = 0.499 {worst_incompressible:.2e} (s12 relative to \
         sqrt(s11 s22))"
    );
    assert!(worst < 1e-12 && worst_incompressible < 1e-12);
}

/// Smallest eigenvalue of the symmetric matrix scaled to unit diagonal, D^-1/2 S D^-1/2
/// (positive iff S is positive definite, and scale-free), or -1 if a diagonal entry is not
/// positive. Cross-checked against nalgebra's Cholesky factorisation away from zero.
fn positive_definite_margin<const N: usize>(s: &SMatrix<f64, N, N>) -> f64 {
    if (0..N).any(|i| s[(i, i)].is_nan() || s[(i, i)] <= 0.0) {
        return -1.0;
    }
    let d = DMatrix::<f64>::from_fn(N, N, |i, j| s[(i, j)] / (s[(i, i)] * s[(j, j)]).sqrt());
    let margin = d.clone().symmetric_eigenvalues().min();
    if margin.abs() > 1e-9 {
        assert_eq!(d.cholesky().is_some(), margin > 0.0, "{s}");
    }
    margin
}

/// What a constructor's result says about admissibility; non-finite input must be an
/// InvalidArgument.
fn accepted(result: orthoslip::Result<Material>, non_finite: bool) -> bool {
    match result {
        Ok(_) => {
            assert!(!non_finite);
            true
        }
        Err(Error::InvalidArgument(_)) => false,
        Err(Error::InadmissibleMaterial(m)) => {
            assert!(
                !non_finite,
                "non-finite input reported as inadmissible: {m}"
            );
            false
        }
        Err(other) => panic!("unexpected error {other:?}"),
    }
}

/// A modulus: mostly positive (log-uniform), sometimes negative, zero or non-finite.
fn random_modulus(rng: &mut fastrand::Rng) -> f64 {
    match rng.usize(0..40) {
        0 => -log_uniform(rng, 1e-3, 1e3),
        1 => 0.0,
        2 => f64::NAN,
        3 => f64::INFINITY,
        _ => log_uniform(rng, 1e-3, 1e3),
    }
}

/// 1 -+ a random offset in 1e-8 .. 1e-2 (log-uniform), either side with equal odds.
fn near_one(rng: &mut fastrand::Rng) -> f64 {
    let d = log_uniform(rng, 1e-8, 1e-2);
    if rng.bool() { 1.0 - d } else { 1.0 + d }
}

/// Tally of check 3: samples that agree, samples skipped within the margin.
struct Tally {
    agree: [usize; 2],
    skipped: usize,
    /// Smallest |margin| among the classified samples.
    closest: f64,
}

impl Tally {
    fn new() -> Self {
        Self {
            agree: [0; 2],
            skipped: 0,
            closest: f64::INFINITY,
        }
    }

    /// Compares a constructor's verdict with the positive-definiteness margin.
    fn record(&mut self, result: orthoslip::Result<Material>, inputs: &[f64], margin: f64) {
        let non_finite = inputs.iter().any(|x| !x.is_finite());
        let ok = accepted(result, non_finite);
        if non_finite {
            assert!(!ok);
            self.agree[0] += 1;
        } else if margin.abs() <= 1e-9 {
            self.skipped += 1;
        } else {
            assert_eq!(ok, margin > 0.0, "inputs {inputs:?}, margin {margin:e}");
            self.closest = self.closest.min(margin.abs());
            self.agree[usize::from(ok)] += 1;
        }
    }
}

/// Check 3: plane stress, plane strain and effective constants, random inputs on both sides of
/// the admissibility boundary.
#[test]
fn admissibility_matches_positive_definiteness() {
    let mut rng = fastrand::Rng::with_seed(0x6e30);
    let (mut stress, mut strain, mut effective) = (Tally::new(), Tally::new(), Tally::new());
    for i in 0..20000 {
        // Every other sample lies within a relative 1e-8 .. 1e-2 of the boundary.
        let near = i % 2 == 1;
        // Plane stress: compliance [[1/E11, -nu12/E11, 0], [., 1/E22, 0], [0, 0, 1/(2 G12)]].
        let (e11, e22, g12) = (
            random_modulus(&mut rng),
            random_modulus(&mut rng),
            random_modulus(&mut rng),
        );
        let r = if near {
            near_one(&mut rng).copysign(rng.f64() - 0.5)
        } else {
            uniform(&mut rng, -1.5, 1.5)
        };
        let nu12 = r * (e11 / e22).abs().sqrt();
        let s = Matrix3::new(
            1.0 / e11,
            -nu12 / e11,
            0.0,
            -nu12 / e11,
            1.0 / e22,
            0.0,
            0.0,
            0.0,
            0.5 / g12,
        );
        stress.record(
            Material::plane_stress(e11, e22, g12, nu12),
            &[e11, e22, g12, nu12],
            positive_definite_margin(&s),
        );

        // Plane strain: the 6x6 orthotropic compliance (G13, G23 positive, not inputs).
        let e = [0; 3].map(|_| random_modulus(&mut rng));
        let g12 = random_modulus(&mut rng);
        let mut r = |i: usize, j: usize| uniform(&mut rng, -1.3, 1.3) * (e[i] / e[j]).abs().sqrt();
        let mut nu = [r(0, 1), r(0, 2), r(1, 2)];
        let (g13, g23) = (
            log_uniform(&mut rng, 1e-3, 1e3),
            log_uniform(&mut rng, 1e-3, 1e3),
        );
        let compliance = |nu: [f64; 3]| {
            let mut s6 = SMatrix::<f64, 6, 6>::zeros();
            s6.fixed_view_mut::<3, 3>(0, 0)
                .copy_from(&normal_compliance(e, nu[0], nu[1], nu[2]));
            s6[(3, 3)] = 1.0 / g23;
            s6[(4, 4)] = 1.0 / g13;
            s6[(5, 5)] = 1.0 / g12;
            s6
        };
        if near && e.iter().all(|&x| x.is_finite() && x > 0.0) && g12.is_finite() && g12 > 0.0 {
            // Scale the Poisson's ratios onto the boundary by bisection, then off it.
            let margin = |l: f64| positive_definite_margin(&compliance(nu.map(|x| l * x)));
            let (mut lo, mut hi) = (0.0, 1.0);
            while margin(hi) > 0.0 {
                hi *= 2.0;
            }
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if margin(mid) > 0.0 {
                    lo = mid
                } else {
                    hi = mid
                }
            }
            let l = lo * near_one(&mut rng);
            nu = nu.map(|x| l * x);
        }
        let s6 = compliance(nu);
        strain.record(
            Material::plane_strain(e[0], e[1], e[2], g12, nu[0], nu[1], nu[2]),
            &[e[0], e[1], e[2], g12, nu[0], nu[1], nu[2]],
            positive_definite_margin(&s6),
        );

        // Effective constants: compliance of eq. (1), delta > 0.
        let (en, delta) = (random_modulus(&mut rng), log_uniform(&mut rng, 1e-3, 1e3));
        let (nu, kappa) = match (near, rng.bool()) {
            (false, _) => (uniform(&mut rng, -1.5, 1.5), uniform(&mut rng, -2.0, 3.0)),
            (true, true) => (
                near_one(&mut rng).copysign(rng.f64() - 0.5),
                uniform(&mut rng, -2.0, 3.0),
            ),
            (true, false) => {
                let nu = uniform(&mut rng, -0.99, 0.99);
                (
                    nu,
                    -nu + (1.0 - near_one(&mut rng)).copysign(rng.f64() - 0.5),
                )
            }
        };
        let [s11, s22, s12, s66] = eq1_compliances(en, nu, delta, kappa);
        let s = Matrix3::new(s11, s12, 0.0, s12, s22, 0.0, 0.0, 0.0, 0.5 * s66);
        effective.record(
            Material::effective(en, nu, delta, kappa),
            &[en, nu, delta, kappa],
            positive_definite_margin(&s),
        );
    }
    // delta <= 0 or non-finite is an invalid argument even though the compliance is fine.
    for delta in [0.0, -1.0, f64::NAN] {
        assert!(matches!(
            Material::effective(1.0, 0.3, delta, 1.0),
            Err(Error::InvalidArgument(_))
        ));
    }
    for (name, t) in [
        ("plane stress", &stress),
        ("plane strain", &strain),
        ("effective", &effective),
    ] {
        println!(
            "check 3: {name}: {} admissible and {} rejected agree with positive definiteness \
             (closest |scaled min eigenvalue| {:.1e}), {} within the 1e-9 margin skipped",
            t.agree[1], t.agree[0], t.closest, t.skipped
        );
        assert!(t.agree[0] > 2000 && t.agree[1] > 2000);
    }
}

/// Check 4: b* = (1 - nu) / sqrt(2 (1 + kappa)) in (0, 1); bp bq = b*^2, bq / bp = delta^2;
/// and bp = A / (pi C), bq = A / (pi B) from the numerical Green's constants.
#[test]
fn coupling_constants_follow_from_green() {
    let mut rng = fastrand::Rng::with_seed(0x6e40);
    let (mut formula, mut product, mut ratio, mut numerical) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    let (mut lowest, mut highest) = (f64::INFINITY, 0.0f64);
    for i in 0..5000 {
        let (e, mut nu, delta) = random_e_nu_delta(&mut rng);
        if i % 5 == 0 {
            // Extremes: nu within 1e-6 of -1 or 1.
            nu = (1.0 - log_uniform(&mut rng, 1e-12, 1e-6)).copysign(nu);
        }
        let kappa = -nu + log_uniform(&mut rng, 1e-9, 1e3);
        let m = Material::effective(e, nu, delta, kappa).unwrap();
        let b = m.b_star();
        let expected = (1.0 - nu) / (2.0 * (1.0 + kappa)).sqrt();
        assert!(
            b > 0.0 && b < 1.0,
            "b* = {b} for nu = {nu}, kappa = {kappa}"
        );
        lowest = lowest.min(b);
        highest = highest.max(b);
        formula = formula.max((b - expected).abs() / expected);
        let c = m.coupling(0.3);
        assert_eq!(c.mu, 0.3);
        product = product.max((c.bp * c.bq - b * b).abs() / (b * b));
        ratio = ratio.max((c.bq / c.bp - delta * delta).abs() / (delta * delta));
        // A = (1 - nu) / E cancels in the numerical route as nu -> 1: skip the extremes.
        if i % 5 != 0 && (kappa - 1.0).abs() > 1e-2 {
            let n = numerical_green(eq1_compliances(e, nu, delta, kappa));
            let bp = n.a_from_u.re / (PI * n.c.re);
            let bq = n.a_from_u.re / (PI * n.b.re);
            numerical = numerical
                .max((c.bp - bp).abs() / bp)
                .max((c.bq - bq).abs() / bq);
        }
    }
    println!(
        "check 4: b* in [{lowest:.3e}, {highest:.15}] ; max relative differences: b* vs formula \
         {formula:.2e}, bp bq vs b*^2 {product:.2e}, bq/bp vs delta^2 {ratio:.2e}, (bp, bq) vs \
         numerical A/(pi C), A/(pi B) {numerical:.2e}"
    );
    assert!(formula < 1e-15 && product < 1e-14 && ratio < 1e-14 && numerical < 1e-10);
}
