//! "Copy as command" (`y`): the `bouncelab run …` line that reproduces a setting of the
//! explorer, and the `#` lines an export's CSV files start with (that line and the parameters).
//!
//! The line names the ball as `run` finds it — `--preset NAME` (embedded or user preset), or
//! `--config FILE` for the preset the explorer was started on from a file — then the law when
//! it is not the preset's, λ and ζ when K_r or c moved off the preset's (`run` sets K_r = λ K_p
//! and c = √(m K_p)/(2ζ) from them, as the explorer does: Eq. 24), and v0. Numbers are written
//! in the shortest form that reads back to the same `f64`.

use crate::preset::Preset;
use crate::text::number;
use crate::tui::param::Param;
use crate::tui::setting::Setting;
use std::path::Path;

/// Where `run` finds the ball.
#[derive(Debug, Clone, Copy)]
pub enum Source<'a> {
    /// `--preset NAME`.
    Name(&'a str),
    /// `--config FILE`.
    Config(&'a Path),
}

/// `s` as one shell word: kept when it holds only characters no shell treats specially,
/// single-quoted otherwise (a `'` inside as `'\''`).
pub fn shell_word(s: &str) -> String {
    let plain = |c: char| c.is_ascii_alphanumeric() || "-_./:=+,@%".contains(c);
    if !s.is_empty() && s.chars().all(plain) {
        s.to_string()
    } else {
        format!("'{}'", s.replace('\'', r"'\''"))
    }
}

/// The `bouncelab run` line that runs `setting` of the ball `preset` found at `source`.
pub fn run_line(source: Source, preset: &Preset, setting: &Setting) -> String {
    let mut words = vec!["bouncelab".to_string(), "run".into()];
    match source {
        Source::Name(name) => words.extend(["--preset".into(), shell_word(name)]),
        Source::Config(path) => {
            words.extend(["--config".into(), shell_word(&path.to_string_lossy())])
        }
    }
    if setting.law != preset.law {
        words.extend(["--law".into(), setting.law.name().into()]);
    }
    let base = preset.params();
    let p = &setting.params;
    // K_p and z_p typed in the form (`m`) are `run`'s overrides; λ and ζ below are then taken
    // on the overridden ball, as `run` applies --lambda/--zeta after --k-p/--z-p
    for (option, now, was) in [("--k-p", p.k_p, base.k_p), ("--z-p", p.z_p, base.z_p)] {
        if now != was {
            words.extend([option.into(), number(now)]);
        }
    }
    if p.mass != base.mass {
        // `run` runs the preset's mass: K_r and c as they are, not λ and ζ, which would move
        // them with it (see `not_carried`)
        for (option, now, was) in [
            ("--k-r", p.k_r, base.k_r),
            ("--damping", p.damping, base.damping),
        ] {
            if now != was {
                words.extend([option.into(), number(now)]);
            }
        }
    } else if p.k_r != base.k_r || p.damping != base.damping {
        for (option, param) in [("--lambda", Param::Lambda), ("--zeta", Param::Zeta)] {
            words.extend([option.into(), number(setting.get(param))]);
        }
    }
    words.extend(["--v0".into(), number(p.v0)]);
    words.join(" ")
}

/// What the line cannot carry: a mass or radius typed in the form (`m`) — `run` has no such
/// options and runs the preset's. `None` when the line reproduces the setting.
pub fn not_carried(preset: &Preset, setting: &Setting) -> Option<String> {
    let mut off = Vec::new();
    if setting.params.mass != preset.measured.mass {
        off.push("m");
    }
    if setting.radius != preset.measured.radius {
        off.push("R");
    }
    (!off.is_empty()).then(|| {
        format!(
            "{} typed in the form: `run` has no option for {} and runs the preset's",
            off.join(" and "),
            if off.len() > 1 { "them" } else { "it" }
        )
    })
}

/// The `#` lines an export's CSV files start with: the command, the ball and law, every
/// parameter in SI, then one command per pin.
pub fn csv_header(line: &str, preset: &Preset, setting: &Setting, pins: &[String]) -> Vec<String> {
    let p = &setting.params;
    let mut out = vec![
        format!("# {line}"),
        format!(
            "# ball {} ({} parameters), {} law",
            preset.name,
            preset.parameters.name(),
            setting.law
        ),
        format!(
            "# lambda {}, zeta {}, v0 {} m/s; mass {} kg, k_p {} N/m, k_r {} N/m, c {} kg/s, z_p {} m",
            number(setting.get(Param::Lambda)),
            number(setting.get(Param::Zeta)),
            number(p.v0),
            number(p.mass),
            number(p.k_p),
            number(p.k_r),
            number(p.damping),
            number(p.z_p),
        ),
    ];
    for (i, pin) in pins.iter().enumerate() {
        out.push(format!("# pinned {}: {pin}", i + 1));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_are_quoted_only_when_needed() {
        assert_eq!(shell_word("golf-custom"), "golf-custom");
        assert_eq!(shell_word("/tmp/my ball.toml"), "'/tmp/my ball.toml'");
        assert_eq!(shell_word("it's"), r"'it'\''s'");
        assert_eq!(shell_word(""), "''");
    }

    #[test]
    fn the_preset_as_it_is_needs_only_its_speed() {
        let p = &Preset::embedded()[0];
        let s = Setting::from_preset(0, p);
        let line = run_line(Source::Name(&p.name), p, &s);
        assert_eq!(
            line,
            format!("bouncelab run --preset superball --v0 {}", p.params().v0)
        );
        let mut moved = s.clone();
        moved.params = Param::Lambda.set(&moved.params, 0.5);
        moved.law = p.law.next();
        let line = run_line(Source::Config(Path::new("/a b/x.toml")), p, &moved);
        assert!(line.starts_with("bouncelab run --config '/a b/x.toml' --law "));
        assert!(line.contains(" --lambda 0.5 --zeta "), "{line}");
    }
}
