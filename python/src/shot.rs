//! `bouncelab.shot(...)`: a shot (docs/flight.md) as arrays; `bouncelab.shots(...)`: many
//! shots over numpy arrays of launch conditions, broadcast together, in parallel.

use crate::arguments::ball::ball_pyfunction;
use crate::error;
use bouncelab::api::{Net, SHOT_QUANTITIES, ShotReport, ShotSpec, TENNIS_NET_HEIGHT};
use bouncelab::flight::{Ends, Launch};
use numpy::PyArray1;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;

/// What every shot of a call shares: its spec, the launch and the samples each shot's own
/// (`ShotSpec { launch, samples, ..common }`).
fn with(common: &ShotSpec, launch: Launch, samples: usize) -> ShotSpec {
    ShotSpec {
        launch,
        samples,
        ..*common
    }
}

fn array<'py>(py: Python<'py>, v: Vec<f64>) -> Bound<'py, PyArray1<f64>> {
    PyArray1::from_vec(py, v)
}

/// The report as a dict: `bounces` and `trajectory` dicts of arrays, `end` a dict, `source`.
fn report<'py>(py: Python<'py>, r: &ShotReport) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let b = PyDict::new(py);
    type Field = fn(&bouncelab::api::ShotBounce) -> f64;
    let fields: [(&str, Field); 14] = [
        ("t", |b| b.t),
        ("x", |b| b.x),
        ("v_in", |b| b.v_in),
        ("angle_in", |b| b.angle_in),
        ("spin_in", |b| b.spin_in),
        ("vx_in", |b| b.vx_in),
        ("vy_in", |b| b.vy_in),
        ("v_out", |b| b.v_out),
        ("angle_out", |b| b.angle_out),
        ("spin_out", |b| b.spin_out),
        ("vx_out", |b| b.vx_out),
        ("vy_out", |b| b.vy_out),
        ("cor_normal", |b| b.cor_normal),
        ("contact_time", |b| b.contact_time),
    ];
    for (name, f) in fields {
        b.set_item(name, array(py, r.bounces.iter().map(f).collect()))?;
    }
    let slid: Vec<bool> = r.bounces.iter().map(|b| b.slid_throughout).collect();
    b.set_item("slid_throughout", PyArray1::from_vec(py, slid))?;
    let warnings: Vec<Vec<String>> = r.bounces.iter().map(|b| b.warnings.clone()).collect();
    b.set_item("warnings", warnings)?;
    d.set_item("bounces", b)?;
    let t = PyDict::new(py);
    type Of = fn(&bouncelab::flight::State) -> f64;
    let cols: [(&str, Of); 6] = [
        ("t", |s| s.t),
        ("x", |s| s.x),
        ("y", |s| s.y),
        ("vx", |s| s.vx),
        ("vy", |s| s.vy),
        ("spin", |s| s.spin),
    ];
    for (name, f) in cols {
        t.set_item(name, array(py, r.trajectory.iter().map(f).collect()))?;
    }
    d.set_item("trajectory", t)?;
    // the JSON's `end` (reason, t, x, y, vx, vy, spin, speed) and `net` objects (None where
    // they have null)
    d.set_item("end", crate::answer::dict(py, &r.end)?)?;
    d.set_item("source", r.aero.source)?;
    if let Some(n) = &r.net {
        d.set_item("net", crate::answer::dict(py, n)?)?;
    }
    Ok(d)
}

/// `net=`: the distance (the tennis net's height at the centre, 0.914 m), or (distance,
/// height), as the command line's `--net DISTANCE[,HEIGHT]`; the library refuses a value
/// that is not positive (`invalid net: …`).
fn net_of(net: Option<&Bound<'_, PyAny>>) -> PyResult<Option<Net>> {
    let Some(net) = net else {
        return Ok(None);
    };
    if let Ok(x) = net.extract::<f64>() {
        return Ok(Some(Net {
            x,
            height: TENNIS_NET_HEIGHT,
        }));
    }
    let (x, height): (f64, f64) = net.extract().map_err(|_| {
        crate::value_error("invalid net: a distance (m) or a (distance, height) pair".into())
    })?;
    Ok(Some(Net { x, height }))
}

/// A `#[pyfunction]` of a shot: the ball's arguments (arguments/ball.rs), `friction` and the
/// flight's keyword-only arguments `shot` and `shots` share (`bounces` … `tangential_damping`,
/// the command line's `shot` options), then the function's own, then `law` and `params`; the
/// body starts from the resolved ball `$ball` and the spec every shot shares, `$common`. One list,
/// so that the two cannot drift apart in a name or a default.
macro_rules! flight_pyfunction {
    (
        $(#[$attr:meta])*
        fn $name:ident<$lt:lifetime>($py:ident, $ball:ident, $common:ident, $surface:ident;
            $($arg:ident: $ty:ty $(= $default:tt)?),* $(,)?) -> $ret:ty $body:block
    ) => {
        ball_pyfunction! {
            $(#[$attr])*
            signature = (preset="tennis", *, friction=None, bounces=1, distance=None, time=None, air_density=1.204, drag_coefficient=None, lift_coefficient=None, spin_decay=None, tangential_stiffness=None, inertia_factor=None, tangential_damping=None, surface=None, net=None, $($arg $(= $default)?,)* law=None, params=None,);
            fn $name<$lt>(
                $py,
                preset: &str,
                friction: Option<f64>,
                bounces: usize,
                distance: Option<f64>,
                time: Option<f64>,
                air_density: f64,
                drag_coefficient: Option<f64>,
                lift_coefficient: Option<f64>,
                spin_decay: Option<f64>,
                tangential_stiffness: Option<f64>,
                inertia_factor: Option<f64>,
                tangential_damping: Option<f64>,
                surface: Option<&Bound<$lt, PyAny>>,
                net: Option<&Bound<$lt, PyAny>>,
                $($arg: $ty,)*
                law: Option<&str>,
                params: Option<&str>,
            ) -> $ret;
            ball choice = (preset, params, law);
            {
                let $ball = choice.resolve(None)?;
                // `surface=` with μ, K_t, c_t over its own, as `oblique`'s (the command
                // line's `shot --surface`)
                let tangential = [friction, tangential_stiffness, tangential_damping];
                let ($surface, friction) =
                    crate::oblique::tangential_surface(surface, tangential)?;
                let $common = ShotSpec {
                    launch: Launch { height: 0.0, speed: 0.0, elevation_deg: 0.0, spin: 0.0 },
                    ends: Ends { bounces, distance, time },
                    friction,
                    tangential_stiffness: $surface.mechanics.tangential_stiffness,
                    inertia_factor,
                    tangential_damping: $surface.mechanics.tangential_damping,
                    air_density,
                    drag_coefficient,
                    lift_coefficient,
                    spin_decay,
                    samples: 0,
                    surface: $surface.mechanics.target(),
                    net: net_of(net)?,
                };
                $body
            }
        }
    };
}

flight_pyfunction! {
    /// One shot, as `bouncelab shot --format json --samples N`: a dict with `bounces` (a dict of
    /// arrays, one element per bounce), `end` (a dict), `trajectory` (a dict of arrays t, x, y,
    /// vx, vy, spin; `samples` of them, 0 for none), `source` (the aerodynamic models) and
    /// `surface` (the JSON's `surface` object), and with `net=` (a distance, or (distance,
    /// height)) `net`, the JSON's `net` object. `after_bounce=D`: `shot --after-bounce D`.
    fn shot<'py>(py, ball, common, surface;
        height: f64,
        speed: f64,
        elevation: f64 = 0.0,
        spin: f64 = 0.0,
        samples: usize = 200,
        after_bounce: Option<f64> = None,
    ) -> PyResult<Bound<'py, PyDict>> {
        let launch = Launch {
            height,
            speed,
            elevation_deg: elevation,
            spin,
        };
        let mut spec = with(&common, launch, samples);
        if let Some(d) = after_bounce {
            if common.ends.distance.is_some() {
                return Err(crate::value_error(
                    "after_bounce does not go with distance (it sets the distance)".into(),
                ));
            }
            spec.ends.distance = Some(py.detach(|| past_bounce(&ball, &spec, d))?);
        }
        let mut r = py.detach(|| ball.shot(&spec)).map_err(error)?;
        r.warn_of(&surface);
        let d = report(py, &r)?;
        d.set_item("surface", crate::surface::to_dict(py, &surface)?)?;
        crate::answer::stated(&d, &ball)?;
        Ok(d)
    }
}

/// `after_bounce=D` as the distance it stands for (`Ball::after_bounce_distance`), its
/// refusals named by the arguments, as the command line's `--after-bounce`.
fn past_bounce(ball: &bouncelab::Ball, spec: &ShotSpec, d: f64) -> PyResult<f64> {
    use bouncelab::api::AfterBounceError as E;
    ball.after_bounce_distance(spec, d).map_err(|e| match e {
        E::NotPositive(d) => {
            crate::value_error(format!("invalid after_bounce: {d} (must be positive)"))
        }
        E::NoBounce => {
            crate::value_error("invalid after_bounce: the shot makes no bounce (bounces=0)".into())
        }
        E::EndsBefore { bounce, t } => crate::value_error(format!(
            "invalid after_bounce: the shot ends (at t = {t} s) before its bounce {bounce}"
        )),
        E::PassesBefore { bounce, x } => crate::value_error(format!(
            "invalid after_bounce: the ball passes x = {x} m before its bounce {bounce}"
        )),
        E::Shot(e) => error(e),
    })
}

/// How many of `shots`' arrays are always there ([`SHOT_QUANTITIES`]' first): the first
/// bounce's and the end's; with `net=` the net's clearance (NaN where the ball does not reach
/// the net) and whether it clears it (1 or 0 in a row, a bool array out) follow.
const SHOTS: usize = 12;

flight_pyfunction! {
    /// Many shots: `height`, `speed`, `elevation` and `spin` numbers or numpy arrays broadcast
    /// together; a dict of arrays of the broadcast shape: the first bounce's `landing_t`,
    /// `landing_x`, `v_in`, `angle_in`, `v_out`, `angle_out`, `spin_out` (NaN with
    /// bounces=0) and the end's `end_t`, `end_x`, `end_y`, `end_vx`, `end_vy`; with `net=`,
    /// `net_clearance` (NaN where the ball does not reach it) and `net_cleared` (bools); and
    /// `surface`, the surface the bounces are on (`shot`'s `surface` dict). Element i is what
    /// `shot` gives for the i-th values; the first element without an answer raises, named.
    fn shots<'py>(py, ball, common, surface;
        height: Bound<'py, PyAny>,
        speed: Bound<'py, PyAny>,
        elevation: Option<Bound<'py, PyAny>> = None,
        spin: Option<Bound<'py, PyAny>> = None,
    ) -> PyResult<Bound<'py, PyDict>> {
        let zero = || 0.0_f64.into_pyobject(py).map(|z| z.into_any());
        let elevation = elevation.map_or_else(zero, Ok)?;
        let spin = spin.map_or_else(zero, Ok)?;
        let np = py.import("numpy")?;
        let b = np.call_method1("broadcast_arrays", (height, speed, elevation, spin))?;
        let shape = b.get_item(0)?.getattr("shape")?;
        let cols: Vec<Vec<f64>> = ["height", "speed", "elevation", "spin"]
            .iter()
            .enumerate()
            .map(|(k, name)| {
                let a = np.call_method1("asarray", (b.get_item(k)?, "float64"));
                let a = crate::of_argument(py, name, a)?;
                a.call_method0("ravel")?.call_method0("tolist")?.extract()
            })
            .collect::<PyResult<_>>()?;
        let n = cols[0].len();
        let rows: Result<Vec<[f64; 14]>, (usize, bouncelab::BallError)> = py.detach(|| {
            (0..n)
                .into_par_iter()
                .map(|i| {
                    let launch = Launch {
                        height: cols[0][i],
                        speed: cols[1][i],
                        elevation_deg: cols[2][i],
                        spin: cols[3][i],
                    };
                    // the numbers only: the bounces' warnings are not made
                    // (`Ball::shot_unwarned`, the numbers of `Ball::shot`)
                    ball.shot_unwarned(&with(&common, launch, 0))
                        .map(|r| r.quantities(&SHOT_QUANTITIES))
                        .map_err(|e| (i, e))
                })
                .collect()
        });
        let rows = rows.map_err(|(i, e)| {
            let err = error(e);
            PyValueError::new_err(format!("element {i}: {}", err.value(py)))
        })?;
        let d = PyDict::new(py);
        for (k, name) in SHOT_QUANTITIES[..SHOTS].iter().enumerate() {
            let a = array(py, rows.iter().map(|r| r[k]).collect());
            d.set_item(*name, a.call_method1("reshape", (&shape,))?)?;
        }
        if common.net.is_some() {
            let clearance = array(py, rows.iter().map(|r| r[12]).collect());
            d.set_item(SHOT_QUANTITIES[12], clearance.call_method1("reshape", (&shape,))?)?;
            let cleared = PyArray1::from_vec(py, rows.iter().map(|r| r[13] == 1.0).collect());
            d.set_item(SHOT_QUANTITIES[13], cleared.call_method1("reshape", (&shape,))?)?;
        }
        // every answer names its surface, as `shot`'s and the command line's (issue 57)
        d.set_item("surface", crate::surface::to_dict(py, &surface)?)?;
        Ok(d)
    }
}
