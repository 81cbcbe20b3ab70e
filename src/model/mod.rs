//! The physical model: parameters, contact laws, and parameters from materials.

pub mod contact;
pub mod materials;
pub mod params;
