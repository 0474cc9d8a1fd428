//! Times METHOD_COUPLED on one core: solve (tol = 1e-10 and 1e-6) and traction evaluation,
//! isotropic plane-strain steel and the carbon/epoxy ply of the default scene, in CPU time
//! of the thread (the machine may be shared): the median over the repetitions.
//! Optional argument: the number of repetitions per case (default 20). "cold": each
//! repetition with its own edge exponent g (mu shifted by 1e-9).
mod support;

use orthoslip::Material;
use orthoslip::coupled::solve;
use orthoslip::problem::{Coupling, Profile};
use support::clock::cpu_seconds;

/// struct timespec of Linux (64-bit).
/// Median CPU time of f over `reps` calls (f gets the call's index).
fn median_cpu(reps: usize, mut f: impl FnMut(usize)) -> f64 {
    let mut times: Vec<f64> = (0..reps)
        .map(|i| {
            let t = cpu_seconds();
            f(i);
            cpu_seconds() - t
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

fn main() {
    let reps: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(20);
    let steel = 2.0 / 7.0;
    let ply = Material::plane_stress(181e9, 10.3e9, 7.17e9, 0.28).expect("admissible ply");
    let Coupling {
        bp: cbp, bq: cbq, ..
    } = ply.coupling(0.0);
    println!("carbon/epoxy: bp = {cbp:.15}, bq = {cbq:.15}; {reps} solves per case");
    for tol in [1e-10, 1e-6] {
        for (name, bp, bq) in [("steel", steel, steel), ("carbon", cbp, cbq)] {
            for mu in [0.1, 0.3, 1.0] {
                let k = Coupling { bp, bq, mu };
                let mut s = solve(&k, tol).expect("solve");
                let per_solve = median_cpu(reps, |_| s = solve(&k, tol).expect("solve"));
                // cold: a new edge exponent g each time (mu shifted by 1e-9 relative)
                let cold = median_cpu(reps, |i| {
                    let mu = mu * (1.0 + 1e-9 * (i + 1) as f64);
                    solve(&Coupling { bp, bq, mu }, tol).expect("solve");
                });
                let npts = 200_000;
                let t = cpu_seconds();
                let mut acc = 0.0;
                for i in 0..npts {
                    let x = -0.999 + 1.998 * (i as f64 + 0.5) / npts as f64;
                    let (p, q) = s.tractions(x);
                    acc += p + q;
                }
                let per_point = (cpu_seconds() - t) / npts as f64;
                println!(
                    "tol {tol:.0e} {name:6} mu {mu:3}: c = {:.15e}, 1 - c = {:.12e}, est {:.1e}, order {:2}, {:3} unknowns, {:8.3} ms/solve ({:8.3} cold), {:3.0} ns/point (checksum {acc:.3})",
                    s.edge().c,
                    s.edge().one_minus_c,
                    s.numerical_error(),
                    s.order(),
                    s.unknowns(),
                    per_solve * 1e3,
                    cold * 1e3,
                    per_point * 1e9
                );
            }
        }
    }
}
