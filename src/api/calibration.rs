//! Where a ball's parameters hold, and which ball an answer ran: the one helper every command
//! (and the explorer, and Python) calls for the "outside calibration: …" warning
//! ([`Ball::calibration_warning`], docs/presets.md "The calibration record") and for the JSON
//! `ball` object ([`Ball::record_json`], docs/cli.md "The ball object").

use super::Ball;
use crate::model::params::ImpactParams;
use crate::text::short;
use serde::Serialize;

/// The names of the parameters of `p` that differ from `own`'s (m, K_p, c, K_r, z_p, K_h; the
/// speed is no parameter of the ball), each compared to 1e-12: what an override changed.
pub fn changed_params(own: &ImpactParams, p: &ImpactParams) -> Vec<String> {
    let same = |a: f64, b: f64| a == b || (a - b).abs() <= 1e-12 * a.abs().max(b.abs());
    [
        ("mass", own.mass, p.mass),
        ("k_p", own.k_p, p.k_p),
        ("c", own.damping, p.damping),
        ("k_r", own.k_r, p.k_r),
        ("z_p", own.z_p, p.z_p),
        ("k_h", own.k_h, p.k_h),
    ]
    .into_iter()
    .filter(|(_, a, b)| !same(*a, *b))
    .map(|(n, ..)| n.to_string())
    .collect()
}

/// The ball an answer ran, as every JSON answer names it (its `ball` object): the preset (or
/// `null`), where it came from, its law and parameters (SI), its κ, and the list of what the
/// command line changed from the preset (`overrides`, empty when nothing).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BallRecord {
    /// The preset's name; `null` for the normalized ball and given parameters.
    pub name: Option<String>,
    /// `"embedded"`, a preset file's path, `"normalized"` or `"parameters"`.
    pub origin: String,
    /// The contact law's name.
    pub law: &'static str,
    /// m, kg.
    pub mass: f64,
    /// R, m (`null` for a ball that is no preset).
    pub radius: Option<f64>,
    /// K_p, N/m.
    pub k_p: f64,
    /// c, kg/s (`null` when infinite).
    pub c: f64,
    /// K_r, N/m.
    pub k_r: f64,
    /// z_p, m (`null` when infinite).
    pub z_p: f64,
    /// K_h, N/m^{3/2}.
    pub k_h: f64,
    /// κ = I/(m R²): the preset's, or a solid ball's 0.4.
    pub inertia_factor: f64,
    /// What the command line changed from the preset: `mass`, `radius`, `k_p`, `c`, `k_r`,
    /// `z_p`, `lambda`, `zeta` (the `parameters` and `law` keys say the set and law).
    pub overrides: Vec<String>,
    /// With overrides: the parameters kept from the preset, as the text header's "kept from
    /// the preset: …" ([`Ball::kept`]); absent without an override (nothing was changed).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub kept: Vec<String>,
}

impl Ball {
    /// The JSON `ball` object of this ball ([`BallRecord`]).
    pub fn record_json(&self) -> BallRecord {
        let p = &self.params;
        BallRecord {
            name: self.name.clone(),
            origin: self.origin.clone(),
            law: self.law.name(),
            mass: p.mass,
            radius: Some(self.radius()).filter(|r| r.is_finite()),
            k_p: p.k_p,
            c: p.damping,
            k_r: p.k_r,
            z_p: p.z_p,
            k_h: p.k_h,
            inertia_factor: self.inertia_factor(),
            overrides: self.overrides.clone(),
            kept: self.kept().into_iter().map(String::from).collect(),
        }
    }

    /// Why a comparison with the preset's measurement is withheld: the overrides changed the
    /// ball, so the measurement is not this ball's (`None`: nothing changed it).
    pub fn measurement_withheld(&self) -> Option<String> {
        if self.overrides.is_empty() {
            return self
                .conditions_moved()
                .map(|m| format!("the measurement is at the record's conditions: {m}"));
        }
        (!self.overrides.is_empty()).then(|| {
            format!(
                "the measurement is the preset's ball's, and {} changed this ball",
                self.overrides.join(", ")
            )
        })
    }

    /// The text header's line of overrides: what the command line changed and what it kept
    /// from the preset ("overrides: k_p; kept from the preset: mass, radius, c, k_r, z_p");
    /// `None` without an override or for a ball that is no preset.
    pub fn overrides_line(&self) -> Option<String> {
        let mut line = self.overrides_words()?;
        let kept = self.kept();
        if !kept.is_empty() {
            line.push_str(&format!("; kept from the preset: {}", kept.join(", ")));
        }
        Some(line)
    }

    /// "overrides: k_p": what the command line changed, the first words of
    /// [`Ball::overrides_line`] (a figure's subtitle says no more, [`Ball::moved_notes`]);
    /// `None` without an override or for a ball that is no preset.
    pub fn overrides_words(&self) -> Option<String> {
        if self.overrides.is_empty() || self.name.is_none() {
            return None;
        }
        Some(format!("overrides: {}", self.overrides.join(", ")))
    }

    /// The preset's parameters an override left as they were (mass, radius, k_p, c, k_r,
    /// z_p, in that order); empty without an override or for a ball that is no preset.
    pub fn kept(&self) -> Vec<&'static str> {
        if self.overrides.is_empty() || self.name.is_none() {
            return Vec::new();
        }
        // λ moves K_r and ζ moves c (Eq. 24): those are changed, not kept
        let moved = |n: &str| match n {
            "k_r" => "lambda",
            "c" => "zeta",
            _ => "",
        };
        ["mass", "radius", "k_p", "c", "k_r", "z_p"]
            .into_iter()
            .filter(|n| !self.overrides.iter().any(|o| o == n || o == moved(n)))
            .collect()
    }

    /// "outside calibration: …" when the preset's measured COR, taken at its measured speed,
    /// is used as the target of a calibration at this ball's v0, another speed (`peers --v0
    /// V`): both speeds named. `None` at the measured speed (to
    /// [`crate::preset::SPEED_SLACK`]) or without a measured COR.
    pub fn measured_cor_warning(&self) -> Option<String> {
        let m = self.measured.as_ref()?;
        let e = m.cor?;
        let v = self.params.v0;
        let same = (v - m.v0).abs() <= crate::preset::SPEED_SLACK * m.v0;
        (!same).then(|| {
            format!(
                "outside calibration: the target COR {} was measured at {} m/s, and this \
                 calibration is at impact speed {} m/s (give --cor E for the COR at that speed)",
                short(e, 4),
                short(m.v0, 4),
                short(v, 4)
            )
        })
    }

    /// "outside calibration: …" when an impact at `v` (m/s) lies outside the speeds the ball's
    /// `[calibration]` record holds over, or when the command line changed the recorded ball;
    /// it names the range and the value. `None` inside the range, and for a ball with no
    /// record (the normalized ball, given parameters, a preset without one).
    ///
    /// ```
    /// let b = bouncelab::Ball::from_preset("baseball")?;
    /// assert_eq!(b.calibration_warning(1.25), None);
    /// let w = b.calibration_warning(25.9).unwrap();
    /// assert!(w.starts_with("outside calibration: impact speed 25.9 m/s, the ball was fitted at 1.25 m/s"));
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn calibration_warning(&self, v: f64) -> Option<String> {
        self.speeds_warning(v, v)
    }

    /// [`Ball::calibration_warning`] for impacts from `lo` to `hi` m/s at once (a sweep's, a
    /// map's grid, a lot's): one warning naming the range of the answer and the record's.
    pub fn speeds_warning(&self, lo: f64, hi: f64) -> Option<String> {
        let c = self.calibration.as_ref()?;
        let (at, fitted) = (speeds_words(lo, hi), fitted_words(c));
        if !self.overrides.is_empty() {
            return Some(format!(
                "outside calibration: {} changed the ball, whose record ({fitted}; {}) no \
                 longer applies; {at}",
                self.overrides.join(", "),
                c.sources()
            ));
        }
        if let Some(other) = &c.other_model {
            return Some(format!(
                "outside calibration: the record ({fitted}; {}) is of the preset's own \
                 parameter set and law, and this answer runs {other}; {at}",
                c.sources()
            ));
        }
        let inside = c.holds_at(lo) && c.holds_at(hi);
        if let Some(moved) = self.conditions_moved() {
            // the speed said as inside or outside: "…carries it there; impact speed 6.111
            // m/s, the ball was fitted at 6.111 m/s only" read as if the speed were out
            let speed = if inside {
                let record = if c.speed_min == c.speed_max {
                    format!("{} m/s", short(c.speed_min, 4))
                } else {
                    c.range_text()
                };
                format!("at {at}, inside the record's {record}")
            } else {
                let verb = if lo == hi { "is" } else { "reach" };
                format!(
                    "{at} {verb} outside the record too: {fitted}, and the answer extrapolates \
                     the model there"
                )
            };
            return Some(format!(
                "outside calibration: {moved} ({}); the conditions' model (docs/model.md §10) \
                 carries it there{}; {speed}",
                c.sources(),
                self.conditions_caveat()
            ));
        }
        if inside {
            return None;
        }
        Some(format!(
            "outside calibration: {at}, {fitted} ({}): the answer extrapolates the model there",
            c.sources()
        ))
    }

    /// The warnings of a map over (λ, ζ) around this ball at its v0: the map's cells move its
    /// K_r and c as `run --lambda --zeta` does, so their warning is `run`'s for this ball with
    /// `lambda` and `zeta` changed, saying that only the ball's own point is its record's;
    /// before it, when nothing else changed the ball, the speed's warning
    /// ([`Ball::calibration_warning`]), which an override's would repeat. Empty without a record.
    pub fn map_calibration_warnings(&self) -> Vec<String> {
        let v = self.params.v0;
        let mut moved = self.clone();
        moved
            .overrides
            .extend(["lambda".to_string(), "zeta".to_string()]);
        let n = self.params.normalized();
        let cells = moved.calibration_warning(v).map(|w| {
            format!(
                "{w}: the map's cells are this ball at other λ and ζ; only its own point \
                 (λ = {}, ζ = {}) is calibrated",
                short(n.lambda, 4),
                short(n.zeta, 4)
            )
        });
        let speed = self
            .overrides
            .is_empty()
            .then(|| self.calibration_warning(v))
            .flatten();
        speed.into_iter().chain(cells).collect()
    }

    /// "outside calibration: …" for a test of `standard` on this ball: its impact speed (a
    /// drop's first impact, through standard air, from the release height) against the
    /// ball's record; `None` inside it, without a record, or when the drop has no impact.
    pub fn standard_calibration_warning(
        &self,
        standard: &crate::drop::standards::Standard,
    ) -> Option<String> {
        let v = match standard.test {
            crate::drop::standards::Test::Cor { speed } => speed,
            crate::drop::standards::Test::Drop { height, .. } => {
                let run = self.drop_test(&crate::drop::DropSetup::new(height)).ok()?;
                run.bounces.first()?.v_in
            }
        };
        self.calibration_warning(v)
    }

    /// "outside calibration: …" for the later bounces of a drop whose impact `speeds` (first
    /// to last) leave the ball's record: a drop is judged by its first impact (that one's
    /// warning is [`Ball::calibration_warning`]'s), but its table shows every bounce, and the
    /// tennis ball fitted at 6.906 m/s only showed nine more down to 0.63 m/s without a word
    /// (tests/cli/cli_drop.rs, `later_bounces_outside_the_record_are_named`). Names them by
    /// their numbers and speeds. `None` when they all lie inside, without a record, and when
    /// an override, another law or the conditions already took the record away (that warning
    /// says so for the whole answer).
    pub fn later_bounces_warning(&self, speeds: &[f64]) -> Option<String> {
        let c = self.calibration.as_ref()?;
        if !self.overrides.is_empty()
            || c.other_model.is_some()
            || self.conditions_moved().is_some()
        {
            return None;
        }
        // bounces are numbered from 1; the first is the judged one
        let out: Vec<(usize, f64)> = (speeds.iter().enumerate().skip(1))
            .filter(|(_, v)| !c.holds_at(**v))
            .map(|(i, v)| (i + 1, *v))
            .collect();
        let (lo, hi) = out
            .iter()
            .fold((f64::INFINITY, 0.0_f64), |(lo, hi), &(_, v)| {
                (lo.min(v), hi.max(v))
            });
        let which = bounce_numbers(&out.iter().map(|b| b.0).collect::<Vec<_>>())?;
        let at = if out.len() == 1 {
            format!("impact speed {} m/s", short(lo, 4))
        } else {
            format!("impact speeds {}–{} m/s", short(lo, 4), short(hi, 4))
        };
        let (lie, rows) = if out.len() == 1 {
            ("lies", "that row extrapolates")
        } else {
            ("lie", "those rows extrapolate")
        };
        Some(format!(
            "outside calibration: {which} of the drop ({at}) {lie} outside the ball's record, \
             fitted at {} ({}): {rows} the model",
            c.range_text(),
            c.sources()
        ))
    }
}

/// "bounce 4", "bounces 2–10", "bounces 2–3 and 8–10": runs of consecutive numbers
/// (`numbers` ascending); `None` when empty.
fn bounce_numbers(numbers: &[usize]) -> Option<String> {
    let (&first, _) = numbers.split_first()?;
    let mut runs: Vec<(usize, usize)> = vec![(first, first)];
    for &n in &numbers[1..] {
        match runs.last_mut() {
            Some(run) if run.1 + 1 == n => run.1 = n,
            _ => runs.push((n, n)),
        }
    }
    let text: Vec<String> = runs
        .iter()
        .map(|&(a, b)| {
            if a == b {
                a.to_string()
            } else {
                format!("{a}–{b}")
            }
        })
        .collect();
    let noun = if numbers.len() == 1 {
        "bounce"
    } else {
        "bounces"
    };
    Some(format!("{noun} {}", text.join(" and ")))
}

/// "impact speed 40 m/s", "impact speeds 0.69–20.7 m/s": an answer's speeds as the
/// calibration warning names them (and a figure's subtitle, [`Ball::moved_notes`]).
pub(super) fn speeds_words(lo: f64, hi: f64) -> String {
    if lo == hi {
        format!("impact speed {} m/s", short(lo, 4))
    } else {
        format!("impact speeds {}–{} m/s", short(lo, 4), short(hi, 4))
    }
}

/// "the ball was fitted at 1.47 m/s only", "the ball was fitted over 1.2–6.9 m/s": the
/// record's speeds as the calibration warning names them.
pub(super) fn fitted_words(c: &crate::preset::Calibration) -> String {
    let range = c.range_text();
    if c.speed_min == c.speed_max {
        format!("the ball was fitted at {range}")
    } else {
        format!("the ball was fitted over {range}")
    }
}

#[cfg(test)]
mod bounce_number_tests {
    use super::bounce_numbers;

    #[test]
    fn runs_of_bounces_are_named_compactly() {
        assert_eq!(bounce_numbers(&[]), None);
        assert_eq!(bounce_numbers(&[4]).unwrap(), "bounce 4");
        assert_eq!(bounce_numbers(&[2, 3, 4, 5]).unwrap(), "bounces 2–5");
        assert_eq!(
            bounce_numbers(&[2, 3, 8, 9, 10]).unwrap(),
            "bounces 2–3 and 8–10"
        );
    }
}
