//! Times the stress field on one core after a COUPLED solve of the default scene (the
//! carbon/epoxy ply, mu = 0.3) and of isotropic steel: the first call (which builds the field
//! from the tractions), then the cost per interior point on grids of the region under the
//! punch (|x| <= 2, depth to 2), near the surface (depth 1e-6 .. 1e-2) and far away, and the
//! slip per point, in CPU time of the thread. Optional argument: the number of grid points per
//! case (default 200 000).
use std::hint::black_box;

use orthoslip::{Contact, Material, Method};

/// CPU time of this thread in seconds, from /proc/thread-self/schedstat (Linux; the
/// machine may be shared, and wall time would count the others' work).
fn cpu_seconds() -> f64 {
    let stat = std::fs::read_to_string("/proc/thread-self/schedstat").expect("schedstat");
    let ns: f64 = stat
        .split_whitespace()
        .next()
        .and_then(|v| v.parse().ok())
        .expect("CPU time in ns");
    1e-9 * ns
}

fn main() {
    let npts: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(200_000);
    let scenes = [
        (
            "ply (kappa > 1)",
            Material::plane_stress(181e9, 10.3e9, 7.17e9, 0.28).expect("admissible"),
        ),
        (
            "steel (kappa = 1)",
            Material::plane_strain(210e9, 210e9, 210e9, 210e9 / 2.6, 0.3, 0.3, 0.3)
                .expect("admissible"),
        ),
        (
            "stiff shear (kappa < 1)",
            Material::plane_stress(100e9, 50e9, 80e9, 0.3).expect("admissible"),
        ),
    ];
    for (name, m) in scenes {
        let mut contact = Contact::new(m);
        contact.set_friction(0.3).expect("mu");
        contact.set_method(Method::Coupled);
        let s = contact.solve().expect("solve");
        // one call: wall time (the CPU-time counter ticks too coarsely)
        let t = std::time::Instant::now();
        black_box(s.stresses(0.0, -0.5).expect("point"));
        let first = t.elapsed().as_secs_f64();
        let side = (npts as f64).sqrt().ceil() as usize;
        let grid = |x0: f64, x1: f64, y: &dyn Fn(f64) -> f64| {
            let t = cpu_seconds();
            let mut acc = 0.0;
            for i in 0..side {
                for j in 0..side {
                    let x = x0 + (x1 - x0) * (i as f64 + 0.5) / side as f64;
                    let st = s.stresses(x, y((j as f64 + 0.5) / side as f64));
                    acc += st.expect("point")[0];
                }
            }
            black_box(acc);
            (cpu_seconds() - t) * 1e6 / (side * side) as f64
        };
        let under = grid(-2.0, 2.0, &|u| -2.0 * u);
        let surface = grid(-1.0, 1.0, &|u| -(10f64).powf(-6.0 + 4.0 * u));
        let far = grid(-10.0, 10.0, &|u| -2.0 - 8.0 * u);
        let t = cpu_seconds();
        let mut acc = 0.0;
        for i in 0..npts {
            acc += s
                .slip(-1.0 + 2.0 * (i as f64 + 0.5) / npts as f64)
                .expect("x");
        }
        black_box(acc);
        let slip = (cpu_seconds() - t) * 1e6 / npts as f64;
        println!(
            "{name:24} c = {:.6}: first call (builds the field) {:.3} ms; us/point: under the punch (|x| <= 2, depth <= 2) {under:.3}, near the surface (depth 1e-6..1e-2) {surface:.3}, far {far:.3}; slip {slip:.3}",
            s.c(),
            first * 1e3
        );
    }
}
