//! The main job: solve the built-in default scene (a unidirectional carbon/epoxy ply,
//! plane stress, mu = 0.3) with every method and print c, 1 - c, the error estimates, the
//! time per solve and a table of the tractions.

use std::time::Instant;

use orthoslip::{Contact, Material, Method};

fn main() {
    let (e11, e22, g12, nu12, mu) = (181e9, 10.3e9, 7.17e9, 0.28, 0.3);
    let ply = Material::plane_stress(e11, e22, g12, nu12).expect("default ply is admissible");
    let k = ply.constants();
    let g = ply.green();
    let coupling = ply.coupling(mu);
    println!("orthoslip {}: default scene", env!("CARGO_PKG_VERSION"));
    println!(
        "carbon/epoxy ply, plane stress: E11 = {e11:e} Pa, E22 = {e22:e} Pa, G12 = {g12:e} Pa, nu12 = {nu12}, mu = {mu}"
    );
    println!(
        "effective: E = {:.6e} Pa, nu = {:.6}, delta = {:.6}, kappa = {:.6}",
        k.e, k.nu, k.delta, k.kappa
    );
    println!(
        "Green: A = {:.6e}, B = {:.6e}, C = {:.6e} 1/Pa; bp = {:.6}, bq = {:.6}, b* = {:.6}",
        g.a,
        g.b,
        g.c,
        coupling.bp,
        coupling.bq,
        coupling.b_star()
    );
    let mut contact = Contact::new(ply);
    contact.set_friction(mu).expect("mu is valid");
    let mut best = None;
    println!(
        "\n{:<8} {:>20} {:>12} {:>10} {:>12}",
        "method", "c", "1 - c", "c error", "time/solve"
    );
    for method in [
        Method::Goodman,
        Method::Spence,
        Method::Lcp,
        Method::Coupled,
    ] {
        contact.set_method(method);
        let t = Instant::now();
        match contact.solve() {
            Ok(s) => {
                let dt = t.elapsed();
                println!(
                    "{:<8} {:>20.16} {:>12.6e} {:>10.2e} {:>12.3?}",
                    format!("{method:?}"),
                    s.c(),
                    s.one_minus_c(),
                    s.error_estimate(),
                    dt
                );
                best = Some(s);
            }
            Err(e) => println!("{:<8} {e}", format!("{method:?}")),
        }
    }
    let Some(s) = best else { return };
    println!(
        "\ntractions per P/a ({:?}): sigma_yy = -(P/a) p, sigma_xy = (P/a) q",
        s.method()
    );
    println!("{:>6} {:>14} {:>14} {:>8}", "x", "p", "q", "zone");
    for i in 0..=20 {
        let x = -1.0 + 0.1 * i as f64;
        let (p, q) = s.tractions(x);
        let zone = if x.abs() < s.c() { "stick" } else { "slip" };
        println!("{x:>6.2} {p:>14.8} {q:>14.8} {zone:>8}");
    }
}
