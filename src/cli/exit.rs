//! How a failure ends the command line: one line on stderr, `bouncelab: error: …`, and one
//! exit code by the kind of error anywhere in its chain ([`exit_code`]: 130 interrupted, 1 not
//! the input's fault, 2 bad input; a closed pipe is no error). The module's introduction
//! (`super`) states the contract.

use super::budget;
use crate::solver::SolveError;
use std::io::{self, Write};
use std::process::ExitCode;

/// The explorer failed (its terminal, its event loop): not the input's fault.
#[derive(Debug, thiserror::Error)]
#[error("{0:#}")]
pub(super) struct ExplorerFailed(pub(super) anyhow::Error);

/// The command's end after `e`: its line on stderr and its exit code ([`report`]).
pub(super) fn fail(e: anyhow::Error) -> ExitCode {
    match report(&e) {
        None => ExitCode::SUCCESS,
        Some((code, line)) => {
            say(&line);
            ExitCode::from(code)
        }
    }
}

/// The exit code and the one line an error ends the command line with; `None` for a closed
/// pipe (`bouncelab … | head`), which is no error.
fn report(e: &anyhow::Error) -> Option<(u8, String)> {
    let code = exit_code(e)?;
    let line = if code == 130 {
        // an interruption is no error of the command's
        format!("bouncelab: {}", budget::Interrupted)
    } else {
        format!("bouncelab: error: {}", one_line(&format!("{e:#}")))
    };
    Some((code, line))
}

/// The one place that maps what went wrong to an exit code, by the kind of error anywhere in
/// the chain: 130 for an interruption (Ctrl-C during long work), 1 for what is not the input's
/// fault (reading or writing files, the explorer's terminal, drawing a figure, an impact the
/// solver could not bring to an end), 2 for bad input of any kind; `None` for a closed pipe.
fn exit_code(e: &anyhow::Error) -> Option<u8> {
    let io_kind = e
        .chain()
        .find_map(|c| c.downcast_ref::<io::Error>())
        .map(io::Error::kind);
    if io_kind == Some(io::ErrorKind::BrokenPipe) {
        return None;
    }
    // Ctrl-C during long work (cli::budget): the shell's code for SIGINT
    // (a SIGINT or SIGTERM that stopped a write makes any failure an interruption: the
    // atomic writer removed what it had staged)
    if e.downcast_ref::<budget::Interrupted>().is_some() || budget::interrupted() {
        return Some(130);
    }
    let not_the_input = |c: &(dyn std::error::Error + 'static)| {
        c.is::<ExplorerFailed>()
            || c.is::<crate::figure::svg::RenderError>()
            || c.is::<crate::api::BatchUnanswered>()
            || matches!(
                c.downcast_ref(),
                Some(
                    crate::analysis::fit::MultiFitError::NoAnswer
                        | crate::analysis::fit::MultiFitError::Unanswered(_)
                )
            )
            || matches!(c.downcast_ref(), Some(SolveError::Unresolved { .. }))
            || c.downcast_ref::<crate::BallError>()
                .is_some_and(crate::BallError::is_no_answer)
    };
    if io_kind.is_some() || e.chain().any(not_the_input) {
        Some(1)
    } else {
        Some(2)
    }
}

/// One line on stderr, its control characters shown as text (crate::sanitize). A stderr that
/// cannot take it (full, closed) changes nothing: the exit code still tells
/// (tests/cli/cli_guarantees.rs, `a_full_stderr_still_exits_2_and_help_to_a_full_stdout_fails`).
fn say(line: &str) {
    let _ = writeln!(io::stderr(), "{}", crate::sanitize::line(line));
}

/// Any message as one line.
fn one_line(s: &str) -> String {
    s.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join(" ")
}

/// Clap's usage errors condensed to one line (help and version print as usual).
pub(super) fn clap_error(e: clap::Error) -> ExitCode {
    use clap::error::ErrorKind::*;
    if matches!(
        e.kind(),
        DisplayHelp | DisplayVersion | DisplayHelpOnMissingArgumentOrSubcommand
    ) {
        // help asked for but not delivered (stdout full or closed) is a failed command
        let printed = e.print().and_then(|()| io::stdout().flush());
        if printed.is_err() {
            return ExitCode::from(1);
        }
        return ExitCode::from(e.exit_code().clamp(0, 255) as u8);
    }
    let text = e.render().to_string();
    let body: Vec<&str> = text
        .lines()
        .take_while(|l| !l.starts_with("Usage:"))
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with("For more information"))
        .collect();
    let msg = body.join(" ");
    let msg = msg.strip_prefix("error: ").unwrap_or(&msg);
    say(&format!("bouncelab: error: {msg} (see --help)"));
    ExitCode::from(2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::params::{Field, ParamError};
    use crate::solver::Unresolved;

    /// No input known reaches "no answer" (the property tests hold the solvers to an answer
    /// over the whole domain), so its path is checked here rather than through the binary:
    /// one line naming λ and ζ, exit 1 (not the input's fault).
    #[test]
    fn no_answer_is_one_line_and_exit_1() {
        let unresolved = SolveError::Unresolved {
            reason: Unresolved::Steps,
            steps: 1_000_001,
            lambda: 0.0,
            zeta: 1e4,
        };
        // as the solver gives it, and as the library's Ball (which `run` goes through) does
        let errors = [
            anyhow::Error::from(unresolved.clone()),
            anyhow::Error::from(crate::BallError::Solve(unresolved)),
        ];
        for e in &errors {
            let (code, line) = report(e).unwrap();
            assert_eq!(code, 1);
            assert_eq!(
                line,
                "bouncelab: error: no answer at λ = 0, ζ = 10000: the step budget of the impact \
                 ran out (1000001 steps); a nearby λ or ζ may answer"
            );
        }
    }

    #[test]
    fn bad_parameters_are_exit_2() {
        let e = anyhow::Error::from(SolveError::Param(ParamError {
            field: Field::Zeta,
            value: f64::NAN,
            reason: "not a number",
        }));
        let (code, line) = report(&e).unwrap();
        assert_eq!(code, 2);
        assert!(line.contains("zeta") && !line.contains('\n'), "{line}");
    }
}
