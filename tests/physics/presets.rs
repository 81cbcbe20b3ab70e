//! The three balls of the paper (docs/model.md §7): λ, ζ as adopted, and COR against measurement.

use bouncelab::preset::Preset;
use bouncelab::{ContactLaw, SolveOptions, simulate};

#[test]
fn presets_reproduce_the_paper() {
    // (name, λ, ζ, measured COR), docs/model.md §7
    let expected = [
        ("superball", 1.3, 0.16, 0.75),
        ("golf", 1.0, 0.07, 0.84),
        ("baseball", 0.4, 0.61, 0.49),
    ];
    for (p, (name, lambda, zeta, cor)) in Preset::embedded().iter().zip(expected) {
        assert_eq!(p.name, name);
        let r = simulate(&p.params(), ContactLaw::Linear, &SolveOptions::default()).unwrap();
        let n = r.normalized;
        assert!((n.lambda - lambda).abs() < 0.01, "{name}: λ = {}", n.lambda);
        assert!((n.zeta - zeta).abs() < 0.01, "{name}: ζ = {}", n.zeta);
        assert_eq!(p.measured.cor, Some(cor));
        assert!(
            (r.cor - cor).abs() <= 0.01,
            "{name}: e = {} vs measured {cor}",
            r.cor
        );
    }
}
