//! METHOD_AUTO: it meets its tolerance against an independent COUPLED reference while picking
//! the approximations where their model-error bounds suffice (`tests/model_error_table.rs`
//! checks the tables behind those bounds): for c alone (traction tolerance infinity), and for
//! c and the tractions (the default: the traction tolerance is the tolerance).

use orthoslip::model_error::{Approximation, bound, traction_bound};
use orthoslip::problem::traction_distance;
use orthoslip::{Contact, Error, Material, Method, Profile, coupled};

#[test]
fn auto_meets_the_tolerance_and_uses_the_approximations_where_they_suffice() {
    let scenes = [
        Material::plane_stress(181e9, 10.3e9, 7.17e9, 0.28).unwrap(),
        Material::plane_strain(210e9, 210e9, 210e9, 210e9 / 2.6, 0.3, 0.3, 0.3).unwrap(),
        Material::effective(1.0, 0.25, 1.3, 0.4).unwrap(),
        Material::effective(1.0, -0.5, 0.8, 1.5).unwrap(),
    ];
    let mut picks = std::collections::BTreeMap::<String, usize>::new();
    for m in scenes {
        for mu in [0.1, 0.3, 1.0, 3.0] {
            let k = m.coupling(mu);
            let Ok(reference) = coupled::solve(&k, 1e-12) else {
                continue;
            };
            let c_ref = reference.edge();
            for (tol, tractions) in [1e-1, 1e-2, 1e-4, 1e-6, 1e-8, 1e-10]
                .into_iter()
                .flat_map(|t| [(t, false), (t, true)])
            {
                let mut contact = Contact::new(m);
                contact.set_friction(mu).unwrap();
                contact.set_tolerance(tol).unwrap();
                if !tractions {
                    contact.set_traction_tolerance(f64::INFINITY).unwrap();
                }
                let s = match contact.solve() {
                    Ok(s) => s,
                    // COUPLED's traction estimate bottoms out near 1e-10 in some scenes
                    Err(Error::ToleranceNotMet { .. }) if tractions && tol <= 1e-10 => {
                        *picks
                            .entry("traction tolerance not met".into())
                            .or_default() += 1;
                        continue;
                    }
                    Err(e) => panic!("AUTO at mu = {mu}, tol = {tol:e}: {e}"),
                };
                if tractions {
                    let t_err = traction_distance(s.profile(), &reference);
                    let t_est = s.traction_error_estimate();
                    assert!(
                        t_est <= tol,
                        "traction estimate {t_est:e} above tolerance {tol:e}"
                    );
                    assert!(
                        t_err <= t_est + reference.traction_error(),
                        "AUTO ({:?}) at mu = {mu}, tol = {tol:e}: traction error {t_err:e} \
                         above the estimate {t_est:e}",
                        s.method()
                    );
                }
                let err = s.edge().distance(c_ref);
                assert!(
                    err <= tol + 1e-12,
                    "AUTO ({:?}) at mu = {mu}, tol = {tol:e}: error {err:e}",
                    s.method()
                );
                assert!(s.error_estimate() <= tol, "estimate above tolerance");
                // 1e-12: the rounding level of c from either solve.
                assert!(
                    s.error_estimate() + reference.numerical_error() + 1e-12 >= err,
                    "AUTO ({:?}) at mu = {mu}, tol = {tol:e}: estimate {:e} below the true error {err:e}",
                    s.method(),
                    s.error_estimate()
                );
                assert_ne!(s.method(), Method::Auto);
                // AUTO takes an approximation exactly when its empirical bounds allow it.
                let ok = |a| {
                    bound(a, &k).is_some_and(|b| b <= tol)
                        && (!tractions || traction_bound(a, &k).is_some_and(|b| b <= tol))
                };
                let (g_ok, s_ok) = (ok(Approximation::Goodman), ok(Approximation::Spence));
                let expected = if g_ok {
                    Method::Goodman
                } else if s_ok {
                    Method::Spence
                } else {
                    Method::Coupled
                };
                assert_eq!(s.method(), expected);
                *picks.entry(format!("{:?}", s.method())).or_default() += 1;
            }
        }
    }
    println!("AUTO's picks over the grid: {picks:?}");
    assert!(picks.get("Goodman").copied().unwrap_or(0) > 0, "{picks:?}");
    assert!(picks.get("Coupled").copied().unwrap_or(0) > 0, "{picks:?}");
}
