//! The options that take `run` from a preset to the explorer's setting (src/tui/command.rs's
//! module docs), each number the shortest that gives `run` the screen's ball to the bit, and
//! what the line cannot carry: built and checked with the library's own steps.

use super::{Source, given, shell_word};
use crate::api::{self, ConditionsSpec, Overrides};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::preset::Preset;
use crate::text::number;
use crate::tui::exact;
use crate::tui::param::Param;
use crate::tui::physical::conditions::conditioned;
use crate::tui::setting::Setting;

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

/// The words after `bouncelab run` that run `setting` (module docs).
pub(super) fn options(source: Source, preset: &Preset, setting: &Setting) -> Vec<String> {
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
    words.extend(given(&[
        ("--mass", o.mass),
        ("--radius", o.radius),
        ("--k-p", o.k_p),
        ("--z-p", o.z_p),
    ]));
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
/// more than the rounding of λ and ζ, 1e-12: [`params_off`]), found by building that ball
/// with the library's own steps. `None` when the line reproduces the setting.
pub fn not_carried(preset: &Preset, setting: &Setting) -> Option<String> {
    let o = Options::of(preset, setting);
    let Some(b) = o.ball(preset) else {
        return Some("`run` would refuse this setting's options".into());
    };
    let off = params_off(&setting.params, &b);
    (!off.is_empty()).then(|| {
        format!(
            "the line runs another {}: `run` has no option that sets it as the screen has it",
            off.join(", ")
        )
    })
}

/// The parameters `b` gives another value than `p` (beyond 1e-12 of `p`'s), by the symbols
/// the screen shows them with, in the form's order: m, K_p, K_r, c, z_p, K_h, v0. Empty when
/// `b` is the screen's ball (equal infinities are the same value).
pub fn params_off(p: &ImpactParams, b: &ImpactParams) -> Vec<&'static str> {
    [
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
    .collect()
}
