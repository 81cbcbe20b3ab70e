use bouncelab::*;
fn main() {
    for (l, z, zp) in [
        (1.0, 1e4, f64::INFINITY),
        (0.4, 3e3, 0.5),
        (0.0, 1e4, 1.0),
        (1e4, 0.5, 1.0),
        (1e-4, 1e4, 0.01),
    ] {
        let p = ImpactParams::from_normalized(l, z, zp);
        let o = SolveOptions::default().with_energy();
        let a = simulate(&p, ContactLaw::Linear, &o).unwrap();
        let b = simulate(&p, ContactLaw::Linear, &o.with_method(Method::Numeric)).unwrap();
        println!(
            "λ={l} ζ={z} zp={zp}: exact e={:.12} τ={:?} res={:.1e} | numeric e={:.12} τ={:?} res={:.1e} Ed {:.6e} vs {:.6e}",
            a.cor,
            a.contact_time_normalized,
            a.energy.unwrap().relative_residual(),
            b.cor,
            b.contact_time_normalized,
            b.energy.unwrap().relative_residual(),
            a.energy.unwrap().dashpot,
            b.energy.unwrap().dashpot
        );
    }
}
