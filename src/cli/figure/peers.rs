//! The peers' figures of `bouncelab figure` (`peers-cor-velocity`, `peers-force-time`; the
//! drawing is src/figure/peers.rs, the peers themselves `bouncelab peers`).

/// `figure peers-cor-velocity` and `figure peers-force-time` (src/figure/peers.rs): the
/// peers calibrated to the ball's measured COR (else, at another speed or for a ball an
/// override changed, its Christoforou–Yigit COR) at v0.
pub fn figure(a: &super::FigureArgs) -> anyhow::Result<crate::figure::Figure> {
    use crate::figure::peers as fig;
    let whole = a.ball.resolve(a.v0)?;
    let b = whole.record();
    let is_measured = whole.measurement_withheld().is_none();
    let target = fig::target(&b, is_measured).map_err(|e| anyhow::anyhow!(e))?;
    let built = if a.name == super::FigureName::PeersForceTime {
        fig::force_time(&b, target, a.points.unwrap_or(super::HISTORY_SAMPLES))
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
        fig::cor_velocity(&b, target, &speeds)
    };
    built.map_err(|e| anyhow::anyhow!(e))
}
