//! # orthoslip
//!
//! Contact tractions of a rigid flat-ended punch pressed into an orthotropic elastic
//! half-plane with Coulomb friction (partial slip), after Shen et al., Int. J. Mech. Sci. 135 (2018)
//! 168-175; model, conventions and methods in docs/theory.md. The Rust core lives in the modules below;
//! the C ABI in `src/ffi/` wraps it and is the only place that deals with raw pointers.
//!
//! ```
//! use orthoslip::{Contact, Material, Method};
//!
//! let ply = Material::plane_stress(181e9, 10.3e9, 7.17e9, 0.28).unwrap();
//! let mut contact = Contact::new(ply);
//! contact.set_friction(0.3).unwrap();
//! contact.set_method(Method::Goodman);
//! let s = contact.solve().unwrap();
//! let (p, q) = s.tractions(0.5);
//! assert!(s.c() > 0.0 && s.c() < 1.0 && p > 0.0 && q.is_finite());
//! ```

pub mod contact;
pub mod error;
pub mod fretting;
pub mod material;
pub mod model_error;
pub mod problem;
pub mod stick_edge_table;

// The numerical tools the methods share.
pub(crate) mod numerics;

// The half-plane's field solution under any method's tractions.
pub(crate) mod field;

// The methods.
pub mod coupled;
pub mod goodman;
pub mod lcp;
pub(crate) mod spectral;
pub mod spence;

// The C ABI: its exported functions are the C API, nothing in it is Rust API.
mod ffi;

pub use contact::{Contact, Method, Solution, TOLERANCE_FLOOR};
pub use error::{Error, Result};
pub use material::{Effective, Green, Material};
pub use problem::{Coupling, Profile, StickEdge};
