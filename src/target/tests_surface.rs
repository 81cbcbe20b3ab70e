//! Surface presets (`surface::Surface::parse`, docs/surfaces.md).

use super::surface::{DEFAULT, EMBEDDED, Surface};

#[test]
fn every_embedded_surface_parses_and_cites_its_sources() {
    let all = Surface::embedded();
    assert_eq!(all.len(), 8);
    for (s, (name, _)) in all.iter().zip(EMBEDDED) {
        assert_eq!(&s.name, name, "the file's name is the list's");
        assert!(!s.sources.is_empty(), "{name} cites a source");
    }
    let names: std::collections::BTreeSet<_> = all.iter().map(|s| s.name.clone()).collect();
    assert_eq!(names.len(), all.len(), "names are unique");
    assert_eq!(all[0].name, DEFAULT);
    let plate = Surface::rigid_plate();
    assert!(plate.mechanics.is_rigid());
    assert_eq!(plate.mechanics.target(), super::Target::wall());
}

/// Parse `text` and the error it gives, as `origin:line:column: message`.
fn error(text: &str) -> String {
    Surface::parse(text, "s.toml").unwrap_err().to_string()
}

const HEAD: &str = "name = \"x\"\ndescription = \"d\"\n";

#[test]
fn a_number_without_a_source_is_refused_where_it_is() {
    let e = error(&format!("{HEAD}[normal]\nstiffness = 1e5\n"));
    assert!(
        e.starts_with("s.toml:4:13: normal.stiffness: no source"),
        "{e}"
    );
    let ok = format!(
        "{HEAD}[normal]\nstiffness = 1e5\ndamping = 20.0\n[tangential]\nfriction = 0.5\n\
         [[sources]]\nquantity = \"stiffness\"\nsource = \"a\"\n[[sources]]\n\
         quantity = \"damping\"\nsource = \"b\"\n[[sources]]\nquantity = \"friction\"\nsource = \"c\"\n"
    );
    let s = Surface::parse(&ok, "s.toml").unwrap().mechanics;
    assert_eq!((s.stiffness, s.damping, s.mass), (1e5, 20.0, f64::INFINITY));
    assert_eq!(s.friction, Some(0.5));
    assert_eq!(s.tangential_stiffness, None);
}

#[test]
fn bad_values_and_keys_name_their_place() {
    let src = "[[sources]]\nquantity = \"friction\"\nsource = \"a\"\n";
    let cases = [
        (
            format!("{HEAD}[tangential]\nfriction = -0.1\n{src}"),
            "s.toml:4:12: tangential.friction: must be ≥ 0",
        ),
        (
            format!("{HEAD}[tangential]\nfriction = inf\n{src}"),
            "s.toml:4:12: tangential.friction: must be finite",
        ),
        (
            format!("{HEAD}[normal]\nstifness = 1.0\n"),
            "s.toml:4:1: unknown field `stifness`",
        ),
        (
            format!("{HEAD}[[sources]]\nquantity = \"colour\"\nsource = \"a\"\n"),
            "s.toml:4:12: sources.quantity: unknown quantity 'colour'",
        ),
        (
            "description = \"d\"\n".to_string(),
            "s.toml:1:1: missing field `name`",
        ),
        (
            "name = \"a b\"\ndescription = \"d\"\n".to_string(),
            "s.toml:1:8: name: must be non-empty",
        ),
    ];
    for (text, want) in cases {
        let e = error(&text);
        assert!(e.starts_with(want), "{e}\nwanted {want}");
        assert!(!e.contains('\n'), "one line: {e}");
    }
}
