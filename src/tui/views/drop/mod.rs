//! The drop view (`d`, outside the `Tab` cycle): the ball released from a height, its bounce
//! sequence and its standard's verdict. Its state and clock in [`state`], its panel in
//! [`widget`]; its part of `update` is `update.rs`.

pub mod state;
mod update;
pub mod widget;
