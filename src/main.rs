//! The `bouncelab` binary: the explorer with no subcommand, the headless command line otherwise.

use std::process::ExitCode;

fn main() -> ExitCode {
    bouncelab::cli::main()
}
