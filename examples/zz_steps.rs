use bouncelab::model::contact::ContactLaw;
fn main() {
    for name in ["superball", "tennis", "softball"] {
        let b = bouncelab::Ball::from_preset(name).unwrap();
        for mult in [1.0, 3.0] {
            let mut p = b.params;
            p.v0 *= mult;
            let n = p.normalized();
            eprintln!("== {name} x{mult}");
            let s = bouncelab::solver::taylor::summary(&n, ContactLaw::ElasticPlastic);
            eprintln!("{:?}", s.map(|s| s.steps));
        }
    }
}
