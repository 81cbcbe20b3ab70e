//! Where a marker's text goes in the SVG: clear of every marker and of the texts placed
//! before it, inside the plot — so that no text is drawn over another text or a glyph and
//! reads as another number (`z_f 3●.9 mm`; the terminal's rule, src/tui/widgets/marks.rs).
//!
//! Written apart from the terminal's `marker_place`: that one moves whole cells of a character
//! grid and splits a glyph from its label, this one moves boxes of any size around a point
//! drawn on its own; what they share is the rule, the first clear place from a fixed list.
//! The boxes are estimates (the renderer's own, [`super::svg`]'s `text_width`), so the tests
//! check the drawn SVG with the same estimate (tests/figures/figure_room.rs).

use super::{Series, Style};

/// A box in drawing units, [x0, x1) × [y0, y1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Rect {
    /// Left edge.
    pub x0: i32,
    /// Top edge.
    pub y0: i32,
    /// Right edge.
    pub x1: i32,
    /// Bottom edge.
    pub y1: i32,
}

impl Rect {
    /// The box of `w` × `h` with its top-left corner at `(x, y)`.
    pub fn at((x, y): (i32, i32), (w, h): (i32, i32)) -> Rect {
        Rect {
            x0: x,
            y0: y,
            x1: x + w,
            y1: y + h,
        }
    }

    /// Whether the two boxes share more than an edge.
    pub fn overlaps(&self, o: &Rect) -> bool {
        self.x0 < o.x1 && o.x0 < self.x1 && self.y0 < o.y1 && o.y0 < self.y1
    }

    /// Whether `o` lies wholly inside this box.
    pub fn holds(&self, o: &Rect) -> bool {
        o.x0 >= self.x0 && o.x1 <= self.x1 && o.y0 >= self.y0 && o.y1 <= self.y1
    }
}

/// A marker's text to place: the marker's centre and the text's box size.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Label {
    /// The marker's centre.
    pub at: (i32, i32),
    /// The text's width and height.
    pub size: (i32, i32),
}

/// Sizes around a marker, in drawing units.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Spacing {
    /// Half the marker's width and height (the largest shape's: a triangle's apex).
    pub half: i32,
    /// The first place's offset of the text's top-left corner from the marker's centre:
    /// up and to the right (x > 0, y < 0), as the figures have always put it.
    pub first: (i32, i32),
    /// Space left between a marker and a text beside it.
    pub gap: i32,
}

/// The top-left corners to try for a text of `w` × `h` at a marker centred on (cx, cy),
/// in order: the usual place (up and right), its mirrors below and to the left, beside and
/// above or below the marker, then the corners and the sides again one to four lines further
/// up or down.
fn candidates((cx, cy): (i32, i32), (w, h): (i32, i32), s: Spacing) -> Vec<(i32, i32)> {
    let (dx, dy) = s.first;
    let (right, left) = (cx + dx, cx - dx - w);
    let (up, down) = (cy + dy, cy - dy - h);
    let side = s.half + s.gap;
    let mut out = vec![
        (right, up),
        (right, down),
        (left, up),
        (left, down),
        (cx + side, cy - h / 2),
        (cx - side - w, cy - h / 2),
        (cx - w / 2, cy - side - h),
        (cx - w / 2, cy + side),
    ];
    for k in 1..=4 {
        let lines = k * h;
        out.extend([
            (right, up - lines),
            (right, down + lines),
            (left, up - lines),
            (left, down + lines),
            (cx + side, cy - h / 2 - lines),
            (cx + side, cy - h / 2 + lines),
            (cx - side - w, cy - h / 2 - lines),
            (cx - side - w, cy - h / 2 + lines),
        ]);
    }
    out
}

/// The top-left corner of each label's text: the first of its places (the usual one, its
/// mirrors, beside, above, below, then further out) inside `plot` and clear of every marker
/// in `marks` (centres) and of the texts placed before it; else
/// the first clear one reaching out of the plot (over its frame, never over a text); the
/// usual place when none is.
pub fn place(labels: &[Label], marks: &[(i32, i32)], plot: Rect, s: Spacing) -> Vec<(i32, i32)> {
    let h = s.half;
    let glyphs: Vec<Rect> = marks
        .iter()
        .map(|&(x, y)| Rect::at((x - h, y - h), (2 * h, 2 * h)))
        .collect();
    let mut placed: Vec<Rect> = Vec::new();
    let mut out = Vec::new();
    for l in labels {
        let all = candidates(l.at, l.size, s);
        if l.size.0 <= 0 {
            // a marker without a text: nothing to place
            out.push(all[0]);
            continue;
        }
        let clear = |corner: (i32, i32), inside: bool| {
            let b = Rect::at(corner, l.size);
            (!inside || plot.holds(&b))
                && !glyphs.iter().any(|g| g.overlaps(&b))
                && !placed.iter().any(|p| p.overlaps(&b))
        };
        // inside the plot if it can be; over the frame rather than over another text
        let corner = [true, false]
            .iter()
            .find_map(|&inside| all.iter().copied().find(|&c| clear(c, inside)))
            .unwrap_or(all[0]);
        placed.push(Rect::at(corner, l.size));
        out.push(corner);
    }
    out
}

/// [`place`] for the markers of `series` (drawn at `at`, a point to its drawn centre, `None`
/// for one not drawn; each text of `size(series, point)`), each text's top-left corner as an
/// offset from its marker's centre, by series and point.
pub fn offsets(
    series: &[Series],
    at: impl Fn((f64, f64)) -> Option<(i32, i32)>,
    size: impl Fn(&Series, usize) -> (i32, i32),
    plot: Rect,
    s: Spacing,
) -> Vec<Vec<(i32, i32)>> {
    let centres: Vec<Vec<(i32, i32)>> = series
        .iter()
        .map(|ser| match ser.style {
            Style::Markers(_) => ser.points.iter().filter_map(|&p| at(p)).collect(),
            _ => Vec::new(),
        })
        .collect();
    let labels: Vec<Label> = series
        .iter()
        .zip(&centres)
        .flat_map(|(ser, cs)| {
            let size = &size;
            cs.iter().enumerate().map(move |(i, &at)| Label {
                at,
                size: size(ser, i),
            })
        })
        .collect();
    let marks: Vec<(i32, i32)> = centres.iter().flatten().copied().collect();
    let mut corners = place(&labels, &marks, plot, s).into_iter();
    centres
        .iter()
        .map(|cs| {
            cs.iter()
                .zip(corners.by_ref())
                .map(|(&(cx, cy), (x, y))| (x - cx, y - cy))
                .collect()
        })
        .collect()
}

/// Where a line from a marker to its text ends (the text's nearest point, from the
/// marker's centre) when the text lies farther than `from` away — moved off its usual place,
/// it could be read as another marker's — else `None`. `offset` is the text's top-left
/// corner from the marker, `size` its box.
pub fn leader((dx, dy): (i32, i32), (w, h): (i32, i32), from: i32) -> Option<(i32, i32)> {
    let near = (0.clamp(dx, dx + w), 0.clamp(dy, dy + h));
    let far = f64::from(near.0).hypot(f64::from(near.1)) > f64::from(from);
    far.then_some(near)
}
