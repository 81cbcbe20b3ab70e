//! The headless command line (clap). Entry point: [`main`].

use std::process::ExitCode;

pub fn main() -> ExitCode {
    match crate::tui::run(crate::preset::Preset::embedded().remove(0)) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("bouncelab: error: {e}");
            ExitCode::from(2)
        }
    }
}
