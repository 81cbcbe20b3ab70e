//! `api::first_pass` and `Unanswered::answer` (Python's `bouncelab.impacts`): the rows written
//! into columns in two passes are `api::impact_rows`' rows bit for bit, under every law, for a
//! seeded mix of balls in and out of the Hertz table, below and past yield, flattening or
//! not; the first pass leaves exactly the elements the table does not answer, each counted by
//! its path (docs/guarantees.md); a ball that is not one is the same first error.

use crate::spread;

use bouncelab::api::{BallError, Columns, ImpactRow, first_pass, impact_rows};
use bouncelab::solver::table;
use bouncelab::{ContactLaw, ImpactParams};

const LAWS: [ContactLaw; 3] = [
    ContactLaw::Linear,
    ContactLaw::Hertz,
    ContactLaw::ElasticPlastic,
];

/// The mix: 600 of tests/support/spread's balls (a decade either side of the superball's: in and out
/// of the table, below and past yield), tennis balls that flatten at 2 … 60 m/s, and the
/// spread's first 40 with λ = K_r/K_p = 5·10⁵ (outside the table).
fn mix() -> Vec<ImpactParams> {
    let mut balls = spread::balls(0x2545_f491_4f6c_dd1d, 600);
    let tennis = bouncelab::Ball::from_preset("tennis").unwrap().params;
    balls.extend((0..=58).map(|i| ImpactParams {
        v0: 2.0 + f64::from(i),
        ..tennis
    }));
    let stiff = balls[..40].iter().map(|p| ImpactParams {
        k_r: p.k_p * 5e5,
        ..*p
    });
    let stiff: Vec<_> = stiff.filter(|p| p.validate().is_ok()).collect();
    balls.extend(stiff);
    balls
}

/// The rows of `balls` under `law` through the two passes, and the first pass's count.
fn two_passes(
    law: ContactLaw,
    balls: &[ImpactParams],
) -> (
    Result<Vec<ImpactRow>, (usize, BallError)>,
    bouncelab::analysis::work::Elements,
) {
    let n = balls.len();
    let mut f = [(); 5].map(|()| vec![-1.0; n]);
    let mut rebound = vec![false; n];
    let mut out = Columns::from_slices(f.each_mut().map(|v| v.as_mut_slice()), &mut rebound);
    let params = |i: usize| balls[i];
    let rest = first_pass(law, &params, &mut out);
    let count = rest.elements();
    let rows = rest.answer(&params, &mut out).map(|()| {
        (0..n)
            .map(|i| ImpactRow {
                cor: f[0][i],
                max_force: f[1][i],
                contact_time: f[2][i],
                max_indentation: f[3][i],
                permanent_indentation: f[4][i],
                rebound: rebound[i],
            })
            .collect()
    });
    (rows, count)
}

/// Two rows the same to the last bit (a NaN contact time equal to a NaN).
fn same_bits(a: &ImpactRow, b: &ImpactRow) -> bool {
    let bits = |r: &ImpactRow| {
        [
            r.cor,
            r.max_force,
            r.contact_time,
            r.max_indentation,
            r.permanent_indentation,
        ]
        .map(f64::to_bits)
    };
    bits(a) == bits(b) && a.rebound == b.rebound
}

#[test]
fn the_two_passes_give_impact_rows_bits_under_every_law() {
    let balls = mix();
    for law in LAWS {
        let want = impact_rows(balls.len(), law, |i| balls[i]).unwrap();
        let (got, _) = two_passes(law, &balls);
        let got = got.unwrap();
        for (i, (g, w)) in got.iter().zip(&want).enumerate() {
            assert!(
                same_bits(g, w),
                "{law:?} {i} {:?}: {g:?} vs {w:?}",
                balls[i]
            );
        }
    }
}

#[test]
fn the_first_pass_leaves_what_the_table_does_not_answer_counted_by_path() {
    let balls = mix();
    let (_, linear) = two_passes(ContactLaw::Linear, &balls);
    assert_eq!((linear.off_table, linear.past_yield), (0, 0));
    for law in [ContactLaw::Hertz, ContactLaw::ElasticPlastic] {
        let (_, count) = two_passes(law, &balls);
        let (mut off, mut past) = (0, 0);
        for p in &balls {
            let n = p.normalized();
            // the table answers where it holds the ball and, elastic–plastic, below yield
            // (`table::summary` then takes no Taylor step); it gives a rebound there
            let tabulated = table::summary(&n, law).is_some_and(|s| s.steps == 0);
            if !table::holds(&n) {
                off += 1;
            } else if !tabulated {
                past += 1;
            }
        }
        eprintln!(
            "{law:?}: {} elements, {off} outside the table, {past} past yield",
            balls.len()
        );
        assert_eq!(count.n, balls.len());
        assert_eq!((count.off_table, count.past_yield), (off, past), "{law:?}");
        assert!(off >= 40, "{off} outside");
        if law == ContactLaw::ElasticPlastic {
            assert!(past >= 50, "{past} past yield");
        }
    }
}

#[test]
fn a_ball_that_is_not_one_is_the_first_error_and_nothing_after_it_runs() {
    let mut balls = mix();
    let bad = 450;
    balls[bad].k_p = -1.0;
    balls[bad + 100].mass = f64::NAN;
    for law in LAWS {
        let want = impact_rows(balls.len(), law, |i| balls[i]).unwrap_err();
        let (got, count) = two_passes(law, &balls);
        let got = got.unwrap_err();
        assert_eq!(got.0, bad, "{law:?}");
        assert_eq!(got.0, want.0, "{law:?}");
        assert_eq!(got.1.to_string(), want.1.to_string(), "{law:?}");
        // only elements before the bad one are left to run and counted
        let before = two_passes(law, &balls[..bad]).1;
        assert_eq!(
            (count.off_table, count.past_yield),
            (before.off_table, before.past_yield),
            "{law:?}"
        );
    }
}

/// The linear law's flattening rows (z_f > 0) are the flattening closed form's answers in
/// lanes (`map::fast::lanes::flattening_one`, which `first_pass` runs eight at a time), to the
/// last bit of e and t_f — not the scalar `map::fast::flattening`'s, which differs in its last
/// bits at some of these balls (the test tells the two paths apart: it fails if the rows go
/// the scalar way).
#[test]
fn flattening_rows_are_the_lanes_answers() {
    use bouncelab::map::fast::{flattening, lanes::flattening_one};
    let balls = mix();
    let (rows, _) = two_passes(ContactLaw::Linear, &balls);
    let rows = rows.unwrap();
    let (mut lanes, mut apart) = (0, 0);
    for (p, row) in balls.iter().zip(&rows) {
        let n = p.normalized();
        if row.permanent_indentation <= 0.0 {
            continue;
        }
        let Some(s) = flattening_one(n.lambda, n.zeta, n.zp_bar).filter(|s| s.cor > 0.0) else {
            continue;
        };
        lanes += 1;
        let w0 = p.omega0();
        assert_eq!(row.cor.to_bits(), s.cor.to_bits(), "{p:?}");
        assert_eq!(row.contact_time.to_bits(), (s.contact_time / w0).to_bits());
        let scalar = flattening(n.lambda, n.zeta, n.zp_bar);
        apart += usize::from(scalar.is_none_or(|c| c.cor.to_bits() != s.cor.to_bits()));
    }
    eprintln!("{lanes} flattening rows, {apart} of them not the scalar path's bits");
    assert!(lanes >= 50 && apart > 0, "{lanes}, {apart}");
}
