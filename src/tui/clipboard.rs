//! The terminal's clipboard for "copy as command" (`y`): OSC 52, sent only where the
//! terminal is known to take it (docs/explorer.md, `y`). The line itself is
//! `crate::tui::command`'s.

/// OSC 52, "set the clipboard to `text`": `ESC ] 52 ; c ; base64(text) BEL`, sent only where
/// [`osc52_allowed`] says the terminal takes it (docs/explorer.md, `y`). Base64 by the
/// `base64` crate.
pub fn osc52(text: &str) -> String {
    use base64::Engine;
    let b64 = base64::engine::general_purpose::STANDARD.encode(text.as_bytes());
    format!("\x1b]52;c;{b64}\x07")
}

/// Write [`osc52`] of `text` to the terminal (the event loop's part of `y`); a failure to
/// write only means no copy: the box shows the line to select by hand.
pub fn copy(text: &str) {
    use std::io::Write;
    let mut out = std::io::stdout();
    let _ = out.write_all(osc52(text).as_bytes());
    let _ = out.flush();
}

/// The environment variable that forces OSC 52 on (`1`, `on`, `yes`, `true`) or off (`0`,
/// `off`, `no`, `false`) whatever the terminal.
pub const OSC52_VAR: &str = "BOUNCELAB_OSC52";

/// Terminals that take OSC 52 by default, known by `$TERM_PROGRAM`: iTerm2, WezTerm, Ghostty.
const OSC52_PROGRAMS: [&str; 3] = ["iTerm.app", "WezTerm", "ghostty"];
/// … by the start of `$TERM`: kitty, foot, Alacritty, WezTerm, Ghostty.
const OSC52_TERMS: [&str; 5] = [
    "xterm-kitty",
    "foot",
    "alacritty",
    "wezterm",
    "xterm-ghostty",
];
/// … by a variable of their own: kitty, Windows Terminal.
const OSC52_MARKS: [&str; 2] = ["KITTY_WINDOW_ID", "WT_SESSION"];

/// Whether to copy with OSC 52 (issue 29 item 2), as htop and lazygit decide on escape
/// sequences: only where the terminal is known to take it, because an unknown one may print
/// the sequence as garbage or (VTE, Konsole) silently drop it and a "copied" would lie.
/// `env` reads a variable; `tmux_clipboard` is tmux's `set-clipboard` option when inside tmux
/// (`tmux show-options -gv set-clipboard`): tmux passes an application's OSC 52 on only when
/// it is `on` (its default, `external`, keeps it from applications). Order: [`OSC52_VAR`],
/// then tmux, then GNU screen (never: it swallows the sequence), then the known terminals.
pub fn osc52_allowed(env: &dyn Fn(&str) -> Option<String>, tmux_clipboard: Option<&str>) -> bool {
    if let Some(v) = env(OSC52_VAR) {
        match v.trim().to_ascii_lowercase().as_str() {
            "1" | "on" | "yes" | "true" => return true,
            "0" | "off" | "no" | "false" => return false,
            _ => {}
        }
    }
    let set = |k: &str| env(k).is_some_and(|v| !v.is_empty());
    if set("TMUX") {
        return tmux_clipboard.map(str::trim) == Some("on");
    }
    if set("STY") {
        return false;
    }
    let program = env("TERM_PROGRAM").unwrap_or_default();
    let term = env("TERM").unwrap_or_default();
    OSC52_PROGRAMS.contains(&program.as_str())
        || OSC52_TERMS.iter().any(|t| term.starts_with(t))
        || OSC52_MARKS.iter().any(|&k| set(k))
}

/// [`osc52_allowed`] for this process: its environment, and tmux asked for its option when
/// `$TMUX` is set (a failure to ask counts as "not on").
pub fn osc52_here() -> bool {
    let env = |k: &str| std::env::var(k).ok();
    let tmux = env("TMUX").filter(|v| !v.is_empty()).and_then(|_| {
        let out = std::process::Command::new("tmux")
            .args(["show-options", "-gv", "set-clipboard"])
            .stderr(std::process::Stdio::null())
            .output()
            .ok()?;
        String::from_utf8(out.stdout).ok()
    });
    osc52_allowed(&env, tmux.as_deref())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env_of<'a>(vars: &'a [(&'a str, &'a str)]) -> impl Fn(&str) -> Option<String> + 'a {
        move |k| {
            vars.iter()
                .find(|(name, _)| *name == k)
                .map(|(_, v)| v.to_string())
        }
    }

    /// OSC 52 goes out only where the terminal takes it: known terminals, tmux with
    /// `set-clipboard on`, or the opt-in; never in GNU screen, an unknown terminal or tmux's
    /// default `external`; the opt-out wins over everything.
    #[test]
    fn osc52_only_where_the_terminal_takes_it() {
        let allowed =
            |vars: &[(&str, &str)], tmux: Option<&str>| osc52_allowed(&env_of(vars), tmux);
        assert!(allowed(&[("TERM", "xterm-kitty")], None));
        assert!(allowed(&[("TERM", "foot-extra")], None));
        assert!(allowed(
            &[("TERM_PROGRAM", "WezTerm"), ("TERM", "xterm-256color")],
            None
        ));
        assert!(allowed(
            &[("WT_SESSION", "x"), ("TERM", "xterm-256color")],
            None
        ));
        assert!(
            !allowed(&[("TERM", "xterm-256color")], None),
            "unknown: not sent"
        );
        assert!(!allowed(
            &[("TERM", "xterm-256color"), ("VTE_VERSION", "7600")],
            None
        ));
        let tmux = [
            ("TMUX", "/tmp/tmux-1/default,1,0"),
            ("TERM", "tmux-256color"),
        ];
        assert!(allowed(&tmux, Some("on\n")));
        assert!(
            !allowed(&tmux, Some("external\n")),
            "tmux's default keeps it"
        );
        assert!(!allowed(&tmux, None));
        assert!(!allowed(&[("STY", "1.pts"), ("TERM", "xterm-kitty")], None));
        assert!(allowed(&[("BOUNCELAB_OSC52", "1"), ("TERM", "dumb")], None));
        assert!(!allowed(
            &[("BOUNCELAB_OSC52", "off"), ("TERM", "xterm-kitty")],
            None
        ));
        assert!(!allowed(
            &[("BOUNCELAB_OSC52", "off"), ("TMUX", "x")],
            Some("on")
        ));
    }
}
