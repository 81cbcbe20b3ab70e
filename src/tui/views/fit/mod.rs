//! Measured data and the fit (`o`, `f`, `F`): not a view of its own but a pane under the
//! charts of the impact and sweeps views, with the data drawn on them. The data loaded and the
//! fit asked and received in [`state`], the fit's thread in [`worker`], the pane in [`widget`];
//! its part of `update` is `update.rs`.

pub mod state;
mod update;
pub mod widget;
pub mod worker;
