//! The design map (issue 21): COR, peak force and contact time over a grid of (λ, ζ), with
//! targets on them, the feasible region, iso-lines and sensitivities. No I/O: plain data in,
//! plain data out; the command line (`bouncelab map`) and the explorer's map view are thin
//! layers on it (docs/map.md).
//!
//! A map varies the recoil spring and the dashpot of one ball and keeps the rest: K_r = λ K_p
//! and c = √(m K_p)/(2ζ), with m, K_p, z_p, K_h and v0 held (Eq. 24) — the normalized ball
//! (m = K_p = v0 = 1, optionally with a flattening threshold z̄_p), or a dimensional ball at
//! its v0, flattening included. Each cell is exactly what [`crate::simulate`] (and so
//! `bouncelab run --lambda L --zeta Z`) gives at that (λ, ζ).
//!
//! ```
//! use bouncelab::map::{Axis, MapSpec, Param, Quantity, Scale, Targets, compute};
//! use bouncelab::ContactLaw;
//!
//! let lambda = Axis::new(Param::Lambda, 0.1, 10.0, 9, Scale::Log)?;
//! let zeta = Axis::parse(Param::Zeta, "0.01:1:9", Scale::Log)?;
//! let spec = MapSpec::normalized(None, ContactLaw::Linear, lambda, zeta)?;
//! let map = compute(spec);
//! let e = map.cell(8, 0).unwrap().cor; // λ = 10, ζ = 0.01: a nearly elastic bounce
//! assert!(e > 0.9);
//! let targets = Targets::parse("cor>=0.8")?;
//! let ok = map.feasible(&targets);
//! assert!(ok[8 * 9]);
//! let iso = map.contours(Quantity::Cor, 0.8); // the iso-COR line of a target COR
//! assert!(!iso.is_empty());
//! # Ok::<(), bouncelab::map::MapError>(())
//! ```
//!
//! Coarse to fine: [`Map::new`] evaluates nothing; each [`Map::refine`] evaluates one pass (a
//! lattice twice as fine as the one before, on all cores) and returns; the caller draws
//! between passes ([`Map::nearest`] fills the cells not yet evaluated from the coarse lattice)
//! and stops when it likes. [`Map::refine_until`] also stops inside a pass once a flag is
//! set; the next call takes the pass up where it stopped. For the linear law,
//! [`MapSpec::with_fast`] takes the closed form of [`fast`] (six to eight times faster, within
//! 1e-12 of the exact solver) wherever it answers.

mod axis;
mod contour;
pub mod csv;
mod eval;
pub mod fast;
mod sensitivity;
mod target;

pub use axis::{Axis, MAX_AXIS_POINTS, MAX_CELLS, Param, Scale};
pub use contour::{Contour, contour_lines};
pub use eval::{Pass, cell_at, compute};
pub use sensitivity::{Sensitivity, sensitivity};
pub use target::{Bound, Constraint, Targets, unmet_warning};

use crate::api::BallError;
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use serde::Serialize;

/// Why a map cannot be set up. Each message is one line naming what is at fault.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MapError {
    /// An axis given out of its domain (`axis` is `lambda` or `zeta`, as the flags).
    #[error("invalid {axis}: '{text}' ({reason})")]
    Axis {
        /// `lambda` or `zeta`.
        axis: &'static str,
        /// The axis as given.
        text: String,
        /// Why it is refused.
        reason: String,
    },
    /// More cells than [`MAX_CELLS`].
    #[error("invalid grid: {lambdas} λ values × {zetas} ζ values is {cells} cells (at most {max})", max = MAX_CELLS)]
    TooLarge {
        /// λ values asked for.
        lambdas: usize,
        /// ζ values asked for.
        zetas: usize,
        /// Their product.
        cells: usize,
    },
    /// A part of a targets text that does not read (`part` is the part, as given).
    #[error("invalid where: '{part}' ({reason})")]
    Target {
        /// The part, as given.
        part: String,
        /// Why it does not read.
        reason: String,
    },
    /// The ball, or a K_r or c an axis end gives it, is out of its domain.
    #[error(transparent)]
    Ball(#[from] BallError),
}

/// What a map shows in each cell.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Quantity {
    /// The coefficient of restitution e (Eq. 6).
    Cor,
    /// Peak force: F̄_m on a normalized map, N on a dimensional one.
    MaxForce,
    /// Contact time: τ_f on a normalized map, s on a dimensional one (none without rebound).
    ContactTime,
}

impl Quantity {
    /// Every quantity, in the order the outputs list them.
    pub const ALL: [Quantity; 3] = [Quantity::Cor, Quantity::MaxForce, Quantity::ContactTime];

    /// `cor`, `max_force`, `contact_time`: the names targets use.
    pub fn name(self) -> &'static str {
        match self {
            Quantity::Cor => "cor",
            Quantity::MaxForce => "max_force",
            Quantity::ContactTime => "contact_time",
        }
    }
}

/// One cell's answer. On a normalized map the force and time are F̄_m and τ_f; on a
/// dimensional one N and s. Where the solver had no answer (`SolveError::Unresolved`), the
/// COR and force are NaN.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Cell {
    /// The COR e (Eq. 6).
    pub cor: f64,
    /// Peak force: F̄_m (normalized) or N.
    pub max_force: f64,
    /// `None` when the ball does not rebound (or the solver had no answer).
    pub contact_time: Option<f64>,
}

impl Cell {
    /// A cell whose impact had no answer.
    pub const UNRESOLVED: Cell = Cell {
        cor: f64::NAN,
        max_force: f64::NAN,
        contact_time: None,
    };

    /// The quantity's value; NaN for a contact time that does not exist.
    pub fn get(&self, q: Quantity) -> f64 {
        match q {
            Quantity::Cor => self.cor,
            Quantity::MaxForce => self.max_force,
            Quantity::ContactTime => self.contact_time.unwrap_or(f64::NAN),
        }
    }
}

/// What a map evaluates: the ball whose K_r and c vary, its contact law, and the axes.
#[derive(Debug, Clone, PartialEq)]
pub struct MapSpec {
    /// The ball; its K_r and c are replaced in each cell, the rest held.
    pub base: ImpactParams,
    /// Whether the cells report F̄_m and τ_f (the normalized ball) or N and s.
    pub normalized: bool,
    /// The contact law of every cell.
    pub law: ContactLaw,
    /// The λ values (rows).
    pub lambda: Axis,
    /// The ζ values (columns).
    pub zeta: Axis,
    /// Linear law only: take [`fast::summary`] (closed form, six to eight times faster; in
    /// lanes, four cells at a time: [`fast::lanes`], docs/map.md) wherever it answers and the
    /// ball does not flatten; the exact solver elsewhere. It answers only
    /// where its rounding bound keeps 1e-13, and agrees with the exact solver (`run`) to 1e-12
    /// there (tests/physics/map_precision.rs, a dense grid and the turning points). A flattening ball
    /// takes the Taylor steps of [`crate::solver::taylor`] within their domain, which keep
    /// 1e-12 against the exact solver too (tests/physics/taylor.rs). `bouncelab map` and the explorer
    /// turn it on. Off by default: each cell then is `run`'s own answer.
    pub fast: bool,
    /// The Hertz and elastic–plastic laws: take the Taylor steps of [`crate::solver::taylor`]
    /// within their domain, the adaptive solver elsewhere. They agree with the adaptive
    /// solver to 1e-9 (its own precision at rtol 1e-10, `run`'s) and with it at rtol 1e-14 to
    /// 1e-12 (tests/physics/taylor.rs): a cell is then not `run`'s to the last digits but closer to
    /// the exact answer. `bouncelab map` and the explorer turn it on.
    pub fast_laws: bool,
}

impl MapSpec {
    /// The same map with the fast linear-law path on or off (see [`MapSpec::fast`]).
    pub fn with_fast(mut self, fast: bool) -> MapSpec {
        self.fast = fast;
        self
    }

    /// The same map with the Taylor steps for the Hertz and elastic–plastic laws on or off
    /// (see [`MapSpec::fast_laws`]).
    pub fn with_fast_laws(mut self, fast: bool) -> MapSpec {
        self.fast_laws = fast;
        self
    }

    /// The normalized ball (m = K_p = v0 = 1), with flattening at z̄_p when given: each cell is
    /// `bouncelab run --normalized [--zp-bar Z] --lambda L --zeta Z`.
    pub fn normalized(
        zp_bar: Option<f64>,
        law: ContactLaw,
        lambda: Axis,
        zeta: Axis,
    ) -> Result<MapSpec, MapError> {
        let ball = crate::Ball::normalized(lambda.from, zeta.from, zp_bar, law)?;
        MapSpec::build(ball.params, true, law, lambda, zeta)
    }

    /// A dimensional ball at its own v0 (flattening included): each cell is `bouncelab run
    /// --preset P --lambda L --zeta Z`. A K_r or c out of its domain at an axis end is named by
    /// the λ or ζ that gives it.
    pub fn dimensional(
        params: ImpactParams,
        law: ContactLaw,
        lambda: Axis,
        zeta: Axis,
    ) -> Result<MapSpec, MapError> {
        params.validate().map_err(BallError::Param)?;
        MapSpec::build(params, false, law, lambda, zeta)
    }

    fn build(
        base: ImpactParams,
        normalized: bool,
        law: ContactLaw,
        lambda: Axis,
        zeta: Axis,
    ) -> Result<MapSpec, MapError> {
        let cells = lambda.n.saturating_mul(zeta.n);
        if cells > MAX_CELLS {
            return Err(MapError::TooLarge {
                lambdas: lambda.n,
                zetas: zeta.n,
                cells,
            });
        }
        // K_r grows with λ and c falls with ζ: the four corners bound every cell's
        for l in [lambda.from, lambda.to] {
            for z in [zeta.from, zeta.to] {
                let mut p = base;
                crate::api::set_lambda_zeta(&mut p, Some(l), Some(z))?;
            }
        }
        Ok(MapSpec {
            base,
            normalized,
            law,
            lambda,
            zeta,
            fast: false,
            fast_laws: false,
        })
    }

    /// The ball's parameters at (λ, ζ): K_r = λ K_p, c = √(m K_p)/(2ζ), as `run --lambda
    /// --zeta` sets them.
    pub fn params_at(&self, lambda: f64, zeta: f64) -> ImpactParams {
        self.base.with_lambda_zeta(lambda, zeta)
    }

    /// Cells in the map.
    pub fn cells(&self) -> usize {
        self.lambda.n * self.zeta.n
    }
}

/// A map being evaluated or evaluated: cell (i, j) is λ = `lambdas[i]`, ζ = `zetas[j]`,
/// stored at `i * zetas.len() + j` (rows of λ, as `sweep zeta` groups its rows).
#[derive(Debug, Clone, PartialEq)]
pub struct Map {
    /// What is evaluated.
    pub spec: MapSpec,
    /// The λ axis' values.
    pub lambdas: Vec<f64>,
    /// The ζ axis' values.
    pub zetas: Vec<f64>,
    /// `None` until evaluated.
    cells: Vec<Option<Cell>>,
    /// The lattice stride of the next pass; 0 once every cell is evaluated.
    stride: usize,
    /// The stride of the last complete pass (the lattice [`Map::nearest`] reads); 0 before.
    done_stride: usize,
}

impl Map {
    /// Cell (i, j) if it has been evaluated.
    pub fn cell(&self, i: usize, j: usize) -> Option<Cell> {
        self.cells[i * self.zetas.len() + j]
    }

    /// Every cell in storage order (`None`: not evaluated yet).
    pub fn cells(&self) -> &[Option<Cell>] {
        &self.cells
    }

    /// Cell (i, j), or while it is not evaluated yet the one of the last complete pass's
    /// lattice that covers it (for a coarse picture); `None` before the first pass.
    pub fn nearest(&self, i: usize, j: usize) -> Option<Cell> {
        self.cell(i, j).or_else(|| {
            let s = self.done_stride;
            (s > 0).then(|| self.cell(i - i % s, j - j % s)).flatten()
        })
    }

    /// The stride of the last complete pass (1 once complete; 0 before the first): the
    /// lattice [`Map::nearest`] fills from.
    pub fn last_stride(&self) -> usize {
        self.done_stride
    }

    /// Whether every cell is evaluated.
    pub fn is_complete(&self) -> bool {
        self.stride == 0
    }

    /// One quantity over the grid in storage order; NaN where it is not evaluated, had no
    /// answer, or does not exist (the contact time of a ball that does not rebound).
    pub fn field(&self, q: Quantity) -> Vec<f64> {
        self.cells
            .iter()
            .map(|c| c.map_or(f64::NAN, |c| c.get(q)))
            .collect()
    }

    /// Which cells meet every target (storage order); a cell not evaluated meets none.
    pub fn feasible(&self, targets: &Targets) -> Vec<bool> {
        self.cells
            .iter()
            .map(|c| c.is_some_and(|c| targets.holds(&c)))
            .collect()
    }

    /// The iso-lines of a quantity at `level`, as polylines in (λ, ζ) (marching squares over
    /// the evaluated cells; a square with a cell missing or NaN is skipped).
    pub fn contours(&self, q: Quantity, level: f64) -> Vec<Contour> {
        let field = self.field(q);
        contour_lines(&field, self.lambdas.len(), self.zetas.len(), level)
            .into_iter()
            .map(|line| line.on_axes(&self.spec.lambda, &self.spec.zeta))
            .collect()
    }

    /// The boundary of the feasible region: the 0.5 level of the feasible mask, in (λ, ζ).
    pub fn feasible_outline(&self, targets: &Targets) -> Vec<Contour> {
        let mask: Vec<f64> = self
            .feasible(targets)
            .iter()
            .map(|&f| if f { 1.0 } else { 0.0 })
            .collect();
        contour_lines(&mask, self.lambdas.len(), self.zetas.len(), 0.5)
            .into_iter()
            .map(|line| line.on_axes(&self.spec.lambda, &self.spec.zeta))
            .collect()
    }
}
