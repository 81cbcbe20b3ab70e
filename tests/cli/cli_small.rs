//! The small defects of issue 28, each through the binary: a ζ of 1e6 that read back above
//! 1e6, `--format` ignored by `peers --export`, links in the presets folder skipped silently.

use crate::common;

use common::*;

/// `map --zeta …:1e6` on a golf ball was refused as "invalid zeta: 1000000.0000000001" (c for
/// ζ = 1e6 read back a hair above): the end given is the end mapped. (At λ = 0.1 and a weak
/// dashpot the tennis ball's centre sinks past its radius, α_max = v0 √(m (1/K_p + 1/K_r)):
/// the one warning its stderr may hold, tests/cli/answer_reach.rs.)
#[test]
fn map_reaches_the_end_of_its_zeta_axis() {
    for preset in ["golf", "superball", "tennis", "baseball"] {
        let o = bl(&argv_with(
            "map --preset {} --lambda 0.1:1e6:3 --zeta 1:1e6:5",
            &[preset],
        ));
        assert_eq!(o.code, 0, "{preset}: {}", o.stderr);
        for line in o.stderr.lines() {
            let centre = "bouncelab: warning: peak displacement of the ball's centre exceeds";
            // and the map's word that its cells are the ball at other λ and ζ
            let cells = "bouncelab: warning: outside calibration: lambda, zeta changed the ball";
            assert!(
                line.starts_with(centre) || line.starts_with(cells),
                "{preset}: {line}"
            );
        }
        let out = o.stdout;
        let last = out.lines().last().unwrap();
        assert!(last.starts_with("1000000,1000000,"), "{preset}: {last}");
    }
}

/// `--export CODE` is the format of what `peers` writes: `--format` with it is refused in one
/// line, not silently ignored.
#[test]
fn peers_export_refuses_format() {
    for format in ["json", "csv", "text"] {
        bad(
            &["peers", "--export", "lammps", "--format", format],
            &["--export", "cannot be used with", "--format"],
        );
    }
    assert!(ok(&["peers", "--export", "json"]).starts_with('{'));
}

/// A dangling or looping `*.toml` link in the presets folder is skipped with one warning on
/// stderr naming it, once a run however often the catalog is read (`fit --save` reads it twice).
#[cfg(unix)]
#[test]
fn dangling_links_are_named_once() {
    let home = config_home(&[]);
    let presets = home.path().join("bouncelab").join("presets");
    std::os::unix::fs::symlink("gone.toml", presets.join("a.toml")).unwrap();
    std::os::unix::fs::symlink("loop.toml", presets.join("loop.toml")).unwrap();
    for args in [&["presets"][..], &["fit", "--cor", "0.8", "--save", "mine"]] {
        let o = bl_in(home.path(), args);
        assert_eq!(o.code, 0, "{args:?}: {}", o.stderr);
        let lines: Vec<&str> = o.stderr.lines().collect();
        assert_eq!(lines.len(), 2, "{args:?}: {}", o.stderr);
        assert!(
            lines[0].starts_with("bouncelab: warning: ")
                && lines[0].ends_with("a.toml skipped: a symbolic link to a missing file"),
            "{}",
            lines[0]
        );
        assert!(
            lines[1].contains("loop.toml skipped: a symbolic link that cannot be followed"),
            "{}",
            lines[1]
        );
    }
}
