//! The isotropic flat punch against classical closed forms: the frictionless punch
//! (mu = 0: p = 1/(pi sqrt(1 - x^2)), q = 0) for every method, and the bonded punch
//! (Abramov 1937, Mossakovskii; Johnson, Contact Mechanics, section 2.8) as the large-friction
//! limit of the exact coupled solution:
//!   p + i q = cosh(pi eps) / (pi sqrt(1 - x^2)) exp(i eps ln((1 + x) / (1 - x))),
//!   eps = ln(3 - 4 nu) / (2 pi) (plane strain).

use std::f64::consts::PI;

use orthoslip::{Contact, Material, Method};

fn steel() -> Material {
    let (e, nu) = (210e9, 0.3);
    Material::plane_strain(e, e, e, e / (2.0 * (1.0 + nu)), nu, nu, nu).unwrap()
}

#[test]
fn frictionless_punch_for_every_method() {
    let mut contact = Contact::new(steel());
    contact.set_friction(0.0).unwrap();
    contact.set_tolerance(1e-3).unwrap();
    // c only: LCP's first-order pressure is checked to 5 % below, not to the tolerance
    contact.set_traction_tolerance(f64::INFINITY).unwrap();
    for method in Method::ALL {
        contact.set_method(method);
        let s = contact.solve().unwrap();
        assert_eq!(s.c(), 0.0, "{method:?}");
        for x in [-0.9, -0.3, 0.0, 0.4, 0.95] {
            let (p, q) = s.tractions(x);
            let p0 = 1.0 / (PI * (1.0 - x * x).sqrt());
            let tol = if s.method() == Method::Lcp {
                0.05
            } else {
                1e-14
            };
            assert!(
                (p - p0).abs() <= tol * p0,
                "{method:?} at x = {x}: p = {p}, p0 = {p0}"
            );
            assert_eq!(q, 0.0, "{method:?}");
        }
    }
}

#[test]
fn large_friction_approaches_the_bonded_punch() {
    let nu: f64 = 0.3;
    let eps = (3.0 - 4.0 * nu).ln() / (2.0 * PI);
    let bonded = |x: f64| {
        let r = (PI * eps).cosh() / (PI * (1.0 - x * x).sqrt());
        let phase = eps * ((1.0 + x) / (1.0 - x)).ln();
        (r * phase.cos(), r * phase.sin())
    };
    let mut contact = Contact::new(steel());
    contact.set_method(Method::Coupled);
    contact.set_tolerance(1e-10).unwrap();
    let mut previous = f64::INFINITY;
    for mu in [2.0, 5.0, 20.0] {
        contact.set_friction(mu).unwrap();
        let s = contact.solve().unwrap();
        let mut worst: f64 = 0.0;
        for i in 0..=18 {
            let x = -0.9 + 0.1 * i as f64;
            let (p, q) = s.tractions(x);
            let (pb, qb) = bonded(x);
            worst = worst.max((p - pb).abs().max((q - qb).abs()) / pb);
        }
        println!(
            "mu = {mu}: 1 - c = {:.3e}, max |(p, q) - bonded| / p on |x| <= 0.9: {worst:.2e}",
            s.one_minus_c()
        );
        assert!(
            worst < previous,
            "no approach to the bonded punch as mu grows"
        );
        previous = worst;
    }
    assert!(
        previous < 2e-5,
        "mu = 20 still {previous:e} away from the bonded punch"
    );
}
