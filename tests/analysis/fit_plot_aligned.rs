//! `fit --plot` stacks the data with the model above their residuals, on one speed (or time)
//! axis: both plots start and end at one x (src/cli/fit/plot.rs takes the wider of their
//! label areas, figure::svg::render_aligned). The residuals' wider tick labels ("-0.0005")
//! once moved the lower plot 16 px right of the upper one.

use crate::common;

use common::{argv, ok_at};

/// The plot frames (`fill="none"`, black stroke) of each stacked figure: (x, width).
fn frames(svg: &str) -> Vec<(u32, u32)> {
    let doc = roxmltree::Document::parse(svg).unwrap();
    doc.descendants()
        .filter(|n| n.has_tag_name("rect"))
        .filter(|n| n.attribute("fill") == Some("none") && n.attribute("stroke") == Some("#000000"))
        .map(|n| {
            let a = |k: &str| n.attribute(k).unwrap().parse::<u32>().unwrap();
            (a("x"), a("width"))
        })
        .collect()
}

#[test]
fn the_two_plots_of_fit_plot_line_up() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // a COR table (the residuals' labels "-0.0005" wide) and two drops (the COR residuals
    // of drops), each fitted and plotted
    std::fs::write(d.join("c.csv"), "v0,cor\n40,0.62\n45,0.6\n").unwrap();
    let cases: [&[&str]; 2] = [
        &argv("--preset superball --cor-table c.csv --free k_r"),
        &argv(
            "--preset tennis --drop-height 2.54 --rebound-height 1.41 --drop-height 2.54 \
            --rebound-height 1.43",
        ),
    ];
    for args in cases {
        let all = [&["fit"][..], args, &["--plot", "p.svg", "--force"]].concat();
        ok_at(d, &all);
        let svg = std::fs::read_to_string(d.join("p.svg")).unwrap();
        let f = frames(&svg);
        assert_eq!(f.len(), 2, "{args:?}: {f:?}");
        assert_eq!(f[0], f[1], "{args:?}: the data's and the residuals' plots");
    }
}
