//! The exact reloading branch (docs/theory_tangential.md section 15): after the first
//! unloading to Q** (= -Q* in a cycle), Q rises again. With the unloaded state as data the
//! branch is the first unloading's problem mirrored (section 5): under x -> -x, q -> -q the
//! reloading from the state at Q** is the unloading from the mirrored state at -Q**, to -Q.
//! So it is solved by [`unload`] on [`Mirror`] of the unloaded state, and read back mirrored:
//!
//! - (R1) H[p] = bp q on (-1, 1);
//! - (R2) on the stick set (b1, b2): H[q] + bq p = H[q**] + bq p** (stuck since Q**);
//! - (R3) on the new leading zone (b2, 1): q = +mu p (slip in -x since Q**); on the edge zone
//!   (-1, b1): q = -mu p (slip in +x, the unloading's leading zone's direction);
//! - (R4) int p = 1, int q = Q/P; bounded tractions at b1 and b2.
//!
//! With bp = 0 there is no zone at -1, and the branch sticks fully up to the first-slip load
//! Q_s = Q** + P (mu - q**/p0 at x = +1) ((T15a); loads below it are refused with that
//! formula); above it b2 solves (T15). For the ply's bq at Q* = 0.6 mu P, Q_s = 1.09 Q*: the
//! cycle shakes down after the first unloading.
//!
//! The corner (sections 15, 22, 23): for bp > 0 the unloaded state's thin trailing zone at
//! +1 sits on the friction bound and the reloading pushes it towards the bound, the mirror
//! of the unloading's corner above -0.48 Q* (section 13). On the ply the three-zone answer
//! does not converge there (the levels' tractions stay 5e-4 .. 9e-3 apart) and slips
//! backwards at +1: it is refused along the whole branch. The mirrored data's corner is the
//! unloaded trailing zone, (O1) with w = 1 - a2** ([`Mirror`]'s `loaded_edge_at_corner`), so
//! [`unload`] answers with the corner's outer model (section 20: a layer stuck since Q** at
//! +1, the zone (b2, 1 - layer) slipping in -x, the zone at -1), marched from Q** by
//! `outer_cold` and checked and estimated as the first unloading's (section 21). On the ply
//! the layer persists up to +Q* (section 23); the reloaded state with it is the data of the
//! second unloading, which [`unload`] answers with the outer model with a far layer
//! (`Start::far_layer`, sections 24-25).

#[cfg(test)]
pub(crate) mod tests;

use std::sync::Arc;

use super::unload::{Mirror, Start, Unloading, unload};
use crate::error::{Error, Result};

/// The reloading state: the unloading state of the mirrored problem, read back mirrored.
pub(crate) struct Reloading {
    pub(crate) mirrored: Unloading<Mirror>,
}

/// The reloading state at Q/P = qp (Q**/P < qp < mu) from the state `data` (the unloaded
/// state, seen mirrored: `Mirror { inner: unloaded }`), b1, b2 to `tol` and the tractions
/// to `traction_tol` ([`unload`]'s ladder, start and admissibility check, in the mirrored
/// frame).
pub(crate) fn reload(
    data: &Arc<Mirror>,
    qp: f64,
    tol: f64,
    traction_tol: f64,
) -> Result<Reloading> {
    let (q_low, mu) = (-data.qp(), data.coupling().mu);
    if !(qp > q_low && qp < mu) {
        return Err(Error::InvalidArgument(format!(
            "exact reloading: needs Q**/P < Q/P < mu (Q/P = {qp}, Q**/P = {q_low}, mu = {mu})"
        )));
    }
    unload(data, -qp, tol, traction_tol)
        .map(|mirrored| Reloading { mirrored })
        .map_err(|e| {
            // the unloading's messages speak of the mirrored frame: say so
            e.reworded(|m| {
                format!(
                    "exact reloading to Q/P = {qp}, solved as the mirrored unloading \
                     (x -> -x, q -> -q, docs/theory_tangential.md section 15): {m}"
                )
            })
        })
}

impl Reloading {
    /// Q/P.
    pub(crate) fn qp(&self) -> f64 {
        -self.mirrored.qp
    }

    /// (b1, b2), the stick set.
    pub(crate) fn stick_set(&self) -> (f64, f64) {
        let (a1, a2) = self.mirrored.stick_set();
        (-a2, -a1)
    }
}

/// A reloading state as the data of the next unloading: the mirror of its mirrored state.
impl Start for Reloading {
    fn coupling(&self) -> &crate::problem::Coupling {
        Start::coupling(&self.mirrored)
    }
    fn qp(&self) -> f64 {
        -Start::qp(&self.mirrored)
    }
    fn kinks(&self) -> Vec<super::unload::Kink> {
        Start::kinks(&self.mirrored)
            .into_iter()
            .rev()
            .map(super::unload::Kink::mirrored)
            .collect()
    }
    fn tractions(&self, opx: f64, omx: f64) -> (f64, f64) {
        let (p, q) = Start::tractions(&self.mirrored, omx, opx);
        (p, -q)
    }
    fn forcing(&self, opx: f64, omx: f64) -> f64 {
        Start::forcing(&self.mirrored, omx, opx)
    }
    fn path(&self) -> Vec<f64> {
        Start::path(&self.mirrored)
    }
    fn sign(&self) -> f64 {
        -Start::sign(&self.mirrored)
    }
    fn loaded_edge_at_corner(&self) -> bool {
        Start::slip_edge_at_far_corner(&self.mirrored)
    }
    fn slip_edge_at_far_corner(&self) -> bool {
        Start::loaded_edge_at_corner(&self.mirrored)
    }
    /// A reloading answered by the corner's outer model has its layer at +1 in the contact's
    /// frame: the second unloading's data (docs/theory_tangential.md sections 24-25).
    fn near_layer(&self) -> Option<f64> {
        Start::far_layer(&self.mirrored)
    }
    fn far_layer(&self) -> Option<f64> {
        Start::near_layer(&self.mirrored)
    }
}
