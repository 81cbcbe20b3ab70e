//! A force–time trace: a recorder's clock (arbitrary zero), noise around a baseline before
//! and after the pulse. [`Trace::summary`] reads off what a fit starts from: baseline, noise,
//! peak, where the pulse starts and ends, and the impulse.

use super::MeasuredError;
use super::table::{self, ColumnSpec};

/// The columns of a trace (also how `parse_any` tells one).
pub(super) const SPECS: [ColumnSpec; 2] = [
    ColumnSpec::required(
        "time",
        &[
            ("time", 1.0),
            ("t", 1.0),
            ("time_s", 1.0),
            ("time_ms", 1e-3),
            ("time_us", 1e-6),
        ],
    ),
    ColumnSpec::required(
        "force",
        &[
            ("force", 1.0),
            ("f", 1.0),
            ("force_n", 1.0),
            ("force_kn", 1e3),
        ],
    ),
];

/// Samples in SI, time strictly increasing.
#[derive(Debug, Clone, PartialEq)]
pub struct Trace {
    /// Sample times, s, strictly increasing.
    pub time: Vec<f64>,
    /// Force at each time, N.
    pub force: Vec<f64>,
    /// Line of each sample in the text (for errors found later).
    pub lines: Vec<usize>,
    /// Column of each sample's force cell.
    pub force_columns: Vec<usize>,
    /// The line after the last one read, for errors about the whole trace.
    pub end_line: usize,
}

/// What a trace shows before any model is fitted.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TraceSummary {
    /// Median force away from the pulse (N).
    pub baseline: f64,
    /// Noise standard deviation there, from the median absolute deviation (N).
    pub noise: f64,
    /// Peak force above the baseline (N).
    pub peak: f64,
    /// Time of the peak (s).
    pub t_peak: f64,
    /// Where the force, above the baseline, first exceeds 5 % of the peak, extrapolated
    /// linearly back to zero from there (s).
    pub t_start: f64,
    /// Likewise where it last exceeds 5 % of the peak, extrapolated forward to zero (s).
    pub t_end: f64,
    /// ∫ (F − baseline) dt over [t_start, t_end] (N s) = m v0 (1 + e) for a rebound.
    pub impulse: f64,
}

impl Trace {
    /// Columns `time`/`t`/`time_s`/`time_ms`/`time_us` and `force`/`F`/`force_N`/`force_kN`.
    /// Rows go straight into the trace's vectors, reserved once (`table::read_each`).
    pub fn parse(text: &str) -> Result<Trace, MeasuredError> {
        Trace::read(text.into())
    }

    /// [`Trace::parse`] of a text or of rows already read (a batch's ball).
    pub fn read(src: table::Source<'_>) -> Result<Trace, MeasuredError> {
        let room = table::rows_at_most(src);
        let mut tr = Trace {
            time: Vec::with_capacity(room),
            force: Vec::with_capacity(room),
            lines: Vec::with_capacity(room),
            force_columns: Vec::with_capacity(room),
            end_line: 0,
        };
        let end_line = table::read_each(src, &SPECS, |line, v| {
            let ((t, t_column), (f, f_column)) = (v[0], v[1]);
            let t = t.unwrap_or(f64::NAN);
            if let (Some(&before), Some(&before_line)) = (tr.time.last(), tr.lines.last())
                && t <= before
            {
                return Err(MeasuredError::at(
                    line,
                    t_column,
                    format!("time not increasing: {t} s after {before} s on line {before_line}"),
                ));
            }
            tr.time.push(t);
            tr.force.push(f.unwrap_or(f64::NAN));
            tr.lines.push(line);
            tr.force_columns.push(f_column);
            Ok(())
        })?;
        tr.end_line = end_line;
        Ok(tr)
    }

    /// Baseline, noise and pulse; an error when there is no pulse above the noise.
    pub fn summary(&self) -> Result<TraceSummary, MeasuredError> {
        let n = self.force.len();
        let edge = (n / 10).max(1);
        let mut quiet: Vec<f64> = self.force[..edge.min(n)].to_vec();
        quiet.extend_from_slice(&self.force[n.saturating_sub(edge)..]);
        let baseline = median(&mut quiet.clone());
        let mut dev: Vec<f64> = quiet.iter().map(|f| (f - baseline).abs()).collect();
        let noise = (1.4826 * median(&mut dev)).min(self.noise_of_differences());
        let (ip, peak) = self.force.iter().map(|f| f - baseline).enumerate().fold(
            (0, f64::NEG_INFINITY),
            |a, (i, f)| if f > a.1 { (i, f) } else { a },
        );
        if !(peak > 5.0 * noise && peak > 0.0) || n < 3 {
            let lowest = self
                .force
                .iter()
                .fold(f64::INFINITY, |a, &f| a.min(f - baseline));
            let hint = if -lowest > 5.0 * noise && -lowest > 0.0 {
                " (the pulse is negative: force is taken positive pushing on the ball)"
            } else {
                "; a trace needs one impact pulse"
            };
            return Err(MeasuredError::at(
                self.lines[ip],
                self.force_columns[ip],
                format!(
                    "empty pulse: the largest force above the baseline ({} N) is within the \
                     noise ({} N){hint}",
                    short(peak),
                    short(noise)
                ),
            ));
        }
        let level = 0.05 * peak;
        let above = |i: usize| self.force[i] - baseline > level;
        let mut a = ip;
        while a > 0 && above(a - 1) {
            a -= 1;
        }
        let mut b = ip;
        while b + 1 < n && above(b + 1) {
            b += 1;
        }
        // straight lines through the 5 % points and the half-peak points, continued to zero
        let t_start = self.extrapolate(a, ip, baseline, peak, true);
        let t_end = self.extrapolate(b, ip, baseline, peak, false);
        let impulse = (a.max(1)..=b.min(n - 1))
            .map(|i| {
                0.5 * (self.force[i] + self.force[i - 1] - 2.0 * baseline)
                    * (self.time[i] - self.time[i - 1])
            })
            .sum();
        Ok(TraceSummary {
            baseline,
            noise,
            peak,
            t_peak: self.time[ip],
            t_start: t_start.min(self.time[a]),
            t_end: t_end.max(self.time[b]),
            impulse,
        })
    }

    /// The noise's standard deviation from the rows' second differences, which a smooth pulse
    /// sampled densely leaves at the noise (F'' h² ≈ 6e-5 of the peak at 400 rows over a
    /// half-sine): the median absolute second difference (the upper middle one of an even
    /// count) over 0.6745 √6 (the difference of independent noise has variance 6σ²). Where
    /// the trace is the contact alone (`run --history`), the first and last tenth of the rows
    /// are the pulse's flanks, whose spread is the pulse's, not the noise's (issue 52);
    /// `tests::a_contact_only_trace_reads_its_noise`. Infinite below three rows.
    fn noise_of_differences(&self) -> f64 {
        let f = &self.force;
        if f.len() < 3 {
            return f64::INFINITY;
        }
        let mut d2: Vec<f64> = f
            .windows(3)
            .map(|w| (w[0] - 2.0 * w[1] + w[2]).abs())
            .collect();
        // the middle one by selection, O(n), not a sort of up to 10⁶ rows' differences
        let mid = d2.len() / 2;
        let (_, m, _) = d2.select_nth_unstable_by(mid, f64::total_cmp);
        1.4826 * *m / 6f64.sqrt()
    }

    /// Where the pulse's flank through sample `edge` reaches zero: the line through the first
    /// samples of the flank (from `edge` toward the peak) above 5 % and above half the peak.
    fn extrapolate(&self, edge: usize, ip: usize, base: f64, peak: f64, rising: bool) -> f64 {
        let mut half = edge;
        while half != ip && self.force[half] - base < 0.5 * peak {
            half = if rising { half + 1 } else { half - 1 };
        }
        let (t1, f1) = (self.time[edge], self.force[edge] - base);
        let (t2, f2) = (self.time[half], self.force[half] - base);
        if half == edge || f2 <= f1 {
            return t1;
        }
        t1 - f1 * (t2 - t1) / (f2 - f1)
    }
}

fn median(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(f64::total_cmp);
    let m = v.len() / 2;
    if v.len() % 2 == 1 {
        v[m]
    } else {
        0.5 * (v[m - 1] + v[m])
    }
}

fn short(x: f64) -> String {
    crate::text::short(x, 3)
}

/// Tests' synthetic traces.
#[cfg(test)]
impl Trace {
    /// These samples as a two-column file with a header reads them: sample i on line i + 2
    /// (`from_columns_is_what_the_file_reads`), with no text behind them to place the force
    /// cells in: column 2 for each.
    pub(crate) fn from_columns(time: Vec<f64>, force: Vec<f64>) -> Trace {
        let rows = time.len();
        Trace {
            lines: (2..rows + 2).collect(),
            force_columns: vec![2; rows],
            end_line: rows + 2,
            time,
            force,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn from_columns_is_what_the_file_reads() {
        let (time, force) = (vec![0.0, 1e-3, 2e-3], vec![0.5, 80.0, 0.25]);
        let text = "time_s,force_N\n0,0.5\n0.001,80\n0.002,0.25\n";
        let (made, read) = (
            Trace::from_columns(time, force),
            Trace::parse(text).unwrap(),
        );
        assert_eq!(
            (made.time, made.force, made.lines, made.end_line),
            (read.time, read.force, read.lines, read.end_line)
        );
        assert_eq!(made.force_columns, [2, 2, 2]);
    }

    fn half_sine(offset: f64, base: f64) -> String {
        let mut s = String::from("# made up\ntime_ms,force_kN\n");
        for i in 0..200 {
            let t = i as f64 * 0.05; // ms
            let x = (t - offset) / 3.0;
            let f = if (0.0..=1.0).contains(&x) {
                (std::f64::consts::PI * x).sin() * 0.1
            } else {
                0.0
            };
            s.push_str(&format!("{t},{}\n", f + base));
        }
        s
    }

    #[test]
    fn summary_reads_pulse_baseline_and_units() {
        let tr = Trace::parse(&half_sine(2.0, 0.001)).unwrap();
        assert_eq!(tr.time.len(), 200);
        assert!((tr.time[1] - 5e-5).abs() < 1e-18);
        let s = tr.summary().unwrap();
        assert!((s.baseline - 1.0).abs() < 1e-9, "{s:?}");
        assert!((s.peak - 100.0).abs() < 0.5, "{s:?}");
        assert!((s.t_start - 2e-3).abs() < 1e-4, "{s:?}");
        assert!((s.t_end - 5e-3).abs() < 1e-4, "{s:?}");
        // ∫ 100 sin(π t / 3 ms) dt = 100 · 6 ms / π
        assert!(
            (s.impulse - 0.6 / std::f64::consts::PI).abs() < 2e-3,
            "{s:?}"
        );
    }

    /// A contact-only trace (a half-sine filling every row, as `run --history` writes one) with
    /// Gaussian noise of 3 N: the noise read is 3 N to its estimate's error (about 5 % at
    /// 400 rows), not the flanks' spread (tens of newtons: the pulse's edges, not its noise).
    #[test]
    fn a_contact_only_trace_reads_its_noise() {
        let mut normal = crate::bench_ball::normals(52);
        let mut text = String::from("t,F\n");
        for i in 0..400 {
            let x = i as f64 / 399.0;
            let f = 250.0 * (std::f64::consts::PI * x).sin() + 3.0 * normal();
            text.push_str(&format!("{},{f}\n", x * 3.5e-3));
        }
        let s = Trace::parse(&text).unwrap().summary().unwrap();
        assert!((s.noise / 3.0 - 1.0).abs() < 0.2, "{s:?}");
    }

    #[test]
    fn bad_traces() {
        let e = Trace::parse("t,F\n0,0\n1,1\n1,2\n").unwrap_err();
        assert_eq!((e.line, e.column), (4, 1));
        assert!(e.message.contains("time not increasing"), "{e}");
        let flat = Trace::parse("t,F\n0,0\n1,0\n2,0\n3,0\n").unwrap();
        let e = flat.summary().unwrap_err();
        assert!(e.message.contains("empty pulse"), "{e}");
    }
}
