//! `static`: the ball squeezed between two rigid plates under a load (docs/model.md §11), as
//! `bouncelab static --format json`: the library's report (`StaticReport`), key for key.

use crate::arguments::ball::ball_pyfunction;
use crate::error;
use bouncelab::api::StaticReport;
use pyo3::prelude::*;

ball_pyfunction! {
    /// The forward deflection of the ball's diameter between two rigid plates under `load_kg`
    /// (its weight on each contact; the ITF's tests use 8.165 kg) and, where the law has
    /// hysteresis, the return deflection after compressing the diameter by `peak` m, as
    /// `bouncelab static --preset NAME --load KG [--peak M] --format json`: a dict with its
    /// keys (`forward` and `return`: `deflection_m`, `indentation_m`, `recoil_m`, or None and
    /// the `reason`; `warnings`; the `ball` object), None where the JSON has null.
    #[pyo3(name = "static")]
    signature = (preset="superball", *, load_kg, peak=0.0254, law=None, params=None,);
    fn static_deflection<'py>(
        py,
        preset: &str,
        load_kg: f64,
        peak: f64,
        law: Option<&str>,
        params: Option<&str>,
    ) -> PyResult<Bound<'py, PyAny>>;
    ball choice = (preset, params, law);
    {
        let ball = choice.resolve(None)?;
        let s = ball.static_deflection(load_kg, peak).map_err(error)?;
        let d = crate::answer::json(py, &StaticReport::new(&ball, load_kg, &s))?;
        // `conditions` beside the report's keys, as the command line's JSON
        d.set_item("surface", crate::surface::rigid_plate(py)?)?;
        d.set_item("conditions", &crate::answer::Stated::of(&ball))?;
        Ok(d)
    }
}
