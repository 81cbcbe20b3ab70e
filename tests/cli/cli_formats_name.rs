//! Every format names the ball, its surface and conditions and warns outside them (docs/
//! guarantees.md; docs/cli.md "Conditions", "The ball object"): the formats a newcomer's trial
//! found losing a warning or a name. A batch's CSV lost the lot's warning. (A shot's
//! trajectory CSV: tests/cli/cli_shot_net.rs.)

use crate::common;

use common::{argv_with, bl};

const LOT: &str = "tests/golden/batch-lot7.csv";

/// `batch --format csv` and `--csv-out`: the lot's warning (the JSON's top-level `warnings`,
/// which belongs to no ball) on every row in `lot_warnings`, and the ball the fits start from,
/// the plate and the conditions after it, as `sweep velocity`'s CSV ends.
#[test]
fn a_batch_csv_carries_the_lot_s_warning_and_names_its_ball() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("balls.csv");
    let json = common::json(&argv_with(
        "batch {} --preset tennis --pressure 10psi --format json",
        &[LOT],
    ));
    let lot = common::warnings(&json);
    assert!(
        lot[0].starts_with(
            "outside calibration: the ball at an unrecorded temperature, 68.95 kPa gauge"
        ),
        "{lot:?}"
    );
    let line = "batch {} --preset tennis --pressure 10psi --format csv --csv-out {}";
    let path = file.display().to_string();
    let o = bl(&argv_with(line, &[LOT, &path]));
    assert_eq!(o.code, 0, "{}", o.stderr);
    for csv in [o.stdout.clone(), std::fs::read_to_string(&file).unwrap()] {
        let mut rows = csv::Reader::from_reader(csv.as_bytes());
        let head = rows.headers().unwrap().clone();
        let at = |name: &str| head.iter().position(|h| h == name).unwrap();
        assert!(head.iter().collect::<Vec<_>>().ends_with(&[
            "fit_error",
            "lot_warnings",
            "preset",
            "origin",
            "parameters",
            "law",
            "surface",
            "surface_stiffness",
            "surface_damping",
            "surface_mass",
            "temperature_c",
            "pressure_gauge_pa",
            "atmosphere_pa"
        ]));
        for row in rows.records() {
            let row = row.unwrap();
            assert_eq!(&row[at("lot_warnings")], lot.join("; "));
            assert_eq!(&row[at("preset")], "tennis");
            assert_eq!(&row[at("surface")], "steel-plate");
            let p: f64 = row[at("pressure_gauge_pa")].parse().unwrap();
            assert!((p - 68947.57).abs() < 0.01, "{p}");
        }
    }
}
