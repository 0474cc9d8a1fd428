//! Material handles: construction from engineering or effective constants, and queries.

use super::{Failure, deref, free_handle, new_handle, orthoslip_status, run, write_all};
use crate::material::Material;

/// An orthotropic elastic half-plane (opaque). Immutable after construction: may be shared
/// between threads freely.
pub struct orthoslip_material {
    pub(crate) inner: Material,
}

fn wrap(m: crate::Result<Material>) -> Result<orthoslip_material, Failure> {
    Ok(orthoslip_material { inner: m? })
}

/// Creates a material from plane-stress engineering constants (paper eq. (2), with
/// E = sqrt(E11 E22)): Young's moduli e11 (along x, the surface) and e22 (along y, the
/// depth), in-plane shear modulus g12 (any consistent stress unit, all > 0) and Poisson's
/// ratio nu12 (admissible iff nu12^2 < e11/e22).
///
/// On success `*out` owns a new handle, to be released with `orthoslip_material_free`.
/// Returns ORTHOSLIP_OK, ORTHOSLIP_ERROR_NULL_POINTER (`out` NULL),
/// ORTHOSLIP_ERROR_INVALID_ARGUMENT (non-finite value, non-positive modulus, or moduli so
/// close to the ends of the double range that the compliances of
/// `orthoslip_material_green` would overflow or underflow: only their ratios matter),
/// ORTHOSLIP_ERROR_INADMISSIBLE_MATERIAL (compliance not positive definite) or
/// ORTHOSLIP_ERROR_INTERNAL. On failure `*out` is set to NULL.
///
/// # Safety
/// `out` must be NULL or valid for writing one pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_material_new_plane_stress(
    e11: f64,
    e22: f64,
    g12: f64,
    nu12: f64,
    out: *mut *mut orthoslip_material,
) -> orthoslip_status {
    unsafe {
        new_handle("orthoslip_material_new_plane_stress", out, || {
            wrap(Material::plane_stress(e11, e22, g12, nu12))
        })
    }
}

/// Creates a material from the orthotropic constants of a plane-strain half-plane (paper
/// eq. (3)): moduli e11 (x), e22 (y), e33 (out of plane), shear modulus g12 (all > 0) and
/// Poisson's ratios nu12, nu13, nu23 (nu_ij: contraction along j under stress along i). The
/// 3-D compliance must be positive definite.
///
/// Ownership, statuses and `*out` on failure as for `orthoslip_material_new_plane_stress`.
///
/// # Safety
/// `out` must be NULL or valid for writing one pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_material_new_plane_strain(
    e11: f64,
    e22: f64,
    e33: f64,
    g12: f64,
    nu12: f64,
    nu13: f64,
    nu23: f64,
    out: *mut *mut orthoslip_material,
) -> orthoslip_status {
    unsafe {
        new_handle("orthoslip_material_new_plane_strain", out, || {
            wrap(Material::plane_strain(e11, e22, e33, g12, nu12, nu13, nu23))
        })
    }
}

/// Creates a material from the effective constants of paper eq. (1): stiffness e > 0,
/// Poisson's ratio nu in (-1, 1), stiffness ratio delta > 0 and shear parameter
/// kappa > -nu (isotropic: delta = kappa = 1).
///
/// Ownership, statuses and `*out` on failure as for `orthoslip_material_new_plane_stress`.
///
/// # Safety
/// `out` must be NULL or valid for writing one pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_material_new_effective(
    e: f64,
    nu: f64,
    delta: f64,
    kappa: f64,
    out: *mut *mut orthoslip_material,
) -> orthoslip_status {
    unsafe {
        new_handle("orthoslip_material_new_effective", out, || {
            wrap(Material::effective(e, nu, delta, kappa))
        })
    }
}

/// Releases a material. NULL is a no-op. Contacts made from it keep their own copy.
///
/// # Safety
/// `m` must be NULL or a handle from an `orthoslip_material_new_*` function, not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_material_free(m: *mut orthoslip_material) {
    unsafe { free_handle(m) }
}

/// Writes the effective constants of paper eq. (1): stiffness e (unit of the moduli given),
/// Poisson's ratio nu, stiffness ratio delta and shear parameter kappa.
///
/// Returns ORTHOSLIP_OK or ORTHOSLIP_ERROR_NULL_POINTER (any argument NULL; nothing
/// written).
///
/// # Safety
/// `m` must be NULL or a live material; each out-pointer NULL or valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_material_effective(
    m: *const orthoslip_material,
    e: *mut f64,
    nu: *mut f64,
    delta: *mut f64,
    kappa: *mut f64,
) -> orthoslip_status {
    run("orthoslip_material_effective", || unsafe {
        let k = deref(m, "m")?.inner.constants();
        write_all(
            [(e, "e"), (nu, "nu"), (delta, "delta"), (kappa, "kappa")],
            [k.e, k.nu, k.delta, k.kappa],
        )
    })
}

/// Writes the surface Green's function constants A, B, C of paper eqs. (4)-(5) (unit:
/// 1 / unit of the moduli): A = (1 - nu)/E, B = sqrt(2(1 + kappa))/(pi delta E),
/// C = delta sqrt(2(1 + kappa))/(pi E).
///
/// Returns ORTHOSLIP_OK or ORTHOSLIP_ERROR_NULL_POINTER (any argument NULL; nothing
/// written).
///
/// # Safety
/// `m` must be NULL or a live material; each out-pointer NULL or valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn orthoslip_material_green(
    m: *const orthoslip_material,
    a: *mut f64,
    b: *mut f64,
    c: *mut f64,
) -> orthoslip_status {
    run("orthoslip_material_green", || unsafe {
        let g = deref(m, "m")?.inner.green();
        write_all([(a, "a"), (b, "b"), (c, "c")], [g.a, g.b, g.c])
    })
}
