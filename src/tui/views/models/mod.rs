//! The models view (`Tab` to view 3/4): the field's contact models calibrated to the current
//! ball. The calibrations asked and received in [`state`] (they run on the shared
//! `tui::worker`), the table beside the charts in [`widget`] (the charts are
//! `crate::figure::explorer::models`); its part of `update` is `update.rs`.

pub mod state;
mod update;
pub mod widget;
