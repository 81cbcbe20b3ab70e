//! The physical model: parameters, contact laws, and parameters from materials.

mod checks;
pub mod contact;
pub mod materials;
pub mod params;
pub mod static_chain;
