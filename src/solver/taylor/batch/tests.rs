//! The lanes against the scalar code they stand for, bit for bit.

use super::*;

/// The lanes' quick steps are `Rules::step`'s lane by lane, bit for bit, where the norms
/// leave the plain case too: lane 0's zero series (h = ∞), lane 1's subnormal last terms
/// (libm's log₂), huge and tiny coefficients, states below and above 1 (the scales).
#[test]
fn quick_steps_are_the_scalar_rule_lane_by_lane() {
    quick_steps_are_the_scalar_rule_lane_by_lane_in::<NARROW>();
    quick_steps_are_the_scalar_rule_lane_by_lane_in::<WIDE>();
}

fn quick_steps_are_the_scalar_rule_lane_by_lane_in<const W: usize>() {
    let rules = POWER_RULES;
    let picks = [0.0, 1e-310, 3e-17, 0.25, 1.0, 7.5, 1e200, -2e-5];
    for shift in 0..W {
        let value = |v: usize, n: usize, j: usize| {
            let k = (j + shift + 3 * v + n) % picks.len();
            match j {
                0 => 0.0,
                1 if n + 2 >= POWER_LEN => 1e-310,
                _ => picks[k],
            }
        };
        let mut c = [[Lanes::splat(0.0); POWER_LEN]; 4];
        for (v, series) in c.iter_mut().enumerate() {
            for (n, cn) in series.iter_mut().enumerate() {
                *cn = Lanes(std::array::from_fn(|j| value(v, n, j)));
            }
        }
        let x: [Lanes<W>; 4] =
            std::array::from_fn(|v| Lanes(std::array::from_fn(|j| picks[(j + v) % 8] * 3.0)));
        let lanes = quick_steps_in(&c, &x, rules.eps);
        for j in 0..W {
            let lane: [[f64; POWER_LEN]; 4] =
                std::array::from_fn(|v| std::array::from_fn(|n| c[v][n].0[j]));
            let scales = x.map(|xv| xv.0[j].abs().max(1.0));
            let want = rules.step(&lane, &scales);
            assert_eq!(
                lanes.0[j].to_bits(),
                want.to_bits(),
                "lane {j}, shift {shift}"
            );
        }
    }
}

/// The fast series are `mul_add`'s correctly rounded bits whether it is an FMA instruction
/// (`series`'s and `series_one`'s compilations, on a CPU with FMA) or the library's `fma`
/// (this function's own compilation, as on a CPU without): the answers do not depend on
/// the CPU. States and systems of the phases' ranges, a batch's lanes of each.
#[test]
fn series_are_the_same_bits_without_fma_instructions() {
    series_are_the_same_bits_without_fma_instructions_in::<NARROW>();
    series_are_the_same_bits_without_fma_instructions_in::<WIDE>();
}

fn series_are_the_same_bits_without_fma_instructions_in<const W: usize>() {
    let pick = |i: usize, lo: f64, hi: f64| lo + (hi - lo) * ((i * 37 + 11) % 101) as f64 / 100.0;
    for round in 0..16 {
        let lane = |j: usize, v: usize| round * 8 + j + 13 * v;
        let x: [Lanes<W>; 4] = [
            each(|j| pick(lane(j, 0), 0.0, 1.2)),
            each(|j| pick(lane(j, 1), -1.0, 1.0)),
            each(|j| pick(lane(j, 2), -0.3, 0.3)),
            each(|j| pick(lane(j, 3), 0.0, 4.0)),
        ];
        let a = each(|j| pick(lane(j, 5), 0.1, 3.0));
        let k = Coefs {
            two_zeta: each(|j| pick(lane(j, 4), 0.01, 2.0)),
            lambda: each(|j| pick(lane(j, 6), 0.1, 5.0)),
            a,
            minus_a: each(|j| -a.0[j]),
            half_b: each(|j| 0.5 / pick(lane(j, 7), 0.2, 1.5)),
        };
        let mut fused = [[Lanes::splat(0.0); POWER_LEN]; 4];
        let mut scratch = [[Lanes::splat(0.0); POWER_LEN]; 2];
        series(k, x, &mut fused, &mut scratch);
        let mut library = fused;
        power::series_of::<Lanes<W>, POWER_LEN>(k, x, &mut library, &mut scratch);
        for j in 0..W {
            let one = |l: Lanes<W>| l.0[j];
            let kj = Coefs {
                two_zeta: one(k.two_zeta),
                lambda: one(k.lambda),
                a: one(k.a),
                minus_a: one(k.minus_a),
                half_b: one(k.half_b),
            };
            let mut single = [[0.0; POWER_LEN]; 4];
            super::super::series_one(kj, x.map(one), &mut single, &mut [[0.0; POWER_LEN]; 2]);
            for v in 0..4 {
                for n in 0..POWER_LEN {
                    let bits = [fused[v][n].0[j], library[v][n].0[j], single[v][n]];
                    assert!(
                        bits.iter().all(|b| b.to_bits() == bits[0].to_bits()),
                        "round {round}, lane {j}, series {v}, order {n}: {bits:?}"
                    );
                }
            }
        }
    }
}

/// The lanes' step-end sums (their FMA compilation) are `Rules::horner`'s for the fast
/// phases, lane by lane, bit for bit.
#[test]
fn step_sums_are_the_single_paths_lane_by_lane() {
    step_sums_are_the_single_paths_lane_by_lane_in::<NARROW>();
    step_sums_are_the_single_paths_lane_by_lane_in::<WIDE>();
}

fn step_sums_are_the_single_paths_lane_by_lane_in<const W: usize>() {
    let mut c: LaneSeries<W> = [[Lanes::splat(0.0); POWER_LEN]; 4];
    for (v, series) in c.iter_mut().enumerate() {
        for (n, cn) in series.iter_mut().enumerate() {
            *cn = each(|j| {
                let sign = if (n + j + v) % 3 == 0 { -1.0 } else { 1.0 };
                sign * (1.0 + ((n * 7 + j * 3 + v) % 11) as f64 / 11.0) / 1.9f64.powi(n as i32)
            });
        }
    }
    let h = each(|j| 0.1 + 0.11 * j as f64);
    let ahead = evaluations(&c, h);
    for j in 0..W {
        let lane: [[f64; POWER_LEN]; 4] =
            std::array::from_fn(|v| std::array::from_fn(|n| c[v][n].0[j]));
        let d = poly::derivative(&lane[0]);
        let want = lane.map(|cv| POWER_RULES.horner(&cv, h.0[j]));
        assert_eq!(
            ahead.x.map(|x| x.0[j].to_bits()),
            want.map(f64::to_bits),
            "lane {j}"
        );
        assert_eq!(ahead.s_end.0[j].to_bits(), want[0].to_bits(), "lane {j}");
        let dsh = POWER_RULES.horner(&d, h.0[j]);
        assert_eq!(ahead.dsh.0[j].to_bits(), dsh.to_bits(), "lane {j}");
        assert_eq!(ahead.ds0.0[j].to_bits(), lane[0][1].to_bits(), "lane {j}");
    }
}
