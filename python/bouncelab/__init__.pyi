"""Type stubs of bouncelab (the functions live in the native module bouncelab._native)."""

from typing import Any, Literal, Optional, Sequence, TypedDict, Union

import os

from typing_extensions import NotRequired, Unpack

import numpy as np
import numpy.typing as npt

Law = Literal["linear", "elastic-plastic", "hertz"]
ParamSet = Literal["adopted", "materials"]
# one number, a sequence of numbers or a 1-D numpy array of any real dtype
Floats = Union[float, Sequence[float], npt.NDArray[Union[np.floating[Any], np.integer[Any]]]]
Array = npt.NDArray[np.float64]
# ``surface=``: a surface's name (``bouncelab surfaces``), or a dict of its numbers over the
# named one's (keys ``name``, ``stiffness``, ``damping``, ``mass``, ``friction``,
# ``tangential_stiffness``, ``tangential_damping``: the last three for oblique, court and shot
# only; docs/surfaces.md, docs/python.md)
SurfaceArg = Union[str, dict[str, Any]]

class BallArguments(TypedDict, total=False):
    """The keyword arguments of every function that runs a preset ball, each None (or absent)
    to keep the preset's (python/src/arguments/ball.rs): the command line's overrides ``--mass``,
    ``--radius``, ``--k-p``, ``--damping``, ``--k-r``, ``--z-p`` (SI) and its conditions
    (docs/model.md §10, inflated balls only but ``temperature``): ``pressure`` (Pa gauge, or
    with its unit: ``"0.8bar"``, ``"8psi"``, ``"55kPa"``), ``temperature`` and ``inflated_at``
    (°C), ``after`` the time since inflation and ``half_life`` the leak's (s, or with a unit:
    ``"72h"``, ``"30d"``)."""
    mass: Optional[float]
    radius: Optional[float]
    k_p: Optional[float]
    damping: Optional[float]
    k_r: Optional[float]
    z_p: Optional[float]
    pressure: Optional[Union[float, str]]
    temperature: Optional[float]
    inflated_at: Optional[float]
    after: Optional[Union[float, str]]
    half_life: Optional[Union[float, str]]

class BallRecord(TypedDict):
    """The ball an answer ran, as the JSON's ``ball`` object (docs/cli.md, "The ball
    object"): ``overrides`` lists what the call changed from the preset, ``kept`` (only with
    an override) what it kept; c and z_p None when infinite."""
    name: Optional[str]
    origin: str
    law: str
    mass: float
    radius: Optional[float]
    k_p: float
    c: Optional[float]
    k_r: float
    z_p: Optional[float]
    k_h: float
    inertia_factor: float
    overrides: list[str]
    kept: NotRequired[list[str]]

class Conditions(TypedDict):
    """The conditions an answer ran at (the JSON's ``conditions``): °C, Pa gauge at that
    temperature (None for a solid ball), Pa."""
    temperature_c: Optional[float]
    pressure_gauge_pa: Optional[float]
    atmosphere_pa: float

class SurfaceObject(TypedDict):
    """The surface an answer ran on, as the JSON's ``surface`` object (docs/surfaces.md), but
    ``inf`` where the JSON writes null: K_s (N/m) of a rigid surface, M (kg) of a fixed one;
    μ, K_t, c_t None where neither the surface nor the call gives them, or the answer uses
    none (a normal impact); ``overrides`` what the call changed of the surface's own."""
    name: str
    origin: str
    stiffness: float
    damping: float
    mass: float
    friction: Optional[float]
    tangential_stiffness: Optional[float]
    tangential_damping: Optional[float]
    overrides: list[str]

class Pair(TypedDict):
    """The other ball of a pair (``collide(target_preset=…)``), as the JSON's ``pair``: its
    preset, m_eff (kg) and R_eff (m), and its ball object and conditions as every answer's."""
    preset: str
    effective_mass: float
    effective_radius: Optional[float]
    ball: BallRecord
    conditions: Conditions

class _Named(TypedDict):
    """The keys naming the ball in every answer."""
    preset: Optional[str]
    origin: str
    parameters: str
    law: str

class NoAnswerError(ValueError):
    """The solver ran out of its step budget: no answer (the command line's exit code 1)."""

class Measured(TypedDict):
    v0: float
    cor: Optional[float]
    max_force: Optional[float]
    contact_time: Optional[float]

class Energy(TypedDict):
    initial_kinetic: float
    final_kinetic: float
    dashpot: float
    contact: float
    spring: float
    relative_residual: float

class Impact:
    """One impact, SI units; the attributes are the keys of ``bouncelab run --format json``."""

    preset: Optional[str]
    origin: str
    parameters: str
    law: str
    method: str
    mass: float
    k_p: float
    k_r: float
    c: float
    z_p: float
    k_h: float
    v0: float
    lambda_: float
    zeta: float
    zp_bar: float
    radius: Optional[float]
    poisson_ratio: Optional[float]
    cor: float
    rebound: bool
    max_force: float
    contact_time: Optional[float]
    max_indentation: float
    permanent_indentation: float
    max_force_normalized: float
    contact_time_normalized: Optional[float]
    @property
    def warnings(self) -> list[str]:
        """What the caller should know about this answer (an indentation beyond the ball's
        radius, an energy balance that does not close); ``[]`` when nothing. With ``energy``,
        the exact solver's audit, run on first read after a closed-form answer
        (docs/python.md)."""
    @property
    def measured(self) -> Optional[Measured]: ...
    @property
    def ball(self) -> BallRecord:
        """The ball it ran, as the JSON's ``ball`` object."""
    @property
    def comparison_withheld(self) -> Optional[str]:
        """Why the answer is not compared with ``measured`` (an override or a condition
        changed the ball, or it ran on another surface than the measurement's), else None."""
    @property
    def uncalibrated_outputs(self) -> Optional[list[str]]:
        """The outputs the ball's record does not vouch for, by their keys (``max_force``,
        ``contact_time``, …): the model's alone; None when the record makes no claim."""
    @property
    def conditions(self) -> Conditions:
        """The conditions it ran at, as the JSON's ``conditions``."""
    @property
    def surface(self) -> SurfaceObject:
        """The surface it ran on, as the JSON's ``surface`` object (docs/surfaces.md)."""
    @property
    def energy(self) -> Optional[Energy]:
        """The energy budget (J), the exact solver's audit (docs/python.md)."""
    @property
    def t(self) -> Optional[Array]:
        """Times (s), with ``history=True``."""
    @property
    def force(self) -> Optional[Array]:
        """F(t) (N), with ``history=True``."""
    @property
    def indentation(self) -> Optional[Array]:
        """z(t) (m), with ``history=True``."""
    @property
    def displacement(self) -> Optional[Array]:
        """α(t) (m), with ``history=True``."""
    @property
    def cor_ci95(self) -> Optional[tuple[float, float]]:
        """The COR's 95 % interval on a preset saved by ``fit --save``, else None."""
    @property
    def max_force_ci95(self) -> Optional[tuple[float, float]]:
        """The peak force's 95 % interval (N) on a fitted preset, else None."""
    @property
    def contact_time_ci95(self) -> Optional[tuple[float, float]]:
        """The contact time's 95 % interval (s) on a fitted preset, else None."""
    def __eq__(self, other: object) -> bool:
        """Equal values (every attribute; the history arrays element by element)."""
    def __reduce__(self) -> tuple: ...
    def to_dict(self) -> dict:
        """The keys of ``bouncelab run --format json`` (``lambda``, not ``lambda_``)."""

class Preset(TypedDict):
    """One preset, as ``bouncelab presets --format json`` lists it."""
    name: str
    origin: str
    description: str
    law: Law
    parameters: ParamSet
    zeta: float
    v0: float
    radius: float
    poisson_ratio: float
    inertia_factor: float
    calibration: Optional[dict[str, Any]]
    aerodynamics: Optional[Literal["tennis", "baseball", "golf"]]

def presets() -> list[Preset]:
    """Embedded and user presets, as ``bouncelab presets --format json`` (``lambda`` and
    ``zeta`` too: λ cannot be spelled here, a Python keyword); ``calibration`` the preset's
    record (docs/presets.md, "The calibration record"), None without one; ``aerodynamics``
    the published flight model it flies on (docs/flight.md §2), None for the assumed sphere."""

def run(
    preset: str = "superball",
    law: Optional[Law] = None,
    v0: Optional[float] = None,
    lambda_: Optional[float] = None,
    zeta: Optional[float] = None,
    history: bool = False,
    samples: Optional[int] = None,
    params: Optional[ParamSet] = None,
    *,
    surface: Optional[SurfaceArg] = None,
    **ball: Unpack[BallArguments],
) -> Impact:
    """One impact of a preset, as ``bouncelab run --preset NAME``, the ball changed by
    :class:`BallArguments` as on the command line (overrides, then conditions)."""

def run_normalized(
    lambda_: float = 1.0,
    zeta: float = 0.1,
    zp_bar: Optional[float] = None,
    law: Law = "linear",
    history: bool = False,
    samples: Optional[int] = None,
) -> Impact:
    """One impact of the normalized ball (m = K_p = v0 = 1), as ``run --normalized``."""

def run_params(
    *,
    m: float,
    k_p: float,
    c: float,
    k_r: float,
    v0: float,
    z_p: float = float("inf"),
    k_h: Optional[float] = None,
    law: Law = "linear",
    history: bool = False,
    samples: Optional[int] = None,
) -> Impact:
    """One impact of a ball given by its parameters (SI); z_p = inf: no flattening."""

def impacts(
    *,
    m: Floats,
    k_p: Floats,
    c: Floats,
    k_r: Floats,
    v0: Floats,
    z_p: Optional[Floats] = None,
    k_h: Optional[Floats] = None,
    law: Law = "linear",
) -> dict[str, Array]:
    """Many impacts (SI), the arguments broadcast as a ufunc's: arrays of the broadcast shape
    ``cor``, ``max_force``, ``contact_time`` (NaN without rebound), ``max_indentation``,
    ``permanent_indentation`` and ``rebound`` (bool); element i is ``run_params``'s answer (to
    1e-9 under the Hertz and elastic-plastic laws: the Hertz table and the Taylor steps,
    docs/numerics.md). The work limit (docs/guarantees.md) counts each element by the path
    that answers it: ten linear-law elements as one impact; forty the Hertz table answers
    (under Hertz where it holds the ball, elastic-plastic where the impact also stays below
    yield); twenty elastic-plastic ones past yield (the Taylor steps); an element outside the
    table as a whole impact. A ``ValueError`` beyond it, raised after the table's own
    answers and before anything else runs."""

def sweep_zeta(lambdas: Floats, zetas: Floats, law: Law = "linear") -> dict[str, Array]:
    """COR, F̄_m, τ_f against ζ per λ (columns of ``bouncelab sweep zeta``)."""

def sweep_velocity(
    preset: str = "superball",
    speeds: Optional[Floats] = None,
    law: Optional[Law] = None,
    params: Optional[ParamSet] = None,
    **ball: Unpack[BallArguments],
) -> dict[str, Any]:
    """COR, F_m, t_f, z_f against v0 (columns of ``bouncelab sweep velocity``), and the JSON's
    ``max_indentation`` (an array), ``warnings`` (a list of lists of str, one a speed: a
    peak indentation past the ball's radius) and ``uncalibrated_outputs`` (the outputs the
    ball's record does not vouch for, None when it makes no claim)."""

def fit(
    cor: float,
    preset: str = "superball",
    v0: Optional[float] = None,
    law: Optional[Law] = None,
    params: Optional[ParamSet] = None,
    **ball: Unpack[BallArguments],
) -> dict:
    """K_r and λ that give a measured COR (keys of ``bouncelab fit --format json``, with its
    ``warnings``: the fitted ball pressed past its radius at the data's speed)."""

FreeParam = Literal["k_p", "c", "k_r", "z_p", "k_h"]

class Estimate(TypedDict):
    value: float
    std_error: float
    ci95: tuple[float, float]

class LackOfFit(TypedDict):
    """The residuals' test (docs/fitting.md, "Lack of fit"): the runs test's z or χ², and the
    one-sided p-value."""
    test: Literal["runs", "chi2"]
    statistic: float
    p_value: float

class DropAir(TypedDict):
    drag_coefficient: float
    air_density: float

class _MultiFitKeys(TypedDict, total=False):
    data: str
    free: list[str]
    k_p: float
    c: float
    k_r: float
    z_p: float
    k_h: float
    zeta: float
    rms_residual: float
    condition_number: float
    points: int
    converged: bool
    iterations: int
    fitted: dict[str, Estimate]
    correlation: dict[str, dict[str, float]]
    time_offset: float
    nuisance: dict[str, Estimate]
    warnings: list[str]
    identified: bool
    not_pinned: list[str]
    on_bound: list[str]
    lack_of_fit: Optional[LackOfFit]
    exact: bool
    sd_stated: bool
    v0: float
    target_cor: float
    cor: float
    max_force: float
    contact_time: Optional[float]
    model: Array
    drops: dict[str, Array]
    air: Optional[DropAir]
    ball: BallRecord
    surface: SurfaceObject
    conditions: Conditions

class MultiFit(_Named, _MultiFitKeys):
    """A multi-parameter fit: the keys of ``bouncelab fit --format json`` (SI), and
    ``model``, the model at each data point (N for a trace, COR for a table). The keys
    ``lambda`` (λ of the fitted ball) cannot be spelled here: a Python keyword."""

def fit_trace(
    time: Floats,
    force: Floats,
    *,
    preset: str = "superball",
    free: Optional[Union[str, Sequence[FreeParam]]] = None,
    v0: Optional[float] = None,
    law: Optional[Law] = None,
    params: Optional[ParamSet] = None,
    **ball: Unpack[BallArguments],
) -> MultiFit:
    """k_p, c, k_r (default; k_h for k_p on the Hertz law) fitted to a force–time trace (s, N),
    with the contact start and the baseline, as ``bouncelab fit --force-time FILE``; without
    ``v0`` the impact speed too (as ``free`` with "v0", a warning saying so first), as the
    command line fits it without ``--v0``."""

def fit_cor_table(
    v0: Floats,
    cor: Floats,
    *,
    cor_sd: Optional[Floats] = None,
    max_force: Optional[Floats] = None,
    contact_time: Optional[Floats] = None,
    preset: str = "superball",
    free: Optional[Union[str, Sequence[FreeParam]]] = None,
    law: Optional[Law] = None,
    params: Optional[ParamSet] = None,
    **ball: Unpack[BallArguments],
) -> MultiFit:
    """k_r, z_p (default, k_r alone below three points) fitted to COR against speed (NaN in
    the optional columns: not measured), as ``bouncelab fit --cor-table FILE``."""

def fit_drops(
    drop_heights: Floats,
    rebound_heights: Floats,
    *,
    preset: str = "superball",
    free: Optional[Union[str, Sequence[FreeParam]]] = None,
    drag_coefficient: Optional[float] = None,
    air_density: float = 1.204,
    law: Optional[Law] = None,
    params: Optional[ParamSet] = None,
    rebound_height_sd: Optional[float] = None,
    **ball: Unpack[BallArguments],
) -> MultiFit:
    """k_r, z_p fitted to drop tests (m), in vacuum or with quadratic drag, as ``bouncelab fit
    --drop-height H --rebound-height R …``, each drop weighed by its rebound height's reading
    (``rebound_height_sd``, m, when known: each COR's ``cor_sd`` and a χ² lack-of-fit test);
    ``drops`` adds each drop's v0 and COR (and ``cor_sd``); ``air`` the air they were taken
    in (None: vacuum, which ``bouncelab drop`` is not unless ``--no-drag``)."""

class ObliqueEstimate(TypedDict):
    value: float
    std_error: float
    ci95: list[float]

class _ObliqueFitSometimes(TypedDict, total=False):
    exact: bool  # only when true: as many rows as quantities, or every residual zero

class ObliqueFit(_Named, _ObliqueFitSometimes):
    """The keys of ``bouncelab fit --oblique FILE --format json`` (SI; ``file`` None for
    arrays): μ, K_t (and κ with spins) fitted, their intervals and the verdict."""
    data: str
    file: Optional[str]
    free: list[str]
    friction: float
    tangential_stiffness: float
    inertia_factor: float
    radius: float
    rms_vx: float
    rms_spin: Optional[float]
    rms_vy: float
    points: int
    converged: bool
    iterations: int
    condition_number: float
    fitted: dict[str, ObliqueEstimate]
    correlation: dict[str, dict[str, float]]
    warnings: list[str]
    identified: bool
    not_pinned: list[str]
    on_bound: list[str]
    ball: BallRecord
    surface: SurfaceObject
    conditions: Conditions

def fit_oblique(
    file: Optional[Union[str, os.PathLike[str]]] = None,
    *,
    v0: Optional[Floats] = None,
    angle_deg: Optional[Floats] = None,
    spin_in: Optional[Floats] = None,
    vx_out: Optional[Floats] = None,
    vy_out: Optional[Floats] = None,
    spin_out: Optional[Floats] = None,
    preset: str = "superball",
    law: Optional[Law] = None,
    params: Optional[ParamSet] = None,
    **ball: Unpack[BallArguments],
) -> ObliqueFit:
    """μ and K_t (and κ when ``spin_out`` is given) fitted to oblique bounces, as ``bouncelab
    fit --oblique FILE``: a CSV file ``v0,angle_deg,spin_in,vx_out,vy_out[,spin_out]`` or the
    same columns as arrays (m/s, degrees, rad/s). Bad rows raise ``ValueError`` naming
    FILE:LINE:COLUMN (arrays: the row and column); check ``identified`` as the command line's
    exit code does."""

class StandardTest(TypedDict, total=False):
    """What a standard measures: ``kind`` "drop" (``height`` m to ``drop_ref``, the rebound
    read at ``rebound_ref``: "bottom" or "top"), "cor" and "bbcor" (``speed`` m/s),
    "court-pace" (``speed`` m/s at ``angle_deg``), "pressure-loss" (``hours`` at
    ``temperature`` °C from ``pressure`` Pa gauge)."""
    kind: Literal["drop", "cor", "bbcor", "court-pace", "pressure-loss"]
    height: float
    drop_ref: Literal["bottom", "top"]
    rebound_ref: Literal["bottom", "top"]
    speed: float
    angle_deg: float
    hours: float
    pressure: float
    temperature: float

class StandardConditions(TypedDict):
    """A test's conditions as its rule states them: ``temperature_c`` [nominal, ±] °C and
    ``pressure_gauge_pa`` [lo, hi] Pa, None where the rule states none, and their ``source``."""
    temperature_c: Optional[list[float]]
    pressure_gauge_pa: Optional[list[float]]
    source: str

class Standard(TypedDict, total=False):
    """One governing body's test, as ``bouncelab standards --format json`` lists it."""
    name: str
    title: str
    test: StandardTest
    surface: str
    window: list[Optional[float]]
    categories: list[float]
    balls: list[str]
    source: str
    unconfirmed: Optional[str]
    conditions: StandardConditions

def standards() -> list[Standard]:
    """The standards, as ``bouncelab standards --format json``: the ball standards, the bat
    standards and the court pace, in one list. The names of kind "drop" and "cor" are what
    ``drop(standard=…)`` and ``batch(standard=…)`` take (docs/drop.md, "Standards", cites
    each source; ``unconfirmed`` says what a public source did not confirm)."""

class _DropStandardSometimes(TypedDict, total=False):
    # a static standard's (``itf-deformation``): its load, the return reading and the rules'
    # return window (load_kg, peak_m, return_deflection_m, return_reason, return_window,
    # return_inside)
    static: dict[str, Any]

class DropStandard(_DropStandardSometimes):
    """The verdict of ``bouncelab drop --standard NAME``: ``window`` [lo, hi] (m of rebound in
    the standard's convention, or a COR; None where the standard sets no bound), ``measured``
    in the same units, ``margin`` the distance to the nearer bound (positive inside),
    ``judged_at_height_m`` the standard's own drop height it was judged at (None for a COR
    test or a static one); a static standard's (``itf-deformation``: the forward deflection
    in m of the diameter, by the model's static chain) ``static`` report."""
    name: str
    window: list[Optional[float]]
    measured: float
    verdict: Literal["pass", "fail"]
    margin: float
    judged_at_height_m: Optional[float]

class _DropKeys(TypedDict):
    height: float
    drag: bool
    bounces: dict[str, Array]
    warnings: list[str]
    uncalibrated_outputs: Optional[list[str]]
    surface: SurfaceObject
    ball: BallRecord
    conditions: Conditions

class LeakVerdict(TypedDict):
    """``drop(standard="fifa-pressure-loss", half_life=…)``'s verdict on the ball's leak."""
    name: str
    hours: float
    max_loss: float
    half_life_h: float
    lost: float
    verdict: Literal["pass", "fail"]
    margin: float

class Drop(_DropKeys, total=False):
    """The keys of ``bouncelab drop --format json``; ``standard`` only when an impact or a
    static standard is named, ``pressure_loss`` only for a pressure-loss test."""
    standard: DropStandard
    pressure_loss: LeakVerdict

def drop(
    preset: str = "superball",
    height: Optional[float] = None,
    bounces: int = 10,
    min_rebound: float = 0.001,
    drag: bool = True,
    drag_coefficient: Optional[float] = None,
    air_density: Optional[float] = None,
    law: Optional[Law] = None,
    params: Optional[ParamSet] = None,
    standard: Optional[str] = None,
    *,
    surface: Optional[SurfaceArg] = None,
    **ball: Unpack[BallArguments],
) -> Drop:
    """A drop test, bounce by bounce, as ``bouncelab drop --format json``: released from rest at
    ``height`` (m, the bottom of the ball; default the standard's drop height, else 1 m);
    ``bounces`` holds arrays v_in, v_out, cor, rebound_height, contact_time, max_force, t_start
    (one entry a bounce; on a fitted preset also ``cor_ci95_lo``, ``cor_ci95_hi``, … for cor,
    max_force, contact_time, rebound_height); ``warnings`` what the caller should know. With
    ``standard`` (a name ``bouncelab standards`` lists, e.g. ``"itf"``), ``standard`` holds the
    verdict of that standard's own test (its drop height, or its COR speed) in this drop's air,
    whatever ``height`` says. Every standard ``drop --standard`` takes: a static one
    (``"itf-deformation"``) is judged on the model's static deflection, with its ``static``
    report; the pressure-loss test (``"fifa-pressure-loss"``) judges the leak of the
    ``half_life`` given (no other conditions: the test sets them) in ``pressure_loss`` and
    drops the ball after the test's time. No standard is judged unless named, as on the
    command line; a preset's own is the one whose ``balls`` list it in ``standards()``."""

class Collision:
    """A two-body impact, SI units: the keys of ``bouncelab collide --format json``."""

    ball: Optional[str]
    law: Law
    ball_mass: float
    ball_speed: float
    target_mass: float
    target_speed: float
    target_stiffness: float
    target_damping: float
    cor: float
    apparent_cor: float
    ball_speed_out: float
    target_speed_out: float
    max_force: float
    contact_time: Optional[float]
    reduced_mass: float
    closing_speed: float
    rebound: bool
    max_indentation: float
    permanent_indentation: float
    max_target_deflection: float
    method: Literal["exact", "numeric"]
    effective_mass: Optional[float]
    effective_radius: Optional[float]
    # the JSON's ``target.rigid``: False for a ball partner (its own chain deforms), though
    # its ``target_stiffness`` is inf (no surface of its own)
    target_rigid: bool
    # ball on ball (``target_preset``): the JSON's ``pair``, the partner named as every
    # answer names its ball; None otherwise
    pair: Optional[Pair]
    warnings: list[str]
    # None where the ball met another ball that deforms (``surface_note`` says so)
    surface: Optional[SurfaceObject]
    surface_note: Optional[str]
    ball_record: BallRecord  # the JSON's ``ball`` object: ``ball`` is the preset's name here
    conditions: Conditions
    def to_dict(self) -> dict:
        """The keys of ``bouncelab collide --format json``, the target's under ``target``
        (``mass``, ``speed``, ``stiffness``, ``damping``, ``rigid``; inf for the JSON's
        null), ``pair`` for a ball partner, ``surface_note`` where ``surface`` is None."""
    def __eq__(self, other: object) -> bool:
        """Equal values (every attribute)."""
    def __reduce__(self) -> tuple: ...

def collide(
    preset: str = "superball",
    v0: Optional[float] = None,
    target_mass: Optional[float] = None,
    target_speed: float = 0.0,
    target_stiffness: float = float("inf"),
    target_damping: float = 0.0,
    target_preset: Optional[str] = None,
    law: Optional[Law] = None,
    params: Optional[ParamSet] = None,
    *,
    surface: Optional[SurfaceArg] = None,
    **ball: Unpack[BallArguments],
) -> Collision:
    """The ball against a target of mass M (inf: the wall) moving at v_t toward it, rigid or
    with a surface K_s ∥ c_s, as ``bouncelab collide``; or against another preset ball
    (``target_preset``): both balls deform, their chains in series (docs/targets.md §8)."""

class ObliqueImpact:
    """An oblique impact, SI units; attributes are ``bouncelab oblique --format json``'s keys:
    the ball, the tangential model that ran (K_t as given, else Mindlin's from the preset's
    Poisson ratio; κ as given, else the preset's) and the answer."""

    preset: Optional[str]
    origin: str
    parameters: str
    law: Law
    friction: float
    tangential_stiffness: Optional[float]
    inertia_factor: float
    radius: Optional[float]
    v_in: float
    angle_in_deg: float
    spin_in: float
    vx_in: float
    vy_in: float
    v_out: float
    angle_out_deg: float
    spin_out: float
    vx_out: float
    vy_out: float
    cor_normal: float
    cor_tangential: Optional[float]
    apparent_friction: float
    slid_throughout: bool
    grip_time: float
    contact_time: float
    max_normal_force: float
    max_friction_force: float
    energy: dict[str, float]
    t: Optional[Array]
    normal_force: Optional[Array]
    friction_force: Optional[Array]
    slip_velocity: Optional[Array]
    spin: Optional[Array]
    warnings: list[str]
    tangential_damping: Optional[float]
    surface: SurfaceObject
    ball: BallRecord
    conditions: Conditions
    def to_dict(self) -> dict:
        """The keys of ``bouncelab oblique --format json``, the history arrays with a history."""
    def __eq__(self, other: object) -> bool:
        """Equal values (every attribute; the history arrays element by element)."""
    def __reduce__(self) -> tuple: ...

def oblique(
    preset: str = "superball",
    *,
    angle: float,
    friction: Optional[float] = None,
    v0: Optional[float] = None,
    spin: float = 0.0,
    tangential_stiffness: Optional[float] = None,
    inertia_factor: Optional[float] = None,
    law: Optional[Law] = None,
    params: Optional[ParamSet] = None,
    history: bool = False,
    samples: Optional[int] = None,
    surface: Optional[SurfaceArg] = None,
    tangential_damping: Optional[float] = None,
    **ball: Unpack[BallArguments],
) -> ObliqueImpact:
    """One oblique impact with friction and spin (docs/oblique.md), as ``bouncelab oblique``:
    angle to the surface in degrees (0 < angle ≤ 90), spin in rad/s (> 0 topspin); with
    ``history``, ``samples`` of it (2 … 100000, default 400; refused without ``history``, as
    ``run`` refuses it)."""

NetArg = Union[float, tuple[float, float]]
"""``net=``: a net's distance from the launch (m; its height the tennis net's 0.914 m at
the centre), or (distance, height): the command line's ``--net DISTANCE[,HEIGHT]``."""

class FlightArguments(BallArguments, total=False):
    """The keyword arguments ``shot`` and ``shots`` share beside ``bounces`` and
    ``air_density`` (python/src/shot.rs declares them once for both), each None (or absent)
    as the command line's ``shot`` without that option (``friction`` the surface's); the
    ball's, :class:`BallArguments`, with them."""
    friction: Optional[float]
    distance: Optional[float]
    time: Optional[float]
    drag_coefficient: Optional[float]
    lift_coefficient: Optional[float]
    spin_decay: Optional[float]
    tangential_stiffness: Optional[float]
    inertia_factor: Optional[float]
    tangential_damping: Optional[float]
    surface: Optional[SurfaceArg]
    net: Optional[NetArg]

def shot(
    preset: str = "tennis",
    *,
    bounces: int = 1,
    air_density: float = 1.204,
    height: float,
    speed: float,
    elevation: float = 0.0,
    spin: float = 0.0,
    samples: int = 200,
    after_bounce: Optional[float] = None,
    law: Optional[Law] = None,
    params: Optional[ParamSet] = None,
    **flight: Unpack[FlightArguments],
) -> dict[str, Any]:
    """A shot (docs/flight.md), as ``bouncelab shot --format json --samples N``: launched from
    ``height`` (the centre, m) at ``speed`` (m/s), ``elevation`` (degrees, negative down) and
    ``spin`` (rad/s, > 0 topspin), bouncing by ``oblique`` on ``surface`` (a name or a dict
    of its numbers, as ``oblique``'s; the rigid plate when None) of ``friction`` (the
    surface's when None, required when it has none); ``after_bounce=D`` ends it D m past its
    last bounce (``--after-bounce D``; not with ``distance``); a
    dict with ``bounces`` (a dict of arrays, one element a bounce: t, x, v_in, angle_in,
    spin_in, vx_in, vy_in, v_out, angle_out, spin_out, vx_out, vy_out, cor_normal,
    contact_time, slid_throughout, and warnings a list), ``end`` (reason, t, x, y, vx, vy,
    spin, speed), ``trajectory`` (arrays t, x, y, vx, vy, spin; ``samples`` of them) and
    ``source`` (the aerodynamic models used), ``surface`` (the JSON's ``surface`` object),
    ``ball`` and ``conditions``; with ``net=`` (:data:`NetArg`) ``net``, the JSON's ``net``
    object (x, height, clearance, cleared, t, y, bounces_before, warnings: the flight is the
    same, computed as if the net were absent). The overrides are
    the command line's: ``drag_coefficient``, ``lift_coefficient``, ``spin_decay``,
    ``air_density``, ``tangential_stiffness``, ``inertia_factor``, ``tangential_damping`` and
    :class:`BallArguments`."""

def shots(
    preset: str = "tennis",
    *,
    bounces: int = 1,
    air_density: float = 1.204,
    height: Floats,
    speed: Floats,
    elevation: Optional[Floats] = None,
    spin: Optional[Floats] = None,
    law: Optional[Law] = None,
    params: Optional[ParamSet] = None,
    **flight: Unpack[FlightArguments],
) -> dict[str, Any]:
    """Many shots, ``height``, ``speed``, ``elevation`` and ``spin`` (``None``: 0) broadcast
    together as a ufunc's arguments: arrays of the broadcast shape ``landing_t``, ``landing_x``, ``v_in``,
    ``angle_in``, ``v_out``, ``angle_out``, ``spin_out`` (the first bounce; NaN with
    bounces=0) and ``end_t``, ``end_x``, ``end_y``, ``end_vx``, ``end_vy``; with ``net=``
    ``net_clearance`` (NaN where the ball does not reach it) and ``net_cleared`` (bools);
    and ``surface``, the surface dict ``shot`` gives."""

Dist = Literal["normal", "uniform", "lognormal"]

class McStats(TypedDict):
    n: int
    mean: float
    sd: float
    min: float
    max: float
    q: dict[str, float]
    mean_se: float
    mean_ci: list[float]
    q_ci: dict[str, list[Optional[float]]]

class MonteCarlo(TypedDict, total=False):
    samples: int
    seed: int
    preset: Optional[str]
    law: str
    v0: float
    dist: str
    vary: dict[str, float]
    no_rebound: int
    stats: dict[str, McStats]
    warnings: list[str]
    values: dict[str, Array]
    ball: BallRecord
    conditions: Conditions
    surface: SurfaceObject

def batch(
    file: Union[str, "os.PathLike[str]"],
    *,
    standard: Optional[str] = None,
    preset: str = "superball",
    params: Optional[ParamSet] = None,
    law: Optional[Law] = None,
    v0: Optional[float] = None,
    free: Optional[Union[str, list[str]]] = None,
    drag_coefficient: Optional[float] = None,
    air_density: float = 1.204,
    **ball: Unpack[BallArguments],
) -> dict[str, Any]:
    """A batch of balls in one CSV (an ``id`` column and ``fit``'s columns), each fitted and
    judged against ``standard``, as ``bouncelab batch FILE --format json``: ``summary`` (n,
    mean, sd, min, max, failures, cpk, the 95 % intervals mean_ci and cpk_ci, unsure, …) and
    ``balls`` (id, cor, verdict, margin, measured_ci95, warnings, error, …); ``None`` where
    the JSON has null, but ``inf`` for the surface's infinite K_s and M, as every answer's."""

def monte_carlo(
    *,
    preset: str = "superball",
    vary: Union[str, dict[str, float]],
    samples: int = 10000,
    seed: int = 0,
    dist: Dist = "normal",
    v0: Optional[float] = None,
    law: Optional[Law] = None,
    params: Optional[ParamSet] = None,
    return_samples: bool = False,
    correlate: Optional[Union[str, dict[str, float]]] = None,
    **ball: Unpack[BallArguments],
) -> MonteCarlo:
    """COR, max_force and contact_time over ``samples`` samples of the preset's parameters
    spread by ``vary`` (fractions: {"k_p": 0.05}, or "k_p=5%,…"), as ``bouncelab mc --format
    json``; with ``return_samples``, ``values`` holds each sample's values as arrays."""

class StaticReading(TypedDict):
    """The diameter's shortening and one contact's parts (m), or None and the ``reason``."""
    deflection_m: Optional[float]
    indentation_m: Optional[float]
    recoil_m: Optional[float]
    reason: Optional[str]

class StaticReturn(StaticReading):
    peak_m: float
    peak_force_n: Optional[float]

class Static(_Named):
    """The keys of ``bouncelab static --format json`` (``return`` cannot be spelled here: a
    Python keyword; a :class:`StaticReturn`)."""
    load_kg: float
    force_n: float
    g: float
    forward: StaticReading
    warnings: list[str]
    ball: BallRecord
    surface: SurfaceObject
    conditions: Conditions

def static(
    preset: str = "superball",
    *,
    load_kg: float,
    peak: float = 0.0254,
    law: Optional[Law] = None,
    params: Optional[ParamSet] = None,
    **ball: Unpack[BallArguments],
) -> Static:
    """The ball squeezed between two rigid plates under ``load_kg`` (its weight on each
    contact; the ITF's deformation tests use 8.165 kg), as ``bouncelab static --load KG
    [--peak M]``: the forward deflection of the diameter and, where the law has hysteresis,
    the return deflection read on unloading from a ``peak`` m compression (docs/model.md
    §11); None with the ``reason`` where the model gives none."""

class _CourtSometimes(TypedDict, total=False):
    tangential_damping: float
    calibration: dict[str, Any]
    # with ``fit``: file, bounces, apparent_friction, cor_normal, cpr of the measured bounces
    measured: dict[str, Any]

class Court(_Named, _CourtSometimes):
    """The keys of ``bouncelab court --format json``: the Court Pace Rating and what it was
    computed on; ``calibration`` (surface_cor, stiffness, damping, cor, reachable,
    assumption) with ``surface_cor`` or ``fit``; ``measured`` (the file's name, its bounces,
    their mean μ_app and e and the CPR of them) with ``fit``."""
    standard: str
    friction: float
    cpr: float
    category: int
    category_name: str
    apparent_friction: float
    cor_normal: float
    v_out: float
    angle_out_deg: float
    spin_out: float
    warnings: list[str]
    surface: SurfaceObject
    computed_on: str
    ball: BallRecord
    conditions: Conditions

def court(
    preset: str = "tennis",
    *,
    friction: Optional[float] = None,
    surface: Optional[SurfaceArg] = None,
    surface_cor: Optional[float] = None,
    fit: Optional[Union[str, os.PathLike[str]]] = None,
    tangential_stiffness: Optional[float] = None,
    inertia_factor: Optional[float] = None,
    tangential_damping: Optional[float] = None,
    law: Optional[Law] = None,
    params: Optional[ParamSet] = None,
    **ball: Unpack[BallArguments],
) -> Court:
    """The ITF Court Pace Rating (CS 01/02: 30 m/s at 16°, no spin) of a surface for the
    ball (by default the test's ball, ``tennis``), as ``bouncelab court``: ``surface`` a name or a dict of its numbers, ``friction`` μ
    (the surface's when not given), ``surface_cor`` a measured e the court is calibrated to
    (c_s solved at the dict's ``stiffness``, else the ball's K_p: an assumption the answer
    states; a ValueError with the reachable range when e is out of reach); ``fit`` a CSV
    file of measured ITF test bounces (v_in, angle_in, v_out, angle_out in m/s and degrees),
    as ``court --fit FILE``: their mean μ_app and e are the friction and the e calibrated to
    (not with ``friction`` or ``surface_cor``)."""
