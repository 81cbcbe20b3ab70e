//! `collide`: the ball against a target of mass M moving at v_t, rigid or with a surface of its
//! own (docs/targets.md), as `bouncelab collide --format json`: the same fields, by the same
//! names.

use crate::answer::{Record, Stated};
use crate::arguments::ball::{BallChoice, ball_pyfunction};
use crate::error;
use crate::pair::PairObject;
use crate::same::Same;
use bouncelab::Ball;
use bouncelab::api::CollisionReport;
use bouncelab::api::SurfaceUsed;
use bouncelab::target::Target;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// A two-body impact, SI units; attribute names are the keys of `bouncelab collide --format
/// json` (the target's fields as `target_mass`, `target_speed`, `target_stiffness`,
/// `target_damping`).
#[pyclass(frozen, get_all, module = "bouncelab")]
pub(crate) struct Collision {
    ball: Option<String>,
    law: String,
    ball_mass: f64,
    ball_speed: f64,
    target_mass: f64,
    target_speed: f64,
    target_stiffness: f64,
    target_damping: f64,
    cor: f64,
    apparent_cor: f64,
    ball_speed_out: f64,
    target_speed_out: f64,
    max_force: f64,
    contact_time: Option<f64>,
    reduced_mass: f64,
    closing_speed: f64,
    rebound: bool,
    max_indentation: f64,
    permanent_indentation: f64,
    max_target_deflection: f64,
    method: String,
    effective_mass: Option<f64>,
    effective_radius: Option<f64>,
    /// Whether the target is rigid (the JSON's `target.rigid`: a ball partner is not, though
    /// it has no surface of its own, docs/targets.md §3).
    target_rigid: bool,
    /// Ball on ball: the partner, as the JSON's `pair` (its preset, m_eff, R_eff, its ball
    /// object and conditions); `None` otherwise.
    pair: Option<PairObject>,
    warnings: Vec<String>,
    /// The surface the target had (the JSON's `surface`, docs/surfaces.md); `None` where the
    /// ball met another ball that deforms, `surface_note` then saying so.
    surface: Option<crate::surface::SurfaceObject>,
    /// Why `surface` is `None` (the JSON's `surface_note`).
    surface_note: Option<String>,
    /// The ball as the JSON's `ball_record` object (docs/cli.md "The ball object"; `ball`
    /// was already the preset's name here, and stays it).
    ball_record: Record,
    /// The conditions the ball ran at (the JSON's `conditions`).
    conditions: Stated,
}

/// The JSON's keys in its order, after `target` (one macro for both directions, so that
/// `to_dict` and `_from_state` cannot drift apart).
macro_rules! answer_keys {
    ($m:ident) => {
        $m!(
            cor,
            apparent_cor,
            ball_speed_out,
            target_speed_out,
            max_force,
            contact_time,
            reduced_mass,
            closing_speed,
            rebound,
            max_indentation,
            permanent_indentation,
            max_target_deflection,
            method,
            effective_mass,
            effective_radius
        )
    };
}

/// `key`'s value in a state dict, named when absent (`same::state_item`).
fn get<'py, T: pyo3::conversion::FromPyObjectOwned<'py>>(
    d: &Bound<'py, PyDict>,
    key: &str,
) -> PyResult<T> {
    crate::same::state_item(d, key, "Collision state")
}

#[pymethods]
impl Collision {
    fn __repr__(&self) -> String {
        format!(
            "Collision(cor={}, apparent_cor={}, ball_speed_out={}, target_speed_out={})",
            self.cor, self.apparent_cor, self.ball_speed_out, self.target_speed_out
        )
    }

    /// The keys of `bouncelab collide --format json`, the target's under `target` (`mass`,
    /// `speed`, `stiffness`, `damping`); inf where the JSON writes null for an immovable or
    /// rigid target, as the attributes keep it.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("ball", &self.ball)?;
        d.set_item("ball_record", &self.ball_record)?;
        d.set_item("law", &self.law)?;
        d.set_item("ball_mass", self.ball_mass)?;
        d.set_item("ball_speed", self.ball_speed)?;
        let target = PyDict::new(py);
        target.set_item("mass", self.target_mass)?;
        target.set_item("speed", self.target_speed)?;
        target.set_item("stiffness", self.target_stiffness)?;
        target.set_item("damping", self.target_damping)?;
        target.set_item("rigid", self.target_rigid)?;
        d.set_item("target", target)?;
        macro_rules! put {
            ($($k:ident),*) => { $(d.set_item(stringify!($k), &self.$k)?;)* };
        }
        answer_keys!(put);
        // present only for a pair, as the JSON's
        if let Some(p) = &self.pair {
            d.set_item("pair", p)?;
        }
        d.set_item("warnings", &self.warnings)?;
        let surface = (self.surface.as_ref())
            .map(|s| crate::surface::to_dict(py, s))
            .transpose()?;
        d.set_item("surface", surface)?;
        if let Some(note) = &self.surface_note {
            d.set_item("surface_note", note)?;
        }
        d.set_item("conditions", &self.conditions)?;
        Ok(d)
    }

    /// Pickling: the class's `_from_state` and `to_dict()` (a frozen value: every protocol).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<crate::same::Reduced<'py>> {
        crate::same::reduce(slf, slf.get().to_dict(slf.py())?)
    }

    /// The collision of a state [`Collision::__reduce__`] wrote.
    #[classmethod]
    fn _from_state(
        _cls: &Bound<'_, pyo3::types::PyType>,
        state: &Bound<'_, PyDict>,
    ) -> PyResult<Collision> {
        let target: Bound<'_, PyDict> = get(state, "target")?;
        macro_rules! take {
            ($($k:ident),*) => {
                Collision {
                    ball: get(state, "ball")?,
                    law: get(state, "law")?,
                    ball_mass: get(state, "ball_mass")?,
                    ball_speed: get(state, "ball_speed")?,
                    target_mass: get(&target, "mass")?,
                    target_speed: get(&target, "speed")?,
                    target_stiffness: get(&target, "stiffness")?,
                    target_damping: get(&target, "damping")?,
                    target_rigid: get(&target, "rigid")?,
                    $($k: get(state, stringify!($k))?,)*
                    pair: state.get_item("pair")?.map(|p| p.extract()).transpose()?,
                    warnings: get(state, "warnings")?,
                    surface: match state.get_item("surface")? {
                        Some(s) if s.is_none() => None,
                        _ => Some(crate::same::state_surface(state)?.into()),
                    },
                    surface_note: state
                        .get_item("surface_note")?
                        .map(|n| n.extract())
                        .transpose()?,
                    ball_record: get(state, "ball_record")?,
                    conditions: get(state, "conditions")?,
                }
            };
        }
        Ok(answer_keys!(take))
    }

    /// Equal values: every attribute, a NaN equal to a NaN (as `Impact`'s).
    fn __eq__(&self, other: PyRef<'_, Collision>) -> bool {
        macro_rules! all_same {
            ($($k:ident),*) => {
                true $(&& self.$k.same(&other.$k))*
            };
        }
        all_same!(
            ball,
            law,
            ball_mass,
            ball_speed,
            target_mass,
            target_speed,
            target_stiffness,
            target_damping,
            target_rigid,
            warnings
        ) && answer_keys!(all_same)
            && self.pair == other.pair
            && self.surface == other.surface
            && self.surface_note == other.surface_note
            && self.ball_record == other.ball_record
            && self.conditions == other.conditions
    }

    /// A frozen value is its own copy.
    fn __copy__(slf: Py<Self>) -> Py<Self> {
        slf
    }

    fn __deepcopy__(slf: Py<Self>, _memo: &Bound<'_, PyAny>) -> Py<Self> {
        slf
    }
}

impl Collision {
    /// The answer of `r`, a collision of `ball`, as the command line reports it.
    fn of(r: CollisionReport, ball: &Ball) -> Collision {
        let (t, c) = (r.target, r.collision);
        Collision {
            ball: r.ball,
            law: r.law.name().into(),
            ball_mass: r.ball_mass,
            ball_speed: r.ball_speed,
            target_mass: t.mass,
            target_speed: t.speed,
            target_stiffness: t.stiffness,
            target_damping: t.damping,
            cor: c.cor,
            apparent_cor: c.apparent_cor,
            ball_speed_out: c.ball_speed_out,
            target_speed_out: c.target_speed_out,
            max_force: c.max_force,
            contact_time: c.contact_time,
            reduced_mass: c.reduced_mass,
            closing_speed: c.closing_speed,
            rebound: c.rebound,
            max_indentation: c.max_indentation,
            permanent_indentation: c.permanent_indentation,
            max_target_deflection: c.max_target_deflection,
            method: c.method.name().into(),
            effective_mass: r.effective_mass,
            effective_radius: r.effective_radius,
            target_rigid: t.rigid,
            pair: r.pair.map(PairObject),
            warnings: r.warnings,
            surface: Some(SurfaceUsed::rigid_plate().into()),
            surface_note: None,
            ball_record: Record(r.ball_record),
            conditions: Stated::of(ball),
        }
    }
}

ball_pyfunction! {
    /// A preset ball against a target, as `bouncelab collide --preset NAME [--v0 V] --target-mass M
    /// [--target-speed V_T] [--target-stiffness K_S] [--target-damping C_S]`, or against another
    /// preset ball with `target_preset` (instead of `target_mass`; both balls deform, their chains
    /// in series, through the same `Ball::collide_ball`: docs/targets.md §8). `target_mass = inf`
    /// is the wall. `surface=` (a name or a dict of its numbers, python/src/surface.rs) is the
    /// target's surface, as `--surface NAME --surface-stiffness K_S …`: its mass the target's
    /// unless `target_mass` is given, its K_s, c_s unless `target_stiffness` is.
    // help()'s signature, which pyo3 writes "..." for f64::INFINITY in (shown "Ellipsis"):
    // 1e999 is the literal Python reads as inf, shown "inf" (test_the_stub_and_help_give_…)
    #[pyo3(text_signature = "(preset='superball', v0=None, target_mass=None, target_speed=0.0, target_stiffness=1e999, target_damping=0.0, target_preset=None, law=None, params=None, *, surface=None, mass=None, radius=None, k_p=None, damping=None, k_r=None, z_p=None, pressure=None, temperature=None, inflated_at=None, after=None, half_life=None)")]
    signature = (preset="superball", v0=None, target_mass=None, target_speed=0.0, target_stiffness=f64::INFINITY, target_damping=0.0, target_preset=None, law=None, params=None, *, surface=None,);
    fn collide<'py>(
        _py,
        preset: &str,
        v0: Option<f64>,
        target_mass: Option<f64>,
        target_speed: f64,
        target_stiffness: f64,
        target_damping: f64,
        target_preset: Option<&str>,
        law: Option<&str>,
        params: Option<&str>,
        surface: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Collision>;
    ball choice = (preset, params, law);
    {
        let target = (target_mass, target_speed, target_preset);
        collide_with(&choice, v0, target, (target_stiffness, target_damping), surface)
    }
}

/// [`collide`]'s body: the ball of `choice` at `v0` against the target.
fn collide_with(
    choice: &BallChoice<'_>,
    v0: Option<f64>,
    (target_mass, target_speed, target_preset): (Option<f64>, f64, Option<&str>),
    (target_stiffness, target_damping): (f64, f64),
    surface: Option<&Bound<'_, PyAny>>,
) -> PyResult<Collision> {
    if target_damping != 0.0 && !target_damping.is_nan() && target_stiffness == f64::INFINITY {
        // refused as the command line refuses --target-damping without --target-stiffness:
        // a dashpot beside a rigid surface has no effect (docs/targets.md)
        return Err(crate::value_error(format!(
            "invalid target_damping: {} (it needs target_stiffness: a dashpot beside a rigid \
             surface has no effect)",
            bouncelab::text::number(target_damping)
        )));
    }
    let ball = choice.resolve(v0)?;
    let given = surface.is_some_and(|s| !s.is_none());
    let used = crate::surface::resolve_normal(surface)?;
    // the surface asked for by name (not the one its numbers renamed: docs/surfaces.md §1)
    let named = used.started_from().0 != bouncelab::target::surface::DEFAULT
        || used.mechanics.mass.is_finite();
    if target_preset.is_some() && given && named {
        return Err(crate::value_error(
            "target_preset is the target: a named surface and its mass do not apply (give \
             surface={'stiffness': K_S, 'damping': C_S} for its surface)"
                .into(),
        ));
    }
    // the defaults (inf, 0) read as not given: the surface's own then
    let stiffness_given = target_stiffness != f64::INFINITY || target_damping != 0.0;
    let used = used.with_target(
        target_mass,
        stiffness_given.then_some(target_stiffness),
        (target_damping != 0.0).then_some(target_damping),
    );
    let pair = (used.mechanics.stiffness, used.mechanics.damping);
    let report = match (target_mass, target_preset) {
        (None, Some(name)) => {
            let other = crate::arguments::ball::preset_as_it_is(name)?;
            ball.collide_ball(&other, target_speed, pair)
        }
        (_, None) if target_mass.is_some() || given => ball.collide(&Target {
            mass: used.mechanics.mass,
            speed: target_speed,
            stiffness: pair.0,
            damping: pair.1,
        }),
        _ => {
            return Err(crate::value_error(
                "give one of target_mass, target_preset and surface".into(),
            ));
        }
    };
    let mut c = Collision::of(report.map_err(error)?, &ball);
    // a target's surface (a ball partner has none of its own), as the command line's
    if target_preset.is_none() {
        c.warnings.extend(used.warnings());
    }
    // a ball partner that deforms is no surface: None and the note, as the command line's
    // `surface: null` (src/cli/collide.rs); behind a given surface, that surface
    match c
        .pair
        .as_ref()
        .filter(|_| used.mechanics.stiffness.is_infinite())
    {
        Some(p) => (c.surface, c.surface_note) = (None, Some(p.0.no_surface_note())),
        None => c.surface = Some(used.into()),
    }
    Ok(c)
}
