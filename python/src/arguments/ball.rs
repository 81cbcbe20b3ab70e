//! The ball a call runs, resolved in one place as the command line resolves its `BallArgs`
//! (src/cli/ball.rs): the preset and its `params` and `law`, the overrides `mass` … `z_p`,
//! then the conditions `pressure`, `temperature`, `inflated_at`, `after`, `half_life`
//! (`Ball::at_conditions`, docs/model.md §10). Every function that runs a preset ball takes
//! those keyword arguments through [`ball_pyfunction!`], so no function's names, defaults or
//! order of resolution drift from another's.

use crate::{catalog_cache, entry, error, law, load_catalog, of_argument, source, value_error};
use bouncelab::Ball;
use bouncelab::api::{ConditionsSpec, Overrides};
use pyo3::prelude::*;
use std::sync::Arc;

/// The ball a call asks for: the command line's `BallArgs` from the keyword arguments of the
/// same names.
pub(crate) struct BallChoice<'a> {
    pub(crate) preset: &'a str,
    pub(crate) params: Option<&'a str>,
    pub(crate) law: Option<&'a str>,
    /// `--mass`, `--radius`, `--k-p`, `--damping`, `--k-r`, `--z-p` (SI; `None` keeps the
    /// preset's).
    pub(crate) set: Overrides,
    /// `--pressure`, `--temperature`, `--inflated-at`, `--after`, `--half-life`.
    pub(crate) conditions: ConditionsSpec,
}

impl BallChoice<'_> {
    /// The ball at `v0` (`None`: the preset's speed), as `BallArgs::resolve`: the preset with
    /// its set and law, the overrides over it, then the conditions. The preset's own ball is
    /// shared, built once while the catalog holds (catalog_cache.rs), when nothing changes it.
    pub(crate) fn resolve(&self, v0: Option<f64>) -> PyResult<Arc<Ball>> {
        let ball = match (v0, self.set.any()) {
            (None, false) => shared_preset_ball(self.preset, self.params, self.law)?,
            _ => Arc::new(overridden_ball(
                self.preset,
                self.params,
                self.law,
                v0,
                &self.set,
            )?),
        };
        at_conditions(ball, &self.conditions)
    }

    /// [`BallChoice::resolve`]'s ball, owned.
    pub(crate) fn ball(&self, v0: Option<f64>) -> PyResult<Ball> {
        self.resolve(v0).map(Arc::unwrap_or_clone)
    }

    /// The command line's `check_overrides`: one parameter set twice is refused (`--k-r` with
    /// `--lambda`, `--damping` with `--zeta`).
    pub(crate) fn check_lambda_zeta(&self, lambda: Option<f64>, zeta: Option<f64>) -> PyResult<()> {
        if self.set.k_r.is_some() && lambda.is_some() {
            return Err(value_error(
                "k_r and lambda_ both set K_r: give one of them".into(),
            ));
        }
        if self.set.damping.is_some() && zeta.is_some() {
            return Err(value_error(
                "damping and zeta both set c: give one of them".into(),
            ));
        }
        Ok(())
    }
}

/// A `#[pyfunction]` that runs a preset ball: its own signature (ending in `*,` or in
/// keyword-only arguments and a comma), then the ball's keyword-only arguments every such
/// function takes — `mass`, `radius`, `k_p`, `damping`, `k_r`, `z_p`, `pressure`,
/// `temperature`, `inflated_at`, `after`, `half_life` — read into the [`BallChoice`] the body
/// starts from (`ball NAME = (preset, params, law)` names it and the function's own
/// arguments it takes the preset from). `pressure` is Pa or a string with its unit
/// (`"0.8bar"`); `after` and `half_life` seconds or a string with a unit (`"72h"`).
/// The stub (`bouncelab/__init__.pyi`) types the same list once, as `BallArguments`.
macro_rules! ball_pyfunction {
    (
        $(#[$attr:meta])*
        signature = ($($sig:tt)*);
        fn $name:ident<$lt:lifetime>($py:ident $(, $arg:ident: $ty:ty)* $(,)?) -> $ret:ty;
        ball $choice:ident = ($preset:expr, $params:expr, $law:expr);
        $body:block
    ) => {
        #[pyfunction]
        $(#[$attr])*
        #[pyo3(signature = ($($sig)* mass=None, radius=None, k_p=None, damping=None, k_r=None, z_p=None, pressure=None, temperature=None, inflated_at=None, after=None, half_life=None))]
        #[allow(clippy::too_many_arguments)]
        pub(crate) fn $name<$lt>(
            $py: Python<$lt>,
            $($arg: $ty,)*
            mass: Option<f64>,
            radius: Option<f64>,
            k_p: Option<f64>,
            damping: Option<f64>,
            k_r: Option<f64>,
            z_p: Option<f64>,
            pressure: Option<Bound<$lt, PyAny>>,
            temperature: Option<f64>,
            inflated_at: Option<f64>,
            after: Option<Bound<$lt, PyAny>>,
            half_life: Option<Bound<$lt, PyAny>>,
        ) -> $ret {
            let set = bouncelab::api::Overrides { mass, radius, k_p, damping, k_r, z_p };
            let given = [&pressure, &after, &half_life];
            let $choice = $crate::arguments::ball::BallChoice {
                preset: $preset,
                params: $params,
                law: $law,
                set,
                conditions: $crate::arguments::ball::conditions(given, temperature, inflated_at)?,
            };
            $body
        }
    };
}
pub(crate) use ball_pyfunction;

/// A preset ball with the command line's `--params`, `--law`, `--v0` and overrides set over the preset's, each checked and named as
/// the command line checks them (`Ball::from_entry_with`).
fn overridden_ball(
    preset: &str,
    params: Option<&str>,
    law_name: Option<&str>,
    v0: Option<f64>,
    set: &Overrides,
) -> PyResult<Ball> {
    let cat = load_catalog(Some(preset))?;
    let entry = entry(&cat, preset)?;
    let params = params.map(source).transpose()?;
    let law_ = law_name.map(law).transpose()?;
    Ball::from_entry_with(entry, params, law_, v0, set).map_err(error)
}

/// The preset `name`'s own ball, nothing changed (`collide`'s `target_preset`): the shared
/// one of [`shared_preset_ball`].
pub(crate) fn preset_as_it_is(name: &str) -> PyResult<Arc<Ball>> {
    shared_preset_ball(name, None, None)
}

/// A preset ball with the command line's `--params` and `--law` applied, at the preset's
/// speed: built once while the catalog holds (catalog_cache.rs), the same ball, checked the
/// same way, as [`overridden_ball`] builds.
fn shared_preset_ball(
    preset: &str,
    params: Option<&str>,
    law_name: Option<&str>,
) -> PyResult<Arc<Ball>> {
    let choose = || {
        let params = params.map(source).transpose()?;
        Ok((params, law_name.map(law).transpose()?))
    };
    catalog_cache::preset_ball(preset, choose, error)
}

/// `pressure` (Pa, or a string with its unit: `"0.8bar"`, `"8psi"`, `"55kPa"`), `after` and
/// `half_life` (s, or a string with its unit: `"72h"`, `"30d"`), `temperature` and
/// `inflated_at` (°C): the command line's `--pressure`, `--after`, `--half-life`,
/// `--temperature`, `--inflated-at`, each read by the command line's own reader.
pub(crate) fn conditions(
    [pressure, after, half_life]: [&Option<Bound<'_, PyAny>>; 3],
    temperature: Option<f64>,
    inflated_at: Option<f64>,
) -> PyResult<ConditionsSpec> {
    // `field` the command line's name, which its reader's messages give (`half-life`)
    let read = |value: &Option<Bound<'_, PyAny>>,
                field: &str,
                unit: fn(&str, &str) -> Result<f64, String>| {
        value
            .as_ref()
            .map(|v| match v.extract::<String>() {
                Ok(text) => unit(field, &text).map_err(value_error),
                Err(_) => of_argument(v.py(), &field.replace('-', "_"), v.extract::<f64>()),
            })
            .transpose()
    };
    Ok(ConditionsSpec {
        pressure: read(pressure, "pressure", bouncelab::conditions::pressure::parse)?,
        temperature,
        inflated_at,
        after: read(after, "after", bouncelab::conditions::duration::parse)?,
        half_life: read(
            half_life,
            "half-life",
            bouncelab::conditions::duration::parse,
        )?,
    })
}

/// `ball` at the conditions asked (itself when none is).
fn at_conditions(ball: Arc<Ball>, spec: &ConditionsSpec) -> PyResult<Arc<Ball>> {
    if spec.is_empty() {
        return Ok(ball);
    }
    let moved = Arc::unwrap_or_clone(ball).at_conditions(spec);
    Ok(Arc::new(moved.map_err(error)?))
}
