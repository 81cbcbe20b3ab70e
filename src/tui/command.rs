//! "Copy as command" (`y`): the `bouncelab run …` line that reproduces a setting of the
//! explorer, and the `#` lines an export's CSV files start with (that line and the parameters).
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

use crate::api::{self, ConditionsSpec, Overrides};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::preset::Preset;
use crate::text::number;
use crate::tui::exact;
use crate::tui::param::Param;
use crate::tui::physical::conditions::conditioned;
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

/// The options that take `run` from the preset to `setting` (module docs), in their order.
#[derive(Clone)]
struct Options {
    law: Option<ContactLaw>,
    /// --mass, --radius, --k-p, --z-p (None: the preset's).
    mass: Option<f64>,
    radius: Option<f64>,
    k_p: Option<f64>,
    z_p: Option<f64>,
    /// --lambda and --zeta, when K_r or c is not what the ball above has.
    lambda_zeta: Option<(f64, f64)>,
    v0: f64,
    /// --pressure and --temperature (None: the record's).
    conditions: ConditionsSpec,
}

impl Options {
    fn of(preset: &Preset, setting: &Setting) -> Options {
        let p = &setting.params;
        let differs = |now: f64, was: f64| (now != was).then_some(now);
        let mass = differs(p.mass, preset.measured.mass);
        let radius = differs(setting.radius, preset.measured.radius);
        let base = Self::sized(preset, mass, radius);
        // at the conditions typed (issue 56): `run` sets K_p (K_r, c) from them, after the
        // ball's size; no `--k-p` where the conditions' K_p is the setting's
        let r = radius.unwrap_or(preset.measured.radius);
        let base = conditioned(preset, base, r, &setting.conditions).unwrap_or(base);
        let mut o = Options {
            law: (setting.law != preset.law).then_some(setting.law),
            mass,
            radius,
            k_p: differs(p.k_p, base.k_p),
            z_p: differs(p.z_p, base.z_p),
            lambda_zeta: None,
            v0: p.v0,
            conditions: setting.conditions,
        };
        // λ and ζ are taken on the ball the options above make, as `run` applies them
        let ball = o.ball(preset).unwrap_or(base);
        if p.k_r != ball.k_r || p.damping != ball.damping {
            o.lambda_zeta = Some((setting.get(Param::Lambda), setting.get(Param::Zeta)));
        }
        o.shortened(preset)
    }

    /// These options with λ and ζ the shortest decimals that make `run`'s ball the same to
    /// the bit (src/tui/exact.rs): λ = K_r/K_p of a typed 0.3 is 0.30000000000000004, and
    /// "0.3" gives the same K_r; one no shorter text reproduces is kept whole. The other
    /// numbers are the setting's own (m, R, K_p, z_p, v0, T: typed or stepped as decimals),
    /// written as they are: R, for one, moves no parameter of a fitted ball, so "the same
    /// ball" could not tell 0.025 from 0.03.
    fn shortened(mut self, preset: &Preset) -> Options {
        let Some(want) = self.ball(preset) else {
            return self;
        };
        type Slot = fn(&mut Options) -> Option<&mut f64>;
        let slots: [Slot; 2] = [
            |o| o.lambda_zeta.as_mut().map(|(l, _)| l),
            |o| o.lambda_zeta.as_mut().map(|(_, z)| z),
        ];
        for slot in slots {
            let Some(&mut x) = slot(&mut self) else {
                continue;
            };
            let short = exact::shortest_accepted(x, |y| {
                let mut tried = self.clone();
                if let Some(v) = slot(&mut tried) {
                    *v = y;
                }
                tried.ball(preset) == Some(want)
            });
            if let Some(v) = slot(&mut self) {
                *v = short;
            }
        }
        self
    }

    /// The preset's parameter set derived for mass `m` and radius `r` (`run --mass --radius`).
    fn sized(preset: &Preset, m: Option<f64>, r: Option<f64>) -> ImpactParams {
        let mut sized = preset.clone();
        sized.measured.mass = m.unwrap_or(sized.measured.mass);
        sized.measured.radius = r.unwrap_or(sized.measured.radius);
        sized.params()
    }

    /// The parameters `run` builds from these options, by the library's own steps
    /// ([`Overrides::apply`], [`api::set_lambda_zeta`]); `None` where it would refuse them.
    fn ball(&self, preset: &Preset) -> Option<ImpactParams> {
        let mut p = Self::sized(preset, self.mass, self.radius);
        p.v0 = self.v0;
        let set = Overrides {
            mass: self.mass,
            k_p: self.k_p,
            z_p: self.z_p,
            ..Overrides::default()
        };
        set.apply(&mut p).ok()?;
        if !self.conditions.is_empty() {
            // `run` refuses --k-p beside --pressure (Ball::at_conditions)
            if self.k_p.is_some()
                && preset
                    .calibration
                    .as_ref()
                    .and_then(|c| c.pressure)
                    .is_some()
            {
                return None;
            }
            let r = self.radius.unwrap_or(preset.measured.radius);
            p = conditioned(preset, p, r, &self.conditions).ok()?;
        }
        if let Some((l, z)) = self.lambda_zeta {
            api::set_lambda_zeta(&mut p, Some(l), Some(z)).ok()?;
        }
        Some(p)
    }
}

/// The parameters the `y` line's ball options make at the setting's conditions, before λ and
/// ζ: the preset sized by `--mass`, `--radius`, `--z-p` as `run` sizes it, then
/// `--pressure`, `--temperature` ([`conditioned`]). The form's conditions start from these
/// (src/tui/physical/conditions.rs), so the line and the screen agree.
pub fn conditioned_base(preset: &Preset, setting: &Setting) -> Result<ImpactParams, String> {
    let o = Options::of(preset, setting);
    let mut p = Options::sized(preset, o.mass, o.radius);
    p.v0 = setting.params.v0;
    let set = Overrides {
        mass: o.mass,
        z_p: o.z_p,
        ..Overrides::default()
    };
    set.apply(&mut p).map_err(|e| e.to_string())?;
    conditioned(preset, p, setting.radius, &setting.conditions)
}

/// The `bouncelab run` line that runs `setting` of the ball `preset` found at `source` (the
/// export's CSV header: it reproduces the data).
pub fn run_line(source: Source, preset: &Preset, setting: &Setting) -> String {
    let mut words = vec!["bouncelab".to_string(), "run".into()];
    words.extend(options(source, preset, setting));
    words.join(" ")
}

/// The explorer's line, `bouncelab --preset golf --law hertz --v0 3 …` (`y`, issue 29 item
/// 2): `run`'s options without `run`, which open the explorer in this setting again
/// (src/cli/explore.rs takes every option `run` takes; tests/tui/tui_roundtrip.rs parses it back).
pub fn explorer_line(source: Source, preset: &Preset, setting: &Setting) -> String {
    let mut words = vec!["bouncelab".to_string()];
    words.extend(options(source, preset, setting));
    words.extend(what_the_ball_meets(setting));
    words.join(" ")
}

/// The options of what the ball meets, after the ball's: the target off the wall
/// (`--target-mass`, `--target-speed`, `--target-stiffness`, `--target-damping`, as `collide`
/// takes them, issue 51 item 2). Each is written only where it is not the wall's, so a line
/// of the wall is what it was; a surface adds its options here the same way.
fn what_the_ball_meets(setting: &Setting) -> Vec<String> {
    // the surface picked (`G`): by name, and the target's numbers where the form moved them
    // off it (issue 53 item 6)
    let mut words = Vec::new();
    let (wall, c_t) = match &setting.surface {
        Some(s) => {
            words.extend(["--surface".into(), shell_word(&s.name)]);
            (s.target(), s.tangential_damping)
        }
        None => (crate::target::Target::wall(), None),
    };
    if setting.tangential_damping != c_t {
        let c = setting.tangential_damping.unwrap_or(0.0);
        words.extend(["--tangential-damping".into(), number(c)]);
    }
    let t = setting.target();
    for (option, value, default) in [
        ("--target-mass", t.mass, wall.mass),
        ("--target-speed", t.speed, wall.speed),
        ("--target-stiffness", t.stiffness, wall.stiffness),
        ("--target-damping", t.damping, wall.damping),
    ] {
        if value != default {
            words.extend([option.into(), number(value)]);
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
    let mut words = Vec::new();
    let (own, own_c_t) = match &setting.surface {
        Some(s) => {
            words.extend(["--surface".into(), shell_word(&s.name)]);
            (s.target(), s.tangential_damping)
        }
        None => (crate::target::Target::wall(), None),
    };
    let t = setting.target();
    for (option, value, default) in [
        ("--surface-stiffness", t.stiffness, own.stiffness),
        ("--surface-damping", t.damping, own.damping),
        ("--surface-mass", t.mass, own.mass),
    ] {
        if value != default {
            words.extend([option.into(), number(value)]);
        }
    }
    // the surface's own c_t comes with --surface; another (0: none) is written
    if setting.tangential_damping != own_c_t {
        let c = setting.tangential_damping.unwrap_or(0.0);
        words.extend(["--tangential-damping".into(), number(c)]);
    }
    words
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
    let mut ball = options(source, preset, setting);
    if let Some(at) = ball.iter().position(|w| w == "--lambda") {
        ball.splice(at..at + 4, k_r_damping(preset, setting));
    }
    words.extend(ball);
    words.extend(surface_options(setting));
    for (option, value) in [
        ("--angle", Some(o.angle)),
        ("--spin", Some(o.spin)),
        ("--friction", Some(o.friction)),
        ("--tangential-stiffness", o.tangential_stiffness),
        ("--inertia-factor", o.inertia_factor),
    ] {
        if let Some(v) = value {
            words.extend([option.into(), number(v)]);
        }
    }
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
    let mut ball = options(source, preset, setting);
    if let Some(at) = ball.iter().position(|w| w == "--lambda") {
        ball.splice(at..at + 4, k_r_damping(preset, setting));
    }
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

/// The words after `bouncelab run` that run `setting` (module docs).
fn options(source: Source, preset: &Preset, setting: &Setting) -> Vec<String> {
    let mut words = Vec::new();
    match source {
        Source::Name(name) => words.extend(["--preset".into(), shell_word(name)]),
        Source::Config(path) => {
            words.extend(["--config".into(), shell_word(&path.to_string_lossy())])
        }
    }
    let o = Options::of(preset, setting);
    if let Some(law) = o.law {
        words.extend(["--law".into(), law.name().into()]);
    }
    for (option, value) in [
        ("--mass", o.mass),
        ("--radius", o.radius),
        ("--k-p", o.k_p),
        ("--z-p", o.z_p),
    ] {
        if let Some(v) = value {
            words.extend([option.into(), number(v)]);
        }
    }
    if let Some((l, z)) = o.lambda_zeta {
        words.extend(["--lambda".into(), number(l), "--zeta".into(), number(z)]);
    }
    // a pressure in the unit that writes it shortest and reads back exact (`8psi`)
    if let Some(p) = o.conditions.pressure {
        words.extend(["--pressure".into(), exact::pressure_text(p)]);
    }
    if let Some(t) = o.conditions.temperature {
        words.extend(["--temperature".into(), number(t)]);
    }
    words.extend(["--v0".into(), number(o.v0)]);
    words
}

/// What the line cannot carry: the parameters the ball `run` builds from it differs in (by
/// more than the rounding of λ and ζ, 1e-12), found by building that ball with the library's
/// own steps. `None` when the line reproduces the setting.
pub fn not_carried(preset: &Preset, setting: &Setting) -> Option<String> {
    let o = Options::of(preset, setting);
    let Some(b) = o.ball(preset) else {
        return Some("`run` would refuse this setting's options".into());
    };
    let p = &setting.params;
    let off: Vec<&str> = [
        ("m", p.mass, b.mass),
        ("K_p", p.k_p, b.k_p),
        ("K_r", p.k_r, b.k_r),
        ("c", p.damping, b.damping),
        ("z_p", p.z_p, b.z_p),
        ("K_h", p.k_h, b.k_h),
        ("v0", p.v0, b.v0),
    ]
    .into_iter()
    .filter(|(_, a, b)| (a - b).abs() > 1e-12 * a.abs())
    .map(|(name, _, _)| name)
    .collect();
    (!off.is_empty()).then(|| {
        format!(
            "the line runs another {}: `run` has no option that sets it as the screen has it",
            off.join(", ")
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
