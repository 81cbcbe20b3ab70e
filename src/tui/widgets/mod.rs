//! One file per panel, each a widget over the few things it shows (a figure, a view struct),
//! never the whole state: [`plot`] draws any figure, the others the readout, the header and
//! status line, and the dialogs. Nothing here changes the state or runs the model.

pub mod command;
pub mod confirm;
pub mod form;
pub mod help;
pub mod input;
pub mod marks;
pub mod picker;
pub mod pins;
pub mod plot;
pub mod quit;
pub mod readout;
pub mod status;
pub mod strokes;
pub mod surfaces;
pub mod tags;
pub mod title;
pub mod warning;
