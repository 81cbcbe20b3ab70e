use super::*;

#[test]
fn embedded_presets_parse() {
    assert_eq!(
        Preset::embedded()
            .iter()
            .map(|p| p.name.as_str())
            .collect::<Vec<_>>(),
        ["superball", "golf", "baseball"]
    );
    let all = Preset::embedded_all();
    assert_eq!(
        all.iter().map(|p| p.name.as_str()).collect::<Vec<_>>(),
        [
            "superball",
            "golf",
            "baseball",
            "tennis",
            "football",
            "basketball",
            "table-tennis",
            "softball",
            "baseball-mlb",
            "softball-44",
            "squash",
            "volleyball",
            "golf-driver"
        ]
    );
    for p in &all {
        assert!(p.params().validate().is_ok(), "{}", p.name);
        assert!(
            p.params_from(ParamSource::Materials).validate().is_ok(),
            "{}",
            p.name
        );
    }
}

#[test]
fn errors_point_at_file_line_column() {
    let bad = EMBEDDED[0].1.replace("mass = 0.0374", "mass = \"heavy\"");
    let e = Preset::parse(&bad, "x.toml").unwrap_err();
    assert_eq!(e.position.map(|p| p.0), Some(9), "{e}");
    assert!(e.to_string().starts_with("x.toml:9:8: "), "{e}");
    let neg = EMBEDDED[0]
        .1
        .replace("radius = 0.02155", "radius = -0.02155");
    let e = Preset::parse(&neg, "x.toml").unwrap_err();
    assert_eq!(
        e.to_string(),
        "x.toml:10:1: measured.radius: must be a positive finite number, got -0.02155"
    );
    let huge = EMBEDDED[0].1.replace("mass = 0.0374", "mass = 1e300");
    let e = Preset::parse(&huge, "x.toml").unwrap_err();
    assert!(e.to_string().ends_with("got 1e300"), "{e}");
    // a finite number past the parameters' range is told so, not called infinite or negative
    for (from, to, key) in [
        ("mass = 0.0374", "mass = 1e16", "measured.mass"),
        ("k_r = 7.08e4", "k_r = 1e16", "adopted.k_r"),
    ] {
        let e = Preset::parse(&EMBEDDED[0].1.replace(from, to), "x.toml").unwrap_err();
        assert!(
            e.to_string().ends_with(&format!(
                "{key}: must be below 1e15 (every parameter's range), got 1e16"
            )),
            "{e}"
        );
    }
    let unknown = EMBEDDED[0].1.replace("[adopted]", "[adopted]\nspring = 3");
    let e = Preset::parse(&unknown, "x.toml").unwrap_err();
    assert!(e.to_string().contains("spring"), "{e}");
}

/// Found by the `preset_toml` fuzz target (fuzz/regressions/preset_toml/): errors lost
/// their line:column when the key was missing or written in another TOML spelling, and
/// control characters of a quoted key reached the one-line message.
#[test]
fn every_error_has_a_position_and_one_line() {
    let sb = EMBEDDED[0].1;
    let at = |text: &str| Preset::parse(text, "x.toml").unwrap_err().to_string();
    // a comment after the table header
    let t = sb
        .replace("[measured]", "[measured]   # Cross")
        .replace("v0 = 3.12 ", "v0 = 0 ");
    assert_eq!(
        at(&t),
        "x.toml:11:1: measured.v0: must be a positive finite number, got 0"
    );
    // a required key that is missing: the table that lacks it
    let t = sb.replace("kind = \"elastomer\"", "kind = \"metal\"");
    assert_eq!(
        at(&t),
        "x.toml:16:2: material.yield_strength: is required for kind = \"metal\""
    );
    // dotted keys and inline tables
    let t = "name = \"d\"\nmeasured = { mass = 1, radius = 1, v0 = -1 }\n\
             material.modulus = 1\nmaterial.poisson = 0.3\nadopted.k_r = 1\n";
    assert_eq!(
        at(t),
        "x.toml:2:36: measured.v0: must be a positive finite number, got -1"
    );
    // the layer at fault, not the first one
    let golf = EMBEDDED[1].1.replace("thickness = 5.4e-3", "thickness = 0");
    let row = 1 + golf
        .lines()
        .position(|l| l.starts_with("thickness = 0"))
        .unwrap();
    assert!(
        at(&golf).starts_with(&format!("x.toml:{row}:1: material.layers.thickness: ")),
        "{}",
        at(&golf)
    );
    // control characters of a quoted key are escaped
    let t = format!("\"a\\rb\\u001b\" = 1\n{sb}");
    assert_eq!(at(&t).lines().count(), 1, "{:?}", at(&t));
    assert!(
        at(&t).starts_with("x.toml:1:1: unknown field `a\\rb\\u{1b}`"),
        "{:?}",
        at(&t)
    );
}
