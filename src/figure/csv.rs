//! The plotted series of a figure as CSV, so anyone can re-plot them with their own tools.
//!
//! Long ("tidy") form, one row per point: `series,kind,X,Y` where X and Y are the axes' keys
//! (e.g. `series,kind,zeta,cor`). Values are SI, like every other CSV bouncelab writes, even
//! where the figure shows ms or mm (the series hold SI values; only the picture scales them);
//! `kind` is `model`, `measured` or `reference`. Numbers are written in the shortest form that
//! reads back to the same `f64`.

use super::Figure;
use crate::text::{csv_field as field, number as num};
use std::io::{self, Write};

/// Write every series of `fig`, in drawing order, to `out`.
pub fn write(fig: &Figure, out: &mut dyn Write) -> io::Result<()> {
    writeln!(
        out,
        "series,kind,{},{}",
        field(&fig.x.key),
        field(&fig.y.key)
    )?;
    for s in &fig.series {
        let (id, kind) = (field(&s.id), s.kind.name());
        for &(x, y) in &s.points {
            writeln!(out, "{id},{kind},{},{}", num(x), num(y))?;
        }
    }
    Ok(())
}

/// The CSV as a `String`.
pub fn to_string(fig: &Figure) -> String {
    let mut buf = Vec::new();
    write(fig, &mut buf).expect("writing to a Vec cannot fail");
    String::from_utf8(buf).expect("the CSV is built from UTF-8 text")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::figure::{Axis, Kind, Series, Style};

    #[test]
    fn long_form_in_si() {
        let fig = Figure::new(
            "t".into(),
            String::new(),
            Axis::linear("t (ms)", "t", 1e3),
            Axis::linear("F (N)", "force", 1.0),
            vec![
                Series::new("model", "model", Kind::Model, Style::Solid, 0)
                    .with_points(vec![(0.0, 0.0), (1.5e-3, 10.0)]),
                Series::new("a,b", "a,b", Kind::Measured, Style::Dashed, 1)
                    .with_points(vec![(2e-3, 3.0)]),
            ],
        );
        assert_eq!(
            to_string(&fig),
            "series,kind,t,force\nmodel,model,0,0\nmodel,model,0.0015,10\n\"a,b\",measured,0.002,3\n"
        );
    }
}
