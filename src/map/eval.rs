//! Evaluating a map: one cell through the solver `run` uses, and the coarse-to-fine passes on
//! all cores (rayon), which a caller can stop between passes or, with a flag, inside one.

use super::{Cell, Map, MapSpec};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{SolveError, SolveOptions, simulate};
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};

/// One cell at (λ, ζ): [`crate::simulate`] with the default options, as `bouncelab run`
/// solves (its energy audit changes neither solver's COR, F_m or t_f). The linear law runs
/// the exact solver, the others the adaptive one. On the fast path the linear law's closed
/// form runs in lanes (`cells_at`'s, the lane padded with copies of itself; a flattening
/// cell on a lane of width one, [`super::fast::lanes::flattening_one`]), so a cell alone is
/// the map's cell bit for bit (`one_cell_is_the_maps_cell`).
pub fn cell_at(spec: &MapSpec, lambda: f64, zeta: f64) -> Result<Cell, SolveError> {
    let mut out = [Ok(Cell::UNRESOLVED)];
    cells_at(spec, &[(lambda, zeta)], &mut out);
    let [c] = out;
    c
}

/// [`cell_at`] of each (λ, ζ), into `out` (of the same length): on the linear law's fast
/// path eight cells a call in two registers of four ([`super::fast::lanes::summaries`],
/// issue 30 item 3), each lane's answer a function of its own (λ, ζ) only — the same in any grouping, so
/// the coarse-to-fine passes and a lone [`cell_at`] agree bit for bit.
pub fn cells_at(spec: &MapSpec, points: &[(f64, f64)], out: &mut [Result<Cell, SolveError>]) {
    assert_eq!(points.len(), out.len());
    let params: Vec<ImpactParams> = points.iter().map(|&(l, z)| spec.params_at(l, z)).collect();
    let closed = if spec.law == ContactLaw::Linear && spec.fast {
        let norm: Vec<_> = params.iter().map(ImpactParams::normalized).collect();
        let lambda: Vec<f64> = norm.iter().map(|n| n.lambda).collect();
        let zeta: Vec<f64> = norm.iter().map(|n| n.zeta).collect();
        let mut closed = vec![None; points.len()];
        super::fast::lanes::summaries(&lambda, &zeta, &mut closed);
        let zp: Vec<f64> = norm.iter().map(|n| n.zp_bar).collect();
        flattening_in_lanes(&lambda, &zeta, &zp, &mut closed);
        closed
    } else if spec.law != ContactLaw::Linear && spec.fast_laws {
        // the table, and the rest's Taylor steps in lanes: `fast_cell`'s answer, the same bits
        let norm: Vec<_> = params.iter().map(ImpactParams::normalized).collect();
        let short = |t: crate::solver::taylor::Summary| super::fast::Summary {
            cor: t.cor,
            max_force: t.max_force,
            contact_time: t.contact_time,
        };
        let summaries = crate::solver::table::summaries(&norm, spec.law);
        summaries.into_iter().map(|s| s.map(short)).collect()
    } else {
        vec![None; points.len()]
    };
    for ((p, s), o) in params.iter().zip(closed).zip(out.iter_mut()) {
        *o = solve_cell(spec, p, s);
    }
}

/// Where the ball flattens (the no-flattening summary's peak passes z̄_p, or it does not
/// answer), `closed[i]` becomes the flattening closed form's answer, eight cells at a time
/// in lanes ([`super::fast::lanes::flattenings`], issue 30 item 2: one or two cells one by
/// one on a lane of width one, the same bits; `None` where neither the lanes nor the scalar
/// `flattening` answer): afterwards each `Some` is the cell's answer.
fn flattening_in_lanes(
    lambda: &[f64],
    zeta: &[f64],
    zp: &[f64],
    closed: &mut [Option<super::fast::Summary>],
) {
    let flat: Vec<usize> = (0..closed.len())
        .filter(|&i| !matches!(closed[i], Some(s) if s.max_force <= zp[i]))
        .collect();
    if flat.is_empty() {
        return;
    }
    let pick = |a: &[f64]| -> Vec<f64> { flat.iter().map(|&i| a[i]).collect() };
    let mut out = vec![None; flat.len()];
    super::fast::lanes::flattenings(&pick(lambda), &pick(zeta), &pick(zp), &mut out);
    for (&i, s) in flat.iter().zip(out) {
        closed[i] = s;
    }
}

/// One cell from the linear law's closed form `closed` where it answers (with flattening or
/// without: `flattening_in_lanes`),
/// else the fast paths of [`fast_cell`] where they are on, else the solvers.
fn solve_cell(
    spec: &MapSpec,
    params: &ImpactParams,
    closed: Option<super::fast::Summary>,
) -> Result<Cell, SolveError> {
    let fast = match spec.law {
        ContactLaw::Linear => spec.fast,
        _ => spec.fast_laws,
    };
    if fast && let Some(c) = fast_cell(spec, params, closed) {
        return Ok(c);
    }
    let r = simulate(params, spec.law, &SolveOptions::default())?;
    Ok(if spec.normalized {
        Cell {
            cor: r.cor,
            max_force: r.max_force_normalized,
            contact_time: r.contact_time_normalized,
        }
    } else {
        Cell {
            cor: r.cor,
            max_force: r.max_force,
            contact_time: r.contact_time,
        }
    })
}

/// The cell from a fast path when one answers: on the linear law the closed form `closed`
/// ([`super::fast::summary`]'s, in lanes) while the ball does not flatten (z̄_m ≤ z̄_p), the
/// flattening closed form ([`super::fast::flattening`], in lanes: `flattening_in_lanes`)
/// where it does and answers (`closed` holds either, resolved by `cells_at`), else the
/// Taylor steps ([`crate::solver::taylor::summary`]); under the Hertz and elastic–plastic
/// laws `closed` holds [`crate::solver::table::summaries`]' answer (the Hertz table, else the
/// Taylor steps in lanes), resolved by `cells_at` too.
/// SI as `to_si` converts: F = F̄ m v0 ω0, t = τ/ω0.
fn fast_cell(
    spec: &MapSpec,
    p: &ImpactParams,
    closed: Option<super::fast::Summary>,
) -> Option<Cell> {
    let n = p.normalized();
    let s = match closed {
        Some(s) => s,
        None if spec.law == ContactLaw::Linear => {
            let t = crate::solver::table::summary(&n, spec.law)?;
            super::fast::Summary {
                cor: t.cor,
                max_force: t.max_force,
                contact_time: t.contact_time,
            }
        }
        None => return None,
    };
    if spec.normalized {
        return Some(Cell {
            cor: s.cor,
            max_force: s.max_force,
            contact_time: Some(s.contact_time),
        });
    }
    let w0 = p.omega0();
    Some(Cell {
        cor: s.cor,
        max_force: s.max_force * p.mass * p.v0 * w0,
        contact_time: Some(s.contact_time / w0),
    })
}

/// Cells a pass hands to one core at a time: a multiple of the lanes' four, small enough that
/// a stop flag is seen within some microseconds on the closed form (a Hertz cell costs more:
/// a few hundred µs a group) and that both cores share a 200 × 60 screen's first pass.
const CHUNK: usize = 16;

/// What one pass did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Pass {
    /// The lattice stride of the pass: cells (i, j) with i and j multiples of it (1: every
    /// cell).
    pub stride: usize,
    /// Cells evaluated in this call.
    pub evaluated: usize,
    /// Whether the pass is complete (false when a flag stopped it: the next call goes on).
    pub complete: bool,
}

/// The whole map, every pass on all cores.
pub fn compute(spec: MapSpec) -> Map {
    let mut map = Map::new(spec);
    while map.refine().is_some() {}
    map
}

/// The first pass's stride: the power of two that leaves about eight values along the longer
/// axis, so the first picture costs some 80 impacts.
fn first_stride(n: usize) -> usize {
    let mut s = 1;
    while n / (2 * s) >= 8 {
        s *= 2;
    }
    s
}

impl Map {
    /// A map with no cell evaluated yet.
    pub fn new(spec: MapSpec) -> Map {
        let (lambdas, zetas) = (spec.lambda.values(), spec.zeta.values());
        let cells = vec![None; lambdas.len() * zetas.len()];
        let stride = first_stride(lambdas.len().max(zetas.len()));
        Map {
            spec,
            lambdas,
            zetas,
            cells,
            stride,
            done_stride: 0,
        }
    }

    /// This map (none of it evaluated yet) with a first pass of at most `cells` cells — never
    /// less than one, never finer than [`Map::new`]'s: a coarse full picture for a costly
    /// law, fast, before the finer passes (the explorer's map view under the Hertz law,
    /// src/tui/views/map/update.rs).
    pub fn first_cells_at_most(mut self, cells: usize) -> Map {
        let (nl, nz) = (self.lambdas.len(), self.zetas.len());
        let lattice = |s: usize| nl.div_ceil(s) * nz.div_ceil(s);
        if self.done_stride == 0 && self.cells.iter().all(Option::is_none) {
            while lattice(self.stride) > cells.max(1) && self.stride < nl.max(nz) {
                self.stride *= 2;
            }
        }
        self
    }

    /// The cells the next pass evaluates (its lattice's cells not yet evaluated); 0 once
    /// every cell is.
    pub fn next_pass_cells(&self) -> usize {
        let Some(s) = self.next_stride() else {
            return 0;
        };
        let nz = self.zetas.len();
        (0..self.cells.len())
            .filter(|&k| {
                (k / nz).is_multiple_of(s) && (k % nz).is_multiple_of(s) && self.cells[k].is_none()
            })
            .count()
    }

    /// The stride of the next pass; `None` once every cell is evaluated.
    pub fn next_stride(&self) -> Option<usize> {
        (self.stride > 0).then_some(self.stride)
    }

    /// Evaluate the next pass on all cores; `None` when the map was already complete.
    pub fn refine(&mut self) -> Option<Pass> {
        self.refine_until(&AtomicBool::new(false))
    }

    /// As [`Map::refine`], but each cell first looks at `cancel`: once it is set, the cells
    /// left are skipped and the pass returns incomplete (the next call takes it up again).
    pub fn refine_until(&mut self, cancel: &AtomicBool) -> Option<Pass> {
        let s = self.next_stride()?;
        let nz = self.zetas.len();
        let pending: Vec<usize> = (0..self.cells.len())
            .filter(|&k| {
                (k / nz).is_multiple_of(s) && (k % nz).is_multiple_of(s) && self.cells[k].is_none()
            })
            .collect();
        let spec = &self.spec;
        let (lambdas, zetas) = (&self.lambdas, &self.zetas);
        // groups of CHUNK cells over the cores, each through the lanes four at a time
        let found: Vec<(usize, Option<Cell>)> = pending
            .par_chunks(CHUNK)
            .flat_map_iter(|ks| {
                let stop = cancel.load(Ordering::Relaxed);
                let points: Vec<(f64, f64)> = ks
                    .iter()
                    .map(|&k| (lambdas[k / nz], zetas[k % nz]))
                    .collect();
                let mut out = vec![Ok(Cell::UNRESOLVED); ks.len()];
                if !stop {
                    cells_at(spec, &points, &mut out);
                }
                // the spec checked every parameter: only `Unresolved` is left
                ks.iter()
                    .zip(out)
                    .map(move |(&k, c)| (k, (!stop).then(|| c.unwrap_or(Cell::UNRESOLVED))))
            })
            .collect();
        let mut evaluated = 0;
        for (k, c) in found {
            if c.is_some() {
                evaluated += 1;
                self.cells[k] = c;
            }
        }
        let complete = evaluated == pending.len();
        if complete {
            self.done_stride = s;
            self.stride = s / 2;
        }
        Some(Pass {
            stride: s,
            evaluated,
            complete,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Axis, MapSpec, Param, Scale};
    use super::*;

    fn spec(n: usize) -> MapSpec {
        let l = Axis::new(Param::Lambda, 0.1, 10.0, n, Scale::Log).unwrap();
        let z = Axis::new(Param::Zeta, 0.01, 10.0, n, Scale::Log).unwrap();
        MapSpec::normalized(None, ContactLaw::Linear, l, z).unwrap()
    }

    /// Coarse to fine: each pass fills a lattice twice as fine, and the cells of a pass are
    /// the same as the one-shot map's.
    #[test]
    fn passes_refine_to_the_whole_map() {
        let mut m = Map::new(spec(33));
        let mut strides = Vec::new();
        assert!(m.nearest(5, 7).is_none());
        while let Some(p) = m.refine() {
            assert!(p.complete);
            strides.push(p.stride);
            assert!(m.nearest(32, 32).is_some() && m.nearest(31, 3).is_some());
        }
        assert_eq!(strides, vec![4, 2, 1]);
        assert_eq!(m.last_stride(), 1);
        assert!(m.is_complete() && m.cells().iter().all(Option::is_some));
        let whole = compute(spec(33));
        assert_eq!(m.cells(), whole.cells());
    }

    /// A first pass held to a number of cells is coarser, still covers the whole map, and
    /// the passes after it refine to the same map.
    #[test]
    fn a_first_pass_held_to_few_cells_still_covers_the_map() {
        let m = Map::new(spec(33)).first_cells_at_most(10);
        assert!(m.next_pass_cells() <= 10, "{}", m.next_pass_cells());
        assert!(Map::new(spec(33)).next_pass_cells() > 10);
        let mut m = m;
        m.refine();
        assert!((0..33).all(|i| (0..33).all(|j| m.nearest(i, j).is_some())));
        while m.refine().is_some() {}
        assert_eq!(m.cells(), compute(spec(33)).cells());
        // never finer than Map::new's
        assert_eq!(
            Map::new(spec(33))
                .first_cells_at_most(1_000_000)
                .next_stride(),
            Map::new(spec(33)).next_stride()
        );
    }

    /// A set flag stops a pass; the next call finishes it.
    #[test]
    fn a_flag_stops_a_pass_and_the_next_call_resumes() {
        let mut m = Map::new(spec(17));
        let stop = AtomicBool::new(true);
        let p = m.refine_until(&stop).unwrap();
        assert_eq!((p.evaluated, p.complete), (0, false));
        assert_eq!(m.next_stride(), Some(p.stride));
        let p2 = m.refine().unwrap();
        assert!(p2.complete && p2.evaluated > 0 && p2.stride == p.stride);
    }

    /// A lone cell is the map's cell bit for bit (the lanes' answers depend on their own
    /// (λ, ζ) only), on the closed form and where a dimensional ball flattens (the Taylor
    /// steps), and a pass's groups do not change a cell.
    #[test]
    fn one_cell_is_the_maps_cell() {
        let l = Axis::new(Param::Lambda, 0.1, 10.0, 7, Scale::Log).unwrap();
        let z = Axis::new(Param::Zeta, 0.02, 2.0, 5, Scale::Log).unwrap();
        let ball = crate::Ball::from_preset("tennis").unwrap();
        let specs = [
            spec(9).with_fast(true),
            MapSpec::dimensional(ball.params, ContactLaw::Linear, l, z)
                .unwrap()
                .with_fast(true),
        ];
        for s in specs {
            let m = compute(s.clone());
            let (ls, zs) = (s.lambda.values(), s.zeta.values());
            for (i, &lambda) in ls.iter().enumerate() {
                for (j, &zeta) in zs.iter().enumerate() {
                    let alone = cell_at(&s, lambda, zeta).unwrap();
                    assert_eq!(
                        m.cells()[i * zs.len() + j],
                        Some(alone),
                        "λ {lambda}, ζ {zeta}"
                    );
                }
            }
        }
    }

    /// The fast path's map equals the exact one to 1e-9 (away from where the pair turns
    /// real, 2e-12), with flattening (dimensional superball, which flattens at high λ) too.
    #[test]
    fn the_fast_map_agrees_with_the_exact_one() {
        let l = Axis::new(Param::Lambda, 0.1, 10.0, 7, Scale::Log).unwrap();
        let z = Axis::new(Param::Zeta, 0.02, 2.0, 7, Scale::Log).unwrap();
        let ball = crate::Ball::from_preset("superball")
            .unwrap()
            .with_v0(6.0)
            .unwrap();
        let specs = [
            spec(9),
            MapSpec::dimensional(ball.params, ContactLaw::Linear, l, z).unwrap(),
        ];
        for s in specs {
            let (a, b) = (compute(s.clone()), compute(s.with_fast(true)));
            for (x, y) in a.cells().iter().zip(b.cells()) {
                let (x, y) = (x.unwrap(), y.unwrap());
                for q in super::super::Quantity::ALL {
                    let (u, v) = (x.get(q), y.get(q));
                    assert!((u - v).abs() <= 1e-9 * u.abs(), "{q:?}: {u} vs {v}");
                }
            }
        }
    }
}
