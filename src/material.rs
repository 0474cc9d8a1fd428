//! The orthotropic half-plane: effective constants (E, nu, delta, kappa) of paper eq. (1),
//! built from engineering constants by eqs. (2) (plane stress) and (3) (plane strain) with the
//! corrections of docs/theory.md (M3), (M4), and the surface Green's function constants A, B, C of
//! eqs. (4)-(5).

use std::f64::consts::PI;

use crate::error::{Error, Result};
use crate::problem::Coupling;

/// In-plane compliances with tensor shear strain (paper eq. (1)):
/// eps_xx = s11 sxx + s12 syy, eps_yy = s12 sxx + s22 syy, eps_xy = s66 sxy.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Compliances {
    /// s11 = delta^-2 / E.
    pub s11: f64,
    /// s22 = delta^2 / E.
    pub s22: f64,
    /// s12 = -nu / E.
    pub s12: f64,
    /// s66 = (kappa + nu) / E = 1 / (2 G12).
    pub s66: f64,
}

/// The effective constants of paper eq. (1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Effective {
    /// Effective stiffness E = 1 / sqrt(s11 s22) (Pa, or any consistent unit).
    pub e: f64,
    /// Effective Poisson's ratio nu = -E s12, in (-1, 1).
    pub nu: f64,
    /// Stiffness ratio delta = (s22 / s11)^(1/4) > 0 (delta^4 = E11 / E22 in plane stress).
    pub delta: f64,
    /// Shear parameter kappa = E (s12 + s66) > -nu (isotropic: 1).
    pub kappa: f64,
}

/// Surface Green's function constants of paper eqs. (4)-(5) (units 1 / stiffness):
/// -u0' = A f_y + B PV int f_x / (x - s) ds, -w0' = C PV int f_y / (x - s) ds - A f_x.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Green {
    /// A = (1 - nu) / E.
    pub a: f64,
    /// B = sqrt(2 (1 + kappa)) / (pi delta E).
    pub b: f64,
    /// C = delta sqrt(2 (1 + kappa)) / (pi E).
    pub c: f64,
}

/// An admissible orthotropic half-plane (principal axes along x and y).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    k: Effective,
}

/// Checks that every named value is finite and strictly positive.
fn positive(values: &[(&str, f64)]) -> Result<()> {
    for &(name, v) in values {
        if !v.is_finite() || v <= 0.0 {
            return Err(Error::InvalidArgument(format!(
                "{name} = {v} must be finite and > 0"
            )));
        }
    }
    Ok(())
}

/// Checks that every named value is finite.
fn finite(values: &[(&str, f64)]) -> Result<()> {
    for &(name, v) in values {
        if !v.is_finite() {
            return Err(Error::InvalidArgument(format!(
                "{name} = {v} must be finite"
            )));
        }
    }
    Ok(())
}

impl Material {
    /// Plane stress from E11, E22, G12 (> 0) and nu12 (paper eq. (2) with E = sqrt(E11 E22)
    /// and nu = sgn(nu12) sqrt(nu12 nu21)). Admissible iff nu12^2 < E11 / E22.
    pub fn plane_stress(e11: f64, e22: f64, g12: f64, nu12: f64) -> Result<Self> {
        positive(&[("E11", e11), ("E22", e22), ("G12", g12)])?;
        finite(&[("nu12", nu12)])?;
        if nu12 * nu12 >= e11 / e22 {
            return Err(Error::InadmissibleMaterial(format!(
                "plane stress needs nu12^2 < E11/E22 (nu12 = {nu12}, E11/E22 = {})",
                e11 / e22
            )));
        }
        Self::from_compliances(Compliances {
            s11: 1.0 / e11,
            s22: 1.0 / e22,
            s12: -nu12 / e11,
            s66: 0.5 / g12,
        })
    }

    /// Plane strain from the orthotropic constants E11, E22, E33, G12 (> 0) and nu12, nu13,
    /// nu23 (nu_ij = -eps_j / eps_i under stress along i), by the reduced compliances
    /// s'ij = sij - si3 sj3 / s33 (paper eq. (3)). The 3-D compliance must be positive definite
    /// on the normal stresses: |nu_ij| < sqrt(Ei / Ej) and
    /// 1 - nu12 nu21 - nu23 nu32 - nu13 nu31 - 2 nu21 nu32 nu13 > 0.
    pub fn plane_strain(
        e11: f64,
        e22: f64,
        e33: f64,
        g12: f64,
        nu12: f64,
        nu13: f64,
        nu23: f64,
    ) -> Result<Self> {
        positive(&[("E11", e11), ("E22", e22), ("E33", e33), ("G12", g12)])?;
        finite(&[("nu12", nu12), ("nu13", nu13), ("nu23", nu23)])?;
        for (name, nu, ei, ej) in [
            ("nu12", nu12, e11, e22),
            ("nu13", nu13, e11, e33),
            ("nu23", nu23, e22, e33),
        ] {
            if nu * nu >= ei / ej {
                return Err(Error::InadmissibleMaterial(format!(
                    "{name}^2 = {} must be < {} (Ei/Ej) for a positive definite compliance",
                    nu * nu,
                    ei / ej
                )));
            }
        }
        let (nu21, nu31, nu32) = (nu12 * e22 / e11, nu13 * e33 / e11, nu23 * e33 / e22);
        let det = 1.0 - nu12 * nu21 - nu23 * nu32 - nu13 * nu31 - 2.0 * nu21 * nu32 * nu13;
        if det <= 0.0 {
            return Err(Error::InadmissibleMaterial(format!(
                "1 - nu12 nu21 - nu23 nu32 - nu13 nu31 - 2 nu21 nu32 nu13 = {det} must be > 0"
            )));
        }
        let (s11, s22, s33) = (1.0 / e11, 1.0 / e22, 1.0 / e33);
        let (s12, s13, s23) = (-nu12 / e11, -nu13 / e11, -nu23 / e22);
        Self::from_compliances(Compliances {
            s11: s11 - s13 * s13 / s33,
            s22: s22 - s23 * s23 / s33,
            s12: s12 - s13 * s23 / s33,
            s66: 0.5 / g12,
        })
    }

    /// Directly from the effective constants of paper eq. (1). Admissible iff E > 0,
    /// delta > 0, -1 < nu < 1 and kappa > -nu (docs/theory.md (M5)).
    pub fn effective(e: f64, nu: f64, delta: f64, kappa: f64) -> Result<Self> {
        positive(&[("E", e), ("delta", delta)])?;
        finite(&[("nu", nu), ("kappa", kappa)])?;
        if !(-1.0 < nu && nu < 1.0) {
            return Err(Error::InadmissibleMaterial(format!(
                "the effective Poisson's ratio nu = {nu} must lie in (-1, 1)"
            )));
        }
        if kappa <= -nu {
            return Err(Error::InadmissibleMaterial(format!(
                "kappa = {kappa} must exceed -nu = {} (positive shear compliance)",
                -nu
            )));
        }
        let m = Self {
            k: Effective {
                e,
                nu,
                delta,
                kappa,
            },
        };
        // moduli next to the ends of the double range (subnormal E: A = (1 - nu) / E
        // overflows; E ~ 1e308: A underflows to 0): the compliances the material reports
        // and the field uses must be representable
        let g = m.green();
        if ![g.a, g.b, g.c].iter().all(|v| v.is_finite() && *v > 0.0) {
            return Err(Error::InvalidArgument(format!(
                "the compliances A = {}, B = {}, C = {} (1 / stress unit) of E = {e}, nu = \
                 {nu}, delta = {delta}, kappa = {kappa} leave the range of doubles; only the \
                 ratios of the moduli matter: give them in another unit",
                g.a, g.b, g.c
            )));
        }
        Ok(m)
    }

    /// From in-plane compliances: E = 1/sqrt(s11 s22), nu = -E s12, delta^4 = s22/s11,
    /// kappa = E (s12 + s66).
    fn from_compliances(s: Compliances) -> Result<Self> {
        let e = 1.0 / (s.s11 * s.s22).sqrt();
        Self::effective(
            e,
            -e * s.s12,
            (s.s22 / s.s11).sqrt().sqrt(),
            e * (s.s12 + s.s66),
        )
    }

    /// The effective constants (E, nu, delta, kappa).
    pub fn constants(&self) -> Effective {
        self.k
    }

    /// The in-plane compliances of paper eq. (1).
    pub fn compliances(&self) -> Compliances {
        let Effective {
            e,
            nu,
            delta,
            kappa,
        } = self.k;
        Compliances {
            s11: 1.0 / (delta * delta * e),
            s22: delta * delta / e,
            s12: -nu / e,
            s66: (kappa + nu) / e,
        }
    }

    /// sqrt(2 (1 + kappa)) = beta1 + beta2 over delta: finite in every root regime
    /// (kappa > 1, = 1, < 1), so no (beta1 - beta2) denominator appears.
    fn root_sum(&self) -> f64 {
        (2.0 * (1.0 + self.k.kappa)).sqrt()
    }

    /// Green's function constants A, B, C (docs/theory.md (M7)).
    pub fn green(&self) -> Green {
        let Effective { e, nu, delta, .. } = self.k;
        let r = self.root_sum();
        Green {
            a: (1.0 - nu) / e,
            b: r / (PI * delta * e),
            c: delta * r / (PI * e),
        }
    }

    /// b* = (1 - nu) / sqrt(2 (1 + kappa)) in (0, 1): the one material number the tractions
    /// depend on besides delta (docs/theory.md (R1)).
    pub fn b_star(&self) -> f64 {
        (1.0 - self.k.nu) / self.root_sum()
    }

    /// Coupling constants bp = A / (pi C) = b* / delta and bq = A / (pi B) = b* delta of
    /// eqs. (10)-(11), with the friction coefficient mu.
    pub fn coupling(&self, mu: f64) -> Coupling {
        let b = self.b_star();
        Coupling {
            bp: b / self.k.delta,
            bq: b * self.k.delta,
            mu,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn isotropic_plane_strain_matches_johnson() {
        let (e, nu) = (210e9, 0.3);
        let g = e / (2.0 * (1.0 + nu));
        let m = Material::plane_strain(e, e, e, g, nu, nu, nu).unwrap();
        let k = m.constants();
        assert!((k.delta - 1.0).abs() < 1e-15 && (k.kappa - 1.0).abs() < 1e-14);
        let gr = m.green();
        let a = (1.0 - 2.0 * nu) * (1.0 + nu) / e;
        let b = 2.0 * (1.0 - nu * nu) / (PI * e);
        assert!((gr.a - a).abs() <= 1e-14 * a);
        assert!((gr.b - b).abs() <= 1e-14 * b && (gr.c - b).abs() <= 1e-14 * b);
        let bq = gr.a / (PI * gr.b);
        assert!((bq - (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu))).abs() < 1e-14);
    }

    #[test]
    fn plane_stress_constants_follow_eq_2() {
        let (e11, e22, g12, nu12) = (181e9, 10.3e9, 7.17e9, 0.28);
        let k = Material::plane_stress(e11, e22, g12, nu12)
            .unwrap()
            .constants();
        let nu21 = nu12 * e22 / e11;
        assert!((k.e - (e11 * e22).sqrt()).abs() < 1e-15 * k.e);
        assert!((k.nu - (nu12 * nu21).sqrt()).abs() < 1e-15);
        assert!((k.delta.powi(4) - e11 / e22).abs() < 1e-13 * e11 / e22);
        assert!((k.kappa - (k.e / (2.0 * g12) - k.nu)).abs() < 1e-13);
    }

    #[test]
    fn auxetic_ply_keeps_the_sign_of_nu() {
        let k = Material::plane_stress(20e9, 5e9, 3e9, -0.4)
            .unwrap()
            .constants();
        assert!(k.nu < 0.0);
    }

    #[test]
    fn inadmissible_inputs_name_the_condition() {
        let e = Material::plane_stress(1.0, 1.0, 1.0, 1.5).unwrap_err();
        assert!(matches!(e, Error::InadmissibleMaterial(ref m) if m.contains("nu12")));
        let e = Material::effective(1.0, 0.3, 1.0, -0.5).unwrap_err();
        assert!(matches!(e, Error::InadmissibleMaterial(ref m) if m.contains("kappa")));
        assert!(matches!(
            Material::plane_stress(f64::NAN, 1.0, 1.0, 0.3),
            Err(Error::InvalidArgument(_))
        ));
        assert!(matches!(
            Material::plane_strain(1.0, 1.0, 1.0, 1.0, 0.6, 0.6, 0.6),
            Err(Error::InadmissibleMaterial(_))
        ));
    }

    #[test]
    fn compliances_round_trip() {
        let m = Material::effective(3.0, -0.2, 0.7, 0.4).unwrap();
        let s = m.compliances();
        let back = Material::from_compliances(s).unwrap().constants();
        let k = m.constants();
        for (x, y) in [
            (back.e, k.e),
            (back.nu, k.nu),
            (back.delta, k.delta),
            (back.kappa, k.kappa),
        ] {
            assert!((x - y).abs() < 1e-14 * (1.0 + y.abs()));
        }
    }
}
