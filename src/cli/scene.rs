//! The main job (`orthoslip` without arguments): solve the built-in default scene (a
//! unidirectional carbon/epoxy ply, plane stress, mu = 0.3) with every method and print c,
//! 1 - c, the error estimates, the time per solve and a table of the tractions.

use std::io::{self, Write};
use std::time::Instant;

use orthoslip::{Contact, Material, Method};

pub fn run(out: &mut impl Write) -> io::Result<()> {
    let (e11, e22, g12, nu12, mu) = (181e9, 10.3e9, 7.17e9, 0.28, 0.3);
    let ply = Material::plane_stress(e11, e22, g12, nu12).expect("default ply is admissible");
    let k = ply.constants();
    let g = ply.green();
    let coupling = ply.coupling(mu);
    writeln!(
        out,
        "orthoslip {}: default scene",
        env!("CARGO_PKG_VERSION")
    )?;
    writeln!(
        out,
        "carbon/epoxy ply, plane stress: E11 = {e11:e} Pa, E22 = {e22:e} Pa, G12 = {g12:e} Pa, nu12 = {nu12}, mu = {mu}"
    )?;
    writeln!(
        out,
        "effective: E = {:.6e} Pa, nu = {:.6}, delta = {:.6}, kappa = {:.6}",
        k.e, k.nu, k.delta, k.kappa
    )?;
    writeln!(
        out,
        "Green: A = {:.6e}, B = {:.6e}, C = {:.6e} 1/Pa; bp = {:.6}, bq = {:.6}, b* = {:.6}",
        g.a,
        g.b,
        g.c,
        coupling.bp,
        coupling.bq,
        coupling.b_star()
    )?;
    let mut best = None;
    writeln!(
        out,
        "\n{:<8} {:>9} {:>8} {:>19} {:>12} {:>10} {:>11}",
        "method", "tolerance", "used", "c", "1 - c", "c error", "time/solve"
    )?;
    let runs = [
        (Method::Goodman, None),
        (Method::Spence, None),
        (Method::Lcp, Some(1e-3)),
        (Method::Coupled, Some(1e-10)),
        (Method::Auto, Some(1e-1)),
        (Method::Auto, Some(1e-8)),
    ];
    for (method, tol) in runs {
        // A fresh contact per run: the closed forms run at the library's default tolerance,
        // which they ignore.
        let mut contact = Contact::new(ply);
        contact.set_friction(mu).expect("mu is valid");
        contact.set_method(method);
        if let Some(tol) = tol {
            contact.set_tolerance(tol).expect("tolerance is valid");
        }
        let t = Instant::now();
        let name = format!("{method:?}");
        let tol = tol.map_or("-".into(), |t| format!("{t:.0e}"));
        match contact.solve() {
            Ok(s) => {
                let dt = t.elapsed();
                writeln!(
                    out,
                    "{name:<8} {tol:>9} {:>8} {:>19.16} {:>12.6e} {:>10.2e} {:>11.3?}",
                    format!("{:?}", s.method()),
                    s.c(),
                    s.one_minus_c(),
                    s.error_estimate(),
                    dt
                )?;
                if s.method() == Method::Coupled {
                    best = Some(s);
                }
            }
            Err(e) => writeln!(out, "{name:<8} {tol:>9} {e}")?,
        }
    }
    let Some(s) = best else { return Ok(()) };
    writeln!(
        out,
        "\ntractions per P/a ({:?}): sigma_yy = -(P/a) p, sigma_xy = (P/a) q",
        s.method()
    )?;
    writeln!(out, "{:>6} {:>14} {:>14} {:>8}", "x", "p", "q", "zone")?;
    for i in 0..=20 {
        let x = -1.0 + 0.1 * i as f64;
        let (p, q) = s.tractions(x);
        let zone = if x.abs() < s.c() { "stick" } else { "slip" };
        writeln!(out, "{x:>6.2} {p:>14.8} {q:>14.8} {zone:>8}")?;
    }
    writeln!(
        out,
        "\nMore: orthoslip solve --help, orthoslip sweep --help (this scene: orthoslip solve \
         --plane-stress 181e9 10.3e9 7.17e9 0.28 --mu 0.3)"
    )
}
