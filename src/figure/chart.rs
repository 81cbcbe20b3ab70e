//! Which of the explorer's charts a figure is: the one name the explorer, its figures
//! (`explorer`) and the measured data laid over them (`overlay`) share.

/// The explorer's charts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Chart {
    /// F(t) over the contact.
    ForceTime,
    /// F against indentation z: the loading and unloading loop.
    Hysteresis,
    /// COR against ζ at the current λ (Fig. 2).
    CorZeta,
    /// F̄_m against ζ at the current λ (Fig. 3).
    ForceZeta,
    /// COR against impact speed (Fig. 4).
    CorSpeed,
    /// The models view (crate::figure::explorer::models): COR against impact speed of every
    /// calibrated model.
    ModelsCorSpeed,
    /// The models view: force against time of every calibrated model at v0.
    ModelsForceTime,
    /// The models view: force against the ball's approach of every calibrated model at v0.
    ModelsForceDisplacement,
}

impl Chart {
    /// The chart's name in file names: the `bouncelab figure` name of the same figure.
    pub fn file_name(self) -> &'static str {
        match self {
            Chart::ForceTime => "force-time",
            Chart::Hysteresis => "force-displacement",
            Chart::CorZeta => "cor-zeta",
            Chart::ForceZeta => "force-zeta",
            Chart::CorSpeed => "cor-velocity",
            Chart::ModelsCorSpeed => "peers-cor-velocity",
            Chart::ModelsForceTime => "peers-force-time",
            Chart::ModelsForceDisplacement => "peers-force-displacement",
        }
    }
}
