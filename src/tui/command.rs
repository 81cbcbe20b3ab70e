//! "Copy as command" (`y`): the explorer's line that opens it in a setting again, the
//! `bouncelab run …` (or `collide …`) line with the same words that computes the setting's
//! impact, and the `#` lines an export's CSV files start with (that line and the parameters).
//!
//! The line names the ball as `run` finds it — `--preset NAME` (embedded or user preset), or
//! `--config FILE` for the preset the explorer was started on from a file — then the law when
//! it is not the preset's, the mass and radius typed in the form (`--mass`, `--radius`: the
//! preset's set derived for them), K_p and z_p when they differ from that ball's, λ and ζ when
//! K_r or c do (`run` sets K_r = λ K_p and c = √(m K_p)/(2ζ) from them on that ball, as the
//! explorer does: Eq. 24), and v0. Each number is the shortest decimal that gives `run` the
//! screen's ball to the bit, a pressure in the unit that writes it shortest (`--pressure
//! 8psi`; src/tui/exact.rs). [`not_carried`] builds the ball `run` makes of the line and names what
//! differs from the screen's, if anything. The copy to the terminal's clipboard (OSC 52) is
//! `crate::tui::clipboard`'s.

use crate::api::ConditionsSpec;
use crate::preset::Preset;
use crate::text::number;
use crate::tui::param::Param;
use crate::tui::setting::Setting;
use std::path::Path;

mod options;
use options::options;
pub use options::{conditioned_base, not_carried, params_off};

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

/// The line that computes the impact of `setting` of the ball `preset` found at `source`
/// (the export's CSV header: it reproduces the data): the explorer's line's words after the
/// subcommand that takes them, `bouncelab run …` against the wall or a
/// surface, `bouncelab collide …` on a target. c_t (`--tangential-damping`) acts along the
/// surface only: the normal impact does not use it, and neither subcommand takes it.
pub fn run_line(source: Source, preset: &Preset, setting: &Setting) -> String {
    let (subcommand, options) = impact_words(source, preset, setting);
    let mut words = vec!["bouncelab".to_string(), subcommand.into()];
    let mut rest = options.into_iter();
    while let Some(w) = rest.next() {
        if w == "--tangential-damping" {
            rest.next();
        } else {
            words.push(w);
        }
    }
    words.join(" ")
}

/// The explorer's line, `bouncelab --preset golf --law hertz --v0 3 …` (`y`, issue 29 item
/// 2): the options that open the explorer in this setting again (src/cli/explore.rs takes
/// every option `run` and `collide` take for a preset ball; tests/tui/tui_roundtrip.rs parses
/// it back), the same words [`run_line`] gives its subcommand.
pub fn explorer_line(source: Source, preset: &Preset, setting: &Setting) -> String {
    let mut words = vec!["bouncelab".to_string()];
    words.extend(impact_words(source, preset, setting).1);
    words.join(" ")
}

/// The options of the ball and of what it meets, and the subcommand that computes the impact
/// from them: `run` against the wall or a surface; `collide` on a target (`--target-mass`, …,
/// which `run` does not take), the ball's K_r and c then as `--k-r`, `--damping` (`collide`
/// takes no `--lambda`, `--zeta`; the explorer takes both forms).
fn impact_words(source: Source, preset: &Preset, setting: &Setting) -> (&'static str, Vec<String>) {
    let meets = what_the_ball_meets(setting);
    if meets.iter().any(|w| w.starts_with("--target-")) {
        let mut words = ball_by_k_r(source, preset, setting);
        words.extend(meets);
        return ("collide", words);
    }
    let mut words = options(source, preset, setting);
    words.extend(meets);
    ("run", words)
}

/// The options of what the ball meets, after the ball's: the target off the wall
/// (`--target-mass`, `--target-speed`, `--target-stiffness`, `--target-damping`, as `collide`
/// takes them, issue 51 item 2). Each is written only where it is not the wall's, so a line
/// of the wall is what it was; a surface adds its options here the same way.
fn what_the_ball_meets(setting: &Setting) -> Vec<String> {
    // the surface picked (`G`): by name, and the target's numbers where the form moved them
    // off it (issue 53 item 6)
    let (mut words, own, own_c_t) = picked_surface(setting);
    words.extend(tangential_damping(setting, own_c_t));
    let t = setting.target;
    words.extend(differing(&[
        ("--target-mass", t.mass, own.mass),
        ("--target-speed", t.speed, own.speed),
        ("--target-stiffness", t.stiffness, own.stiffness),
        ("--target-damping", t.damping, own.damping),
    ]));
    words
}

/// `--surface NAME` where one was picked (`G`, issue 53 item 6), and what the ball meets with
/// it: that surface's target and c_t (the rigid plate and none where none was picked). The
/// lines write the setting's target and c_t only where they differ from these.
fn picked_surface(setting: &Setting) -> (Vec<String>, crate::target::Target, Option<f64>) {
    match &setting.surface {
        Some(s) => (
            vec!["--surface".into(), shell_word(&s.name)],
            s.mechanics.target(),
            s.mechanics.tangential_damping,
        ),
        None => (Vec::new(), crate::target::Target::wall(), None),
    }
}

/// `--tangential-damping C` where the setting's c_t is not `own` (the surface's, which comes
/// with `--surface`); none as 0.
fn tangential_damping(setting: &Setting, own: Option<f64>) -> Vec<String> {
    if setting.tangential_damping == own {
        return Vec::new();
    }
    let c = setting.tangential_damping.unwrap_or(0.0);
    vec!["--tangential-damping".into(), number(c)]
}

/// Each option whose value is not its default, with the value.
fn differing(pairs: &[(&str, f64, f64)]) -> Vec<String> {
    let off: Vec<(&str, Option<f64>)> = pairs
        .iter()
        .map(|&(option, value, default)| (option, (value != default).then_some(value)))
        .collect();
    given(&off)
}

/// Each option that has a value, with it.
fn given(pairs: &[(&str, Option<f64>)]) -> Vec<String> {
    let mut words = Vec::new();
    for &(option, value) in pairs {
        if let Some(v) = value {
            words.extend([option.into(), number(v)]);
        }
    }
    words
}

/// `--k-r K --damping C` for the commands that take no `--lambda`, `--zeta`. `run` applies
/// them before the conditions, which then move K_r and c by the factor they move the ball's
/// own (src/api/conditions.rs): away from the record the line gives K_r and c before that
/// factor, so that the command's ball has the screen's (to rounding).
fn k_r_damping(preset: &Preset, setting: &Setting) -> [String; 4] {
    let p = &setting.params;
    let (mut k_r, mut c) = (p.k_r, p.damping);
    if !setting.conditions.is_empty() {
        let record = Setting {
            conditions: ConditionsSpec::default(),
            ..setting.clone()
        };
        if let (Ok(at), Ok(rec)) = (
            conditioned_base(preset, setting),
            conditioned_base(preset, &record),
        ) {
            k_r /= at.k_r / rec.k_r;
            c /= at.damping / rec.damping;
        }
    }
    ["--k-r".into(), number(k_r), "--damping".into(), number(c)]
}

/// `oblique`'s options of the surface the view bounces on (issue 53 item 6): `--surface NAME`
/// when one was picked, then `--surface-stiffness`, `--surface-damping`, `--surface-mass` where
/// the target (at rest) is not that surface's (or the rigid plate's), and c_t.
fn surface_options(setting: &Setting) -> Vec<String> {
    let (mut words, own, own_c_t) = picked_surface(setting);
    let t = setting.target;
    words.extend(differing(&[
        ("--surface-stiffness", t.stiffness, own.stiffness),
        ("--surface-damping", t.damping, own.damping),
        ("--surface-mass", t.mass, own.mass),
    ]));
    words.extend(tangential_damping(setting, own_c_t));
    words
}

/// The ball's options as [`explorer_line`]'s but K_r and c as `--k-r` and `--damping`, for
/// the commands that take no `--lambda`, `--zeta` (`oblique`, `shot`).
fn ball_by_k_r(source: Source, preset: &Preset, setting: &Setting) -> Vec<String> {
    let mut ball = options(source, preset, setting);
    if let Some(at) = ball.iter().position(|w| w == "--lambda") {
        ball.splice(at..at + 4, k_r_damping(preset, setting));
    }
    ball
}

/// The oblique view's line, `bouncelab oblique --preset tennis --v0 25 --angle 16 --spin 300
/// --friction 0.6 …` (`y` there, issue 31): the ball's options as [`explorer_line`]'s but
/// K_r and c as `--k-r` and `--damping` (`oblique` takes no `--lambda`, `--zeta`: the same
/// numbers, exactly), then θ, ω, μ and the K_t, κ set in the view (tests/tui/tui_oblique.rs runs
/// it and compares its JSON with the screen's impact).
pub fn oblique_line(
    source: Source,
    preset: &Preset,
    setting: &Setting,
    o: &crate::tui::views::oblique::state::ObliqueValues,
) -> String {
    let mut words = vec!["bouncelab".to_string(), "oblique".into()];
    words.extend(ball_by_k_r(source, preset, setting));
    words.extend(surface_options(setting));
    words.extend(given(&[
        ("--angle", Some(o.angle)),
        ("--spin", Some(o.spin)),
        ("--friction", Some(o.friction)),
        ("--tangential-stiffness", o.tangential_stiffness),
        ("--inertia-factor", o.inertia_factor),
    ]));
    words.join(" ")
}

/// The `bouncelab shot` line that computes the flight view's shot: the ball's options as
/// `oblique_line`'s (K_r and c for λ and ζ, which `shot` does not take), no v0 (the launch
/// speed is the view's), then the launch and μ (src/tui/views/flight/).
pub fn shot_line(
    source: Source,
    preset: &Preset,
    setting: &Setting,
    v: &crate::tui::views::flight::state::FlightValues,
) -> String {
    let mut words = vec!["bouncelab".to_string(), "shot".into()];
    let mut ball = ball_by_k_r(source, preset, setting);
    if let Some(at) = ball.iter().position(|w| w == "--v0") {
        ball.drain(at..at + 2);
    }
    words.extend(ball);
    use crate::tui::views::flight::param::FlightParam;
    for p in FlightParam::ALL {
        words.extend([p.option().into(), number(v.get(p))]);
    }
    words.extend(v.net_words());
    words.join(" ")
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

    /// On a ball of the materials set a typed mass moves the derived density, hence c (Eq. 5),
    /// and a typed radius K_p, z_p (Eqs. 15–20) and c for `run`: the line adds `--k-p`, `--z-p`
    /// and ζ and reproduces the screen (the elastomer's K_h of Eq. 8 is Eq. 16's of its K_p
    /// and z_p). A parameter no option reaches (here a K_h set by hand) is named.
    #[test]
    fn a_materials_ball_runs_to_the_screen_or_names_what_is_not_carried() {
        let mut p = Preset::embedded()[0].clone();
        p.parameters = crate::preset::ParamSource::Materials;
        let mut s = Setting::from_preset(0, &p);
        assert_eq!(not_carried(&p, &s), None);
        s.params.mass = 0.05;
        let line = run_line(Source::Name(&p.name), &p, &s);
        assert!(
            line.contains(" --mass 0.05 --lambda ") && line.contains(" --zeta "),
            "{line}"
        );
        assert_eq!(not_carried(&p, &s), None, "{line}");
        s.radius = 0.03;
        let line = run_line(Source::Name(&p.name), &p, &s);
        assert!(
            line.contains(" --radius 0.03 --k-p ") && line.contains(" --z-p "),
            "{line}"
        );
        assert_eq!(not_carried(&p, &s), None, "{line}");
        s.params.k_h *= 1.5;
        let why = not_carried(&p, &s).expect("K_h is not carried");
        assert!(why.contains("another K_h:"), "{why}");
    }
}
