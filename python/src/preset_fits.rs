//! `fit`: the recoil spring that gives a measured COR, as `bouncelab fit --cor` (`drop` is
//! drops.rs).

use crate::arguments::ball::ball_pyfunction;
use crate::error;
use bouncelab::analysis::fit::Fit;
use bouncelab::api::FitReport;
use pyo3::prelude::*;
use pyo3::types::PyDict;

ball_pyfunction! {
    /// The recoil spring K_r (and λ) that makes the model's COR equal a measured one, at the
    /// preset's ζ, z_p and v0 (or the `v0` given), as `bouncelab fit --cor E`: a dict with the
    /// keys of `bouncelab fit --format json`.
    signature = (cor, preset="superball", v0=None, law=None, params=None, *,);
    fn fit<'py>(
        py,
        cor: f64,
        preset: &str,
        v0: Option<f64>,
        law: Option<&str>,
        params: Option<&str>,
    ) -> PyResult<Bound<'py, PyDict>>;
    ball choice = (preset, params, law);
    {
        let ball = choice.ball(v0)?;
        let f: Fit = py.detach(|| ball.fit_cor(cor)).map_err(error)?;
        let r = FitReport::new(&ball, cor, &f);
        // the fitted ball's warnings at the data's speed, as `bouncelab fit --format json`
        let fitted = bouncelab::ImpactParams {
            k_r: f.k_r,
            ..ball.params
        };
        let warnings = py.detach(|| ball.cor_fit_warnings(&fitted));
        // the report's keys as the command line's JSON writes them (`FitReport`'s serde)
        let d = crate::answer::json(py, &r)?.cast_into::<PyDict>()?;
        d.set_item("warnings", warnings)?;
        d.set_item("ball", &crate::answer::Record::of(&ball))?;
        // the rigid plate the fit assumed, and the conditions, as the command line's JSON
        d.set_item("surface", crate::surface::rigid_plate(py)?)?;
        d.set_item("conditions", &crate::answer::Stated::of(&ball))?;
        Ok(d)
    }
}
