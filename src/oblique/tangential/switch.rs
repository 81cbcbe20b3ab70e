//! Where a phase ends (`find_switch`): the first crossing of its switch function after its
//! start, bracketed on the grid and found on the exact flow.

use super::{Grid, Mode, Phase};
use crate::oblique::{NormalMotion, Scaled};
use crate::solver::exact::PathPoint;
use crate::solver::roots::{brent, newton_bracketed_from};

/// Where `phase` ends before τ_f, if it does: the first τ > start where its switch function
/// turns positive after being negative. At its start (normal motion `first` there) the
/// function is 0 (a switch just happened) or below; the crossing is bracketed from the last
/// grid point where it was negative, and found on the exact flow.
pub(super) fn find_switch(
    path: &impl NormalMotion,
    grid: &Grid,
    s: &Scaled,
    phase: &Phase,
    first: &PathPoint,
    tf: f64,
) -> Option<f64> {
    let g = |t: f64| phase.switch(s, &path.at(t), t);
    let tol = 1e-15 * tf.max(1.0);
    let on_flow = OnFlow {
        path,
        s,
        phase,
        tol,
    };
    // while sticking, sin and cos of ω̃_t (τ_j − start) turn by one rotation a grid step
    let turn = (s.omega_t * grid.h).sin_cos();
    let mut angle: Option<(f64, f64)> = None;
    let last = grid.points.len() - 1;
    let mut below: Option<(f64, f64, f64)> = None;
    let start = phase.start;
    let (g0, d0) = phase.switch(s, first, start);
    if g0 < 0.0 {
        below = Some((start, g0, d0));
    }
    for j in grid.after(start)..grid.points.len() {
        let b = grid.tau(j, tf);
        if b <= start {
            continue;
        }
        let (gb, db) = switch_at_point(s, phase, (&grid.points[j], b), &mut angle, turn, j < last);
        if gb > 0.0 {
            let bracket = match below {
                Some((a, ga, _)) => Some((a, ga)),
                None => probe_below(&|t| g(t).0, start, b),
            };
            // a function that has not been negative since the start marks no switch: the
            // two modes agree there to second order (k̃u on the cap, ṽ_c = μF̄'/k̃), and the
            // phase goes on until its function has turned negative and back
            if let Some((a, ga)) = bracket {
                return Some(on_flow.crossing((a, ga), (b, gb)));
            }
        }
        if let Some((a, ga, da)) = below
            && da > 0.0
            && db < 0.0
            && matches!(phase.mode, Mode::Stick)
        {
            // a peak of k̃|u| − μF̄ between two points below the cap
            let (tm, gm) = on_flow.stick_peak((a, da), (b, db));
            if gm > 0.0 {
                return Some(on_flow.crossing((a, ga), (tm, gm)));
            }
        }
        if gb < 0.0 {
            below = Some((b, gb, db));
        }
    }
    None
}

/// `phase`'s switch function and its rate at a grid point `point` (at τ = `b`). While
/// sticking without a dashpot, sin and cos of ω̃_t (τ − start) are carried in `angle` from
/// one point to the next, turned by `turn`; taken afresh at the first point and the last
/// (`before_last` false).
fn switch_at_point(
    s: &Scaled,
    phase: &Phase,
    (point, b): (&PathPoint, f64),
    angle: &mut Option<(f64, f64)>,
    turn: (f64, f64),
    before_last: bool,
) -> (f64, f64) {
    let start = phase.start;
    match (phase.mode, *angle) {
        (Mode::Stick, _) if s.ct > 0.0 => {
            Phase::stick_switch(s, point, phase.damped_state(s, b - start))
        }
        (Mode::Stick, Some((sn, cs))) if before_last => {
            let (ts, tc) = turn;
            let next = (sn * tc + cs * ts, cs * tc - sn * ts);
            *angle = Some(next);
            Phase::stick_switch(s, point, phase.stick_state(s, next))
        }
        (Mode::Stick, _) => {
            let now = (s.omega_t * (b - start)).sin_cos();
            *angle = Some(now);
            Phase::stick_switch(s, point, phase.stick_state(s, now))
        }
        (Mode::Slip(_), _) => phase.switch(s, point, b),
    }
}

/// A phase's switch function on the exact flow `path`, and the tolerance of Brent's roots on
/// it.
struct OnFlow<'a, M> {
    path: &'a M,
    s: &'a Scaled,
    phase: &'a Phase,
    tol: f64,
}

impl<M: NormalMotion> OnFlow<'_, M> {
    /// The crossing of the switch function in [a, b] (G(a) = `ga` < 0 < G(b) = `gb`): by
    /// safeguarded Newton on the flow's series, G' exact (a slide's from F̄''), else by Brent
    /// on the flow.
    fn crossing(&self, (a, ga): (f64, f64), (b, gb): (f64, f64)) -> f64 {
        let OnFlow {
            path,
            s,
            phase,
            tol,
        } = *self;
        match path.local(a, b) {
            Some(l) => newton_bracketed_from(
                |t| {
                    let (p, curvature) = l.at_with_curvature(t);
                    phase.switch_rate(s, &p, curvature, t)
                },
                (a, ga),
                (b, gb),
            ),
            None => brent(|t| phase.switch(s, &path.at(t), t).0, a, b, ga, gb, tol),
        }
    }

    /// The peak of a stick's k̃|u| − μF̄ in [a, b], where its rate goes from `da` > 0 to
    /// `db` < 0: (τ, G) there. On [a, b] the flow's series when it has one (a few dozen
    /// multiply-adds a reading).
    fn stick_peak(&self, (a, da): (f64, f64), (b, db): (f64, f64)) -> (f64, f64) {
        let OnFlow {
            path,
            s,
            phase,
            tol,
        } = *self;
        let local = path.local(a, b);
        let g = move |t: f64| match &local {
            Some(l) => phase.switch(s, &l.at(t), t),
            None => phase.switch(s, &path.at(t), t),
        };
        let tm = brent(|t| g(t).1, a, b, da, db, tol);
        let (gm, _) = g(tm);
        (tm, gm)
    }
}

/// A point in (start, b) where the switch function is negative, when the first step already
/// ends above zero (a switch tangent at the phase's start).
fn probe_below(g: &impl Fn(f64) -> f64, start: f64, b: f64) -> Option<(f64, f64)> {
    (1..48).find_map(|j| {
        let c = start + (b - start) * 0.5f64.powi(j);
        let gc = g(c);
        (gc < 0.0).then_some((c, gc))
    })
}
