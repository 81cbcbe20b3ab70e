//! Where the oblique fit starts and the box it searches (docs/oblique.md §9).

/// The start and others around it: K_t a factor 3 and 10 either way, μ halved and doubled,
/// and with spins κ a factor 1.4 either way at each K_t. The outgoing motion is piecewise
/// smooth in them (a row turns from sliding to gripping) and oscillates with the grip's phase
/// at separation (√(K_t (1 + 1/κ)), docs/oblique.md §2): the cost has local minima, and a
/// start in the wrong valley stays there (`spins_do_not_stop_in_a_local_minimum`,
/// tests/analysis/fit_oblique_coverage.rs). With c_t fitted (last in x), also c_t a factor 3 either
/// way at the start's μ and K_t.
pub(super) fn starting_points(x0: &[f64], spins: bool, damped: bool) -> Vec<Vec<f64>> {
    let (ln2, ln3, ln10) = (2f64.ln(), 3f64.ln(), 10f64.ln());
    let kappas: &[f64] = if spins {
        &[0.0, 1.4f64.ln(), -(1.4f64.ln())]
    } else {
        &[0.0]
    };
    let mut moves = vec![(ln2, 0.0, 0.0), (-ln2, 0.0, 0.0)];
    for dk in [0.0, ln3, -ln3, ln10, -ln10] {
        moves.extend(kappas.iter().map(|&dq| (0.0, dk, dq)));
    }
    moves.sort_by_key(|m| m != &(0.0, 0.0, 0.0));
    let mut all: Vec<Vec<f64>> = moves
        .into_iter()
        .map(|(dm, dk, dq)| {
            let mut x = x0.to_vec();
            x[0] += dm;
            x[1] += dk;
            if spins {
                // κ ≤ 1
                x[2] = (x[2] + dq).min(0.0);
            }
            x
        })
        .collect();
    if damped {
        let last = x0.len() - 1;
        for dc in [ln3, -ln3] {
            let mut x = x0.to_vec();
            x[last] += dc;
            all.push(x);
        }
    }
    all
}

/// The box: μ in [1e-4, 100], K_t four decades either side of its start, κ in [0.05, 1] (with
/// spins), c_t four decades either side of its start (when fitted, last).
pub(super) fn bounds(x0: &[f64], spins: bool, damped: bool) -> (Vec<f64>, Vec<f64>) {
    let decades = 4.0 * 10f64.ln();
    let mut lo = vec![1e-4f64.ln(), x0[1] - decades];
    let mut hi = vec![100f64.ln(), x0[1] + decades];
    if spins {
        lo.push(0.05f64.ln());
        hi.push(0.0);
    }
    if damped {
        let c = x0[x0.len() - 1];
        lo.push(c - decades);
        hi.push(c + decades);
    }
    (lo, hi)
}
