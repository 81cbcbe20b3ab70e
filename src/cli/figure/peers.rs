//! The peers' figures of `bouncelab figure` (`peers-cor-velocity`, `peers-force-time`; the
//! drawing is src/figure/peers.rs, the peers themselves `bouncelab peers`).

/// `figure peers-cor-velocity` and `figure peers-force-time` (src/figure/peers.rs): the
/// peers calibrated to the ball's measured COR (else, at another speed or for a ball an
/// override changed, its Christoforou–Yigit COR) at v0; the ball's Christoforou–Yigit curve
/// warned of as the one-ball figures' (its record against the speeds drawn) and the notes of
/// what moved in the subtitle.
pub fn figure(a: &super::FigureArgs) -> anyhow::Result<(crate::figure::Figure, Vec<String>)> {
    use crate::figure::peers as fig;
    let ball = a.ball.resolve(a.v0)?;
    let b = ball.record();
    let is_measured = ball.measurement_withheld().is_none();
    let target = fig::target(&b, is_measured).map_err(|e| anyhow::anyhow!(e))?;
    let v0 = b.params.v0;
    let (built, (lo, hi)) = if a.name == super::FigureName::PeersForceTime {
        let samples = a.points.unwrap_or(super::HISTORY_SAMPLES);
        (fig::force_time(&b, target, samples), (v0, v0))
    } else {
        let (lo, hi) = fig::default_range(&b.params);
        let (from, to) = (a.from.unwrap_or(lo), a.to.unwrap_or(hi));
        crate::peers::positive("from", from)?;
        crate::peers::positive("to", to)?;
        if from >= to {
            anyhow::bail!("invalid speed range: --from {from} must be below --to {to}");
        }
        let n = a.points.unwrap_or(super::VELOCITY_POINTS);
        // one Christoforou–Yigit impact per speed, as `figure cor-velocity`: the same limit
        crate::cli::budget::check(n, b.law, &format!("{n} points"))?;
        let speeds = crate::analysis::sweep::log_space(from, to, n);
        (fig::cor_velocity(&b, target, &speeds), (from, to))
    };
    let mut built = built.map_err(|e| anyhow::anyhow!(e))?;
    built.push_notes(&ball.moved_notes(None, Some((lo, hi))));
    Ok((built, ball.speeds_warning(lo, hi).into_iter().collect()))
}
