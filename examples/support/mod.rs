//! Code shared by the examples; each example uses a part of it.
#![allow(dead_code)]

pub mod parallel;
pub mod plot;
