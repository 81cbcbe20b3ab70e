//! What the examples that run a [`Ball`](bouncelab::Ball) share (`mod common;` in each): their
//! exit, as the command line's.

use bouncelab::BallError;
use std::process::ExitCode;

/// Success, or the error on stderr and exit 2: the message names the field at fault, as the
/// command line's does.
pub fn exit(result: Result<(), BallError>) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}
