//! Whether a figure's texts have room: every `<text>` of an SVG as a box, every marker as a
//! box, and the pairs that overlap — a text over another text or over a marker reads as
//! another number (`z_f 3●.9 mm`), the defect tests/tui/tui_marks.rs guards on the terminal.
//!
//! A text's box is estimated as the renderer lays out the legend (src/figure/svg.rs,
//! `text_width`): 0.52 em per character, one em high, its baseline 0.76 em under the top;
//! `dy` (0.76em top, 0.5ex centre, −0.5ex bottom), `text-anchor` and a `rotate(90|270, x, y)`
//! are read as plotters writes them. Markers are the shapes plotters draws for
//! `Style::Markers` and the map's ball: circles, filled squares and polygons under 100 units
//! across (a map cell or a frame is larger, or unfilled).

/// A box in drawing units, [x0, x1] × [y0, y1].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rect {
    pub x0: f64,
    pub y0: f64,
    pub x1: f64,
    pub y1: f64,
}

impl Rect {
    /// Whether the two boxes share more than a line (touching edges do not count).
    pub fn overlaps(&self, o: &Rect) -> bool {
        self.x0 < o.x1 && o.x0 < self.x1 && self.y0 < o.y1 && o.y0 < self.y1
    }
}

/// Per character, in em: the renderer's own estimate (src/figure/svg.rs, `text_width`).
const EM_PER_CHAR: f64 = 0.52;
/// The baseline under the top of a text's box, and the box's height, in em.
const ASCENT: f64 = 0.76;

fn num(n: roxmltree::Node, attr: &str) -> f64 {
    n.attribute(attr)
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("<{}> without a numeric {attr}", n.tag_name().name()))
}

/// The box of one `<text>`.
fn text_box(n: roxmltree::Node, text: &str) -> Rect {
    let (x, y, size) = (num(n, "x"), num(n, "y"), num(n, "font-size"));
    let baseline = match n.attribute("dy") {
        Some("0.76em") => y + ASCENT * size,
        Some("0.5ex") => y + 0.25 * size,
        Some("-0.5ex") => y - 0.25 * size,
        _ => y,
    };
    let w = text.chars().count() as f64 * EM_PER_CHAR * size;
    let x0 = match n.attribute("text-anchor") {
        Some("middle") => x - w / 2.0,
        Some("end") => x - w,
        _ => x,
    };
    let (top, bottom) = (baseline - ASCENT * size, baseline + (1.0 - ASCENT) * size);
    let (along, across) = ((x0 - x, x0 + w - x), (top - y, bottom - y));
    // rotate(a, x, y) turns (along, across) about (x, y): 270 (up the page) maps (d, v) to
    // (v, −d), 90 (down the page) to (−v, d)
    match n
        .attribute("transform")
        .map(|t| t.trim_start_matches("rotate("))
    {
        Some(t) if t.starts_with("270") => Rect {
            x0: x + across.0,
            x1: x + across.1,
            y0: y - along.1,
            y1: y - along.0,
        },
        Some(t) if t.starts_with("90") => Rect {
            x0: x - across.1,
            x1: x - across.0,
            y0: y + along.0,
            y1: y + along.1,
        },
        _ => Rect {
            x0,
            x1: x0 + w,
            y0: top,
            y1: bottom,
        },
    }
}

/// The marker a shape is, if it is one.
fn marker_box(n: roxmltree::Node) -> Option<Rect> {
    let small = |r: &Rect| r.x1 - r.x0 < 100.0 && r.y1 - r.y0 < 100.0;
    let r = match n.tag_name().name() {
        "circle" => {
            let (cx, cy, r) = (num(n, "cx"), num(n, "cy"), num(n, "r"));
            Rect {
                x0: cx - r,
                y0: cy - r,
                x1: cx + r,
                y1: cy + r,
            }
        }
        "rect" if n.attribute("fill") != Some("none") => {
            let (x, y) = (num(n, "x"), num(n, "y"));
            Rect {
                x0: x,
                y0: y,
                x1: x + num(n, "width"),
                y1: y + num(n, "height"),
            }
        }
        "polygon" => {
            let pts: Vec<(f64, f64)> = n
                .attribute("points")?
                .split_whitespace()
                .filter_map(|p| {
                    let (a, b) = p.split_once(',')?;
                    Some((a.parse().ok()?, b.parse().ok()?))
                })
                .collect();
            let xs = pts.iter().map(|p| p.0);
            let ys = pts.iter().map(|p| p.1);
            Rect {
                x0: xs.clone().fold(f64::INFINITY, f64::min),
                x1: xs.fold(f64::NEG_INFINITY, f64::max),
                y0: ys.clone().fold(f64::INFINITY, f64::min),
                y1: ys.fold(f64::NEG_INFINITY, f64::max),
            }
        }
        _ => return None,
    };
    // a square marker is as wide as it is high; a map's cell run is not, or is larger
    let square = n.tag_name().name() != "rect" || (r.x1 - r.x0 - (r.y1 - r.y0)).abs() < 1.0;
    (small(&r) && square).then_some(r)
}

/// A box drawn in a nested `<svg x y width height viewBox>` (`fit --plot` stacks two
/// figures so), in the coordinates of the document's outer `<svg>`.
fn to_root(n: roxmltree::Node, r: Rect) -> Rect {
    let mut r = r;
    for svg in n.ancestors().filter(|a| a.has_tag_name("svg")) {
        if svg.parent_element().is_none() {
            break;
        }
        let attr = |k: &str| svg.attribute(k).and_then(|v| v.parse().ok()).unwrap_or(0.0);
        let view: Vec<f64> = svg
            .attribute("viewBox")
            .map(|v| {
                v.split_whitespace()
                    .filter_map(|x| x.parse().ok())
                    .collect()
            })
            .unwrap_or_default();
        let (vx, vy, k) = match view[..] {
            [vx, vy, w, _] if w > 0.0 => (vx, vy, attr("width") / w),
            _ => (0.0, 0.0, 1.0),
        };
        let (x, y) = (attr("x"), attr("y"));
        r = Rect {
            x0: x + (r.x0 - vx) * k,
            x1: x + (r.x1 - vx) * k,
            y0: y + (r.y0 - vy) * k,
            y1: y + (r.y1 - vy) * k,
        };
    }
    r
}

/// Every text (its content, trimmed) with its box, and every marker's box, in the
/// coordinates of the outer `<svg>`.
pub fn boxes(svg: &str) -> (Vec<(String, Rect)>, Vec<Rect>) {
    let doc = roxmltree::Document::parse(svg).unwrap_or_else(|e| panic!("not XML: {e}"));
    let mut texts = Vec::new();
    let mut marks = Vec::new();
    for n in doc.root_element().descendants() {
        if n.has_tag_name("text") {
            let t = n.text().unwrap_or("").trim();
            if !t.is_empty() {
                texts.push((t.to_string(), to_root(n, text_box(n, t))));
            }
        } else if let Some(r) = marker_box(n) {
            marks.push(to_root(n, r));
        }
    }
    (texts, marks)
}

/// What overlaps in a figure, one line per pair: "text 'softball' over a marker at (1540,
/// 1044)", "text 'e = 0.771' over text 'e = 0.79'"; empty when every text has room.
pub fn collisions(svg: &str) -> Vec<String> {
    let (texts, marks) = boxes(svg);
    let mut out = Vec::new();
    for (i, (a, ra)) in texts.iter().enumerate() {
        for (b, rb) in &texts[i + 1..] {
            if ra.overlaps(rb) {
                out.push(format!("text {a:?} over text {b:?}"));
            }
        }
        for m in marks.iter().filter(|m| ra.overlaps(m)) {
            out.push(format!(
                "text {a:?} over a marker at ({:.0}, {:.0})",
                m.x0, m.y0
            ));
        }
    }
    out
}
