//! `shot --net DISTANCE[,HEIGHT]` and `mc --shot --net` (docs/cli.md `shot`, docs/flight.md
//! §6): the flag read, the text's `net:` line, the CSV's net columns and the net drawn in the
//! side view.

use super::output::given;
use crate::api::{Net, NetReport, TENNIS_NET_HEIGHT};
use crate::figure::{Figure, GREY, Kind, Series, Style};

/// `--net DISTANCE[,HEIGHT]`: the net `DISTANCE` m from the launch, `HEIGHT` m high (default
/// the tennis net's at the centre, ITF Rules of Tennis, Rule 1). The library refuses a
/// distance or a height that is not positive (`invalid --net: …`).
pub fn parse(text: &str) -> Result<Net, String> {
    let (d, h) = match text.split_once(',') {
        Some((d, h)) => (d, Some(h)),
        None => (text, None),
    };
    let number = |t: &str, what: &str| {
        crate::text::parse::number(t.trim()).map_err(|e| format!("{e} (the net's {what})"))
    };
    Ok(Net {
        x: number(d, "distance")?,
        height: h.map_or(Ok(TENNIS_NET_HEIGHT), |h| number(h, "height"))?,
    })
}

/// The text's line: where the ball crosses the net and by how much it clears it.
pub fn line(n: &NetReport) -> String {
    let net = format!(
        "net at x = {} m, {} m high",
        given(n.x, 6),
        given(n.height, 4)
    );
    let (Some(c), Some(y), Some(t)) = (n.clearance, n.y, n.t) else {
        return format!("{net}: not reached");
    };
    let after = match n.bounces_before {
        Some(0) | None => String::new(),
        Some(1) => ", after a bounce".into(),
        Some(k) => format!(", after {k} bounces"),
    };
    let verdict = if n.cleared {
        format!("clears it by {} m", given(c, 3))
    } else {
        "meets it".into()
    };
    format!(
        "{net}: {verdict} (t = {} s, centre {} m up, lowest point {} m {} the top{after})",
        given(t, 4),
        given(y, 4),
        given(c.abs(), 3),
        if c < 0.0 { "under" } else { "over" }
    )
}

/// The CSV's columns after its own, with `--net`.
pub const COLUMNS: [&str; 4] = ["net_x", "net_height", "net_clearance", "net_cleared"];

/// The net's cells, the shot's, on every row (empty clearance when the ball does not reach it).
pub fn cells(n: &NetReport) -> [String; 4] {
    [
        super::output::num(n.x),
        super::output::num(n.height),
        n.clearance.map(super::output::num).unwrap_or_default(),
        n.cleared.to_string(),
    ]
}

/// The side view with the net drawn: a vertical line from the surface to its top, at its x.
pub fn draw(fig: &mut Figure, n: &NetReport) {
    let verdict = match (n.cleared, n.clearance) {
        (true, Some(c)) => format!("cleared by {} m", given(c, 3)),
        (false, Some(_)) => "met".into(),
        _ => "not reached".into(),
    };
    let label = format!("net ({} m; {verdict})", given(n.height, 4));
    let net = Series::new(&label, "net", Kind::Reference, Style::Solid, GREY)
        .with_points(vec![(n.x, 0.0), (n.x, n.height)]);
    fig.series.push(net);
}
