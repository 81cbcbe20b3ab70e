//! The physical model: parameters, contact laws, and parameters from materials.

pub mod contact;
pub mod params;
