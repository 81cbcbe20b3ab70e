//! The fuzz targets' checks (see `checks`), a library so that both targets share them.

pub mod checks;
