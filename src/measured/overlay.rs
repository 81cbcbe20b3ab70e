//! Measured data as points on the model's axes (SI): a trace put on the model's clock, a trace
//! against the ball's displacement, COR against speed. Shared by `figure --measured` and the
//! explorer's `--measured`.

use super::{Data, Flight, MeasuredError, Trace, drop_to_cor};

/// The trace on the model's clock: its contact start (where the force, above the baseline,
/// first exceeds 5 % of its peak, continued to zero) at t = 0, its baseline subtracted.
pub fn aligned(t: &Trace) -> Result<Vec<(f64, f64)>, MeasuredError> {
    let s = t.summary()?;
    Ok(t.time
        .iter()
        .zip(&t.force)
        .map(|(x, f)| (x - s.t_start, f - s.baseline))
        .collect())
}

/// Force against the ball's displacement over the pulse: α(t) = v0 t − (1/m) ∫∫ F dt² from
/// the contact start (Eq. 1 integrated twice with the ball's `mass` and `v0`, trapezoidal
/// rule).
pub fn displacement(t: &Trace, mass: f64, v0: f64) -> Result<Vec<(f64, f64)>, MeasuredError> {
    let s = t.summary()?;
    let (mut velocity, mut alpha) = (v0, 0.0);
    let (mut t0, mut f0) = (s.t_start, 0.0);
    let mut out = Vec::new();
    for (&time, &f) in t.time.iter().zip(&t.force) {
        if time < s.t_start || time > s.t_end {
            continue;
        }
        let f = (f - s.baseline).max(0.0);
        let dt = time - t0;
        let v_new = velocity - 0.5 * (f + f0) / mass * dt;
        alpha += 0.5 * (velocity + v_new) * dt;
        (velocity, t0, f0) = (v_new, time, f);
        out.push((alpha, f));
    }
    Ok(out)
}

/// (v0, e) of a COR table or drop test (drops without air drag); `None` for a trace.
pub fn cor_points(data: &Data) -> Option<Vec<(f64, f64)>> {
    match data {
        Data::Cor(t) => Some(t.points.iter().map(|p| (p.v0, p.cor)).collect()),
        Data::Drop(d) => Some(
            d.drops
                .iter()
                .map(|&(h, r, _)| drop_to_cor(h, r, &Flight::vacuum()))
                .collect(),
        ),
        Data::Trace(_) => None,
    }
}

/// A test's force–time file (s, N): 400 samples 10 µs apart, 0 but over samples 100 … 299,
/// where the force is `pulse`(k) of the pulse's k-th sample (k = 0 … 199).
#[cfg(test)]
pub(crate) fn pulse_text(pulse: impl Fn(f64) -> f64) -> String {
    let mut text = String::from("time_s,force_N\n");
    for i in 0..400 {
        let t = f64::from(i) * 1e-5;
        let f = if (100..300).contains(&i) {
            pulse(f64::from(i - 100))
        } else {
            0.0
        };
        text.push_str(&format!("{t},{f}\n"));
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A constant force F over τ on a ball of mass m from v0: α = v0 t − F t²/(2m) exactly
    /// (the trapezoidal rule is exact for it).
    #[test]
    fn displacement_of_a_constant_force() {
        let tr = Trace::parse(&pulse_text(|_| 10.0)).unwrap();
        let pts = displacement(&tr, 0.05, 2.0).unwrap();
        let start = tr.summary().unwrap().t_start;
        let (a, f) = pts[pts.len() / 2];
        let t = (100 + pts.len() / 2) as f64 * 1e-5 - start;
        assert!(f == 10.0, "{f}");
        assert!((a - (2.0 * t - 10.0 * t * t / 0.1)).abs() < 2e-4 * a, "{a}");
    }
}
