//! Code shared by the examples; each example uses a part of it.
#![allow(dead_code)]

pub mod clock;
pub mod parallel;
pub mod plot;

/// The four materials of the 12 benchmark scenes (each at mu = 0.1, 0.3, 1): examples
/// speed_accuracy and spectral_timing.
pub fn scene_materials() -> Vec<(&'static str, orthoslip::Material)> {
    use orthoslip::Material;
    vec![
        (
            "carbon/epoxy ply",
            Material::plane_stress(181e9, 10.3e9, 7.17e9, 0.28).unwrap(),
        ),
        (
            "isotropic steel, plane strain",
            Material::plane_strain(210e9, 210e9, 210e9, 210e9 / 2.6, 0.3, 0.3, 0.3).unwrap(),
        ),
        (
            "kappa = 0.4 < 1 (complex roots)",
            Material::effective(1.0, 0.25, 1.3, 0.4).unwrap(),
        ),
        (
            "strongly orthotropic, delta = 10",
            Material::effective(1.0, 0.1, 10.0, 3.0).unwrap(),
        ),
    ]
}
