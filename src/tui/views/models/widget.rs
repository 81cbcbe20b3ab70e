//! The models view's table, beside its charts: for each peer model and each rule published
//! for it, the damping the rule gives for the target COR and the COR that damping really
//! produces at v0 (with the miss, Δe, when there is room). The letters in front of the models
//! are the ones on the curves. Damping in the units of `bouncelab peers`.

use crate::figure::Tone;
use crate::figure::explorer::models::{ModelsData, letter, short_name, short_rule};
use crate::peers::PeerModel;
use crate::peers::calibrate::Calibrated;
use crate::peers::rules::Rule;
use crate::text::sig;
use crate::tui::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Widget, Wrap};

/// From this inner width the table shows the miss Δe = e − target too: a row is
/// ` Gonthier 0.3494 0.8104 -0.030`, 30 cells, the table's inner width at 80×24 and 100×30
/// (issue 51 item 6: its rows took 34 and lost Δe there; tests/tui/tui_models.rs,
/// `the_table_shows_the_miss_at_the_small_sizes`).
const WIDTH_FOR_MISS: usize = 30;
/// A rule whose COR misses the target by more than this is shown highlighted.
const MISS_SHOWN: f64 = 0.005;

/// What the table shows.
#[derive(Debug, Clone, Copy)]
pub struct ModelsTable<'a> {
    pub data: Option<&'a ModelsData>,
    /// Why the calibration failed, if it did.
    pub error: Option<&'a str>,
    /// The ball does not rebound at v0: no COR to calibrate the peers to (they take one in
    /// (0, 1]), said in words rather than as the calibration's refusal (issue 51 item 5).
    pub no_rebound: bool,
    /// λ, ζ and v0 of the ball, as the readout would show them.
    pub setting: (f64, f64, f64),
    pub theme: Theme,
}

/// The damping's name and unit, as `bouncelab peers` reports it.
fn damping_unit(model: PeerModel) -> &'static str {
    match model {
        PeerModel::KelvinVoigt | PeerModel::KelvinVoigtNoTension => "η kg/s",
        PeerModel::Tsuji => "η kg/(s·m^¼)",
        PeerModel::HuntCrossley => "χ",
    }
}

impl ModelsTable<'_> {
    /// One rule's row: its damping and the COR it gives, with the miss when `miss`;
    /// highlighted when an approximate rule misses by more than [`MISS_SHOWN`].
    fn rule_line(&self, c: &Calibrated, target: f64, miss: bool) -> Line<'static> {
        let e = c.response.cor;
        let mut text = format!(
            " {:<8} {:>6} {:>6}",
            short_rule(c.rule),
            sig(c.damping, 4),
            format!("{e:.4}")
        );
        if miss {
            // rounded first, so that a miss below 0.0005 prints +0.000, not -0.000
            let delta = ((e - target) * 1e3).round() / 1e3 + 0.0;
            text.push_str(&format!(" {delta:>+6.3}"));
        }
        let off = c.rule != Rule::Exact && (e - target).abs() > MISS_SHOWN;
        let style = if off {
            self.theme.warning()
        } else {
            Style::default()
        };
        Line::styled(text, style)
    }

    /// The ball's setting and the target: "λ 1.000 ζ 0.06571 v0 1.470 m/s" over "target e
    /// 0.8404 = C–Y at v0"; where the first is wider than the table (λ 0.9333 ζ 0.07122 at
    /// 80 × 24: its "m/s" wrapped, pushing the table down a row), v0 goes to the second line.
    fn head(&self, target: Option<f64>, inner_w: usize) -> Vec<Line<'static>> {
        let (lambda, zeta, v0) = self.setting;
        let (lambda, zeta, v0) = (sig(lambda, 4), sig(zeta, 4), sig(v0, 4));
        let whole = format!("λ {lambda} ζ {zeta} v0 {v0} m/s");
        let Some(e) = target else {
            return vec![Line::raw(whole)];
        };
        let e = sig(e, 4);
        if whole.chars().count() <= inner_w {
            vec![
                Line::raw(whole),
                Line::raw(format!("target e {e} = C–Y at v0")),
            ]
        } else {
            vec![
                Line::raw(format!("λ {lambda} ζ {zeta}")),
                Line::raw(format!("v0 {v0} m/s: target e {e}")),
            ]
        }
    }

    /// The table, then the notes that go where there is room.
    fn lines(&self, inner_w: usize) -> (Vec<Line<'static>>, Vec<Line<'static>>) {
        let mut lines = self.head(self.data.map(|d| d.target), inner_w);
        let Some(d) = self.data else {
            let text = match self.error {
                _ if self.no_rebound => "no rebound at this v0: the ball sinks into the \
                    dashpot (e 0), and the peer models calibrate to a COR above 0; \
                    nothing to calibrate them to"
                    .into(),
                Some(e) => format!("no calibration: {}", human_names(e)),
                None => "calibrating…".into(),
            };
            let style = if self.error.is_some() {
                self.theme.error()
            } else {
                self.theme.dim()
            };
            lines.push(Line::styled(text, style));
            return (lines, Vec::new());
        };
        let miss = inner_w >= WIDTH_FOR_MISS;
        // "damping" right-aligned over the damping column (1 + 8 + 1 + 6 cells)
        let head = format!(
            " {:<8}{:>7} {:>6}{}",
            "rule",
            "damping",
            "e",
            if miss { "     Δe" } else { "" }
        );
        lines.push(Line::styled(head, self.theme.dim()));
        for (k, model) in PeerModel::ALL.into_iter().enumerate() {
            lines.push(Line::from(vec![
                Span::styled(letter(Some(model)), self.theme.tone(Tone::Reference(k))),
                Span::raw(format!(
                    " {}, {}",
                    short_name(Some(model)),
                    damping_unit(model)
                )),
            ]));
            for c in d.rows.iter().filter(|c| c.model == model) {
                lines.push(self.rule_line(c, d.target, miss));
            }
        }
        lines.push(Line::styled(
            "C C–Y  h H–C α fixed  ◆ target",
            self.theme.dim(),
        ));
        let mut notes = vec![Line::raw("")];
        if miss {
            notes.push(Line::raw("Δe: the rule's COR − target"));
        }
        notes.push(Line::raw("for a DEM code's input file:"));
        notes.push(Line::raw("bouncelab peers --export CODE"));
        (lines, notes)
    }
}

/// `text` with each peer model's command-line name (`kelvin-voigt-no-tension`) replaced by
/// the name the table gives it (`KV F≥0`): no internal name on screen (issue 51 item 4).
pub fn human_names(text: &str) -> String {
    let mut out = text.to_string();
    // the longest first: `kelvin-voigt` is part of `kelvin-voigt-no-tension`
    let mut models = PeerModel::ALL;
    models.sort_by_key(|m| std::cmp::Reverse(m.name().len()));
    for m in models {
        out = out.replace(m.name(), short_name(Some(m)));
    }
    out
}

impl Widget for &ModelsTable<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let block = Block::bordered()
            .border_style(self.theme.dim())
            .title(Line::styled(" rule → COR obtained ", self.theme.title()));
        let inner = block.inner(area);
        let inner_w = usize::from(inner.width);
        // a short panel cuts the table at a row, marked (60 × 20: tests/tui/tui_small.rs);
        // the notes fill what rows are left after the whole table, as many as fit
        let rows = usize::from(inner.height);
        let (table, notes) = self.lines(inner_w);
        let mut lines = crate::tui::widgets::cut::kept(table, inner_w, rows);
        let room = rows.saturating_sub(crate::tui::widgets::cut::rows(&lines, inner_w));
        lines.extend(notes.into_iter().take(room));
        Paragraph::new(lines)
            .block(block)
            .wrap(Wrap { trim: false })
            .render(area, buf);
    }
}
