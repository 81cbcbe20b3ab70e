//! Where a curve's tag goes on a braille plot (src/tui/widgets/plot.rs): on the curve, by
//! free space, never over another tag or a marker (issue 29 item 11).

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use std::collections::{HashMap, HashSet};

/// What a tag keeps off: the tags already placed (row, first column, end), the markers'
/// cells, and the cells other lines pass (`passing`: how many lines pass each cell; where
/// its curve runs with another, the tag would not say whose it is).
pub struct Taken<'a> {
    pub tags: &'a [(u16, u16, u16)],
    pub points: &'a [(u16, u16)],
    pub passing: &'a HashMap<(u16, u16), u16>,
}

/// A tagged curve's cells, in order ([`along`]) and as a set.
pub struct Curve<'a> {
    pub cells: &'a [(u16, u16)],
    pub set: &'a HashSet<(u16, u16)>,
}

impl Taken<'_> {
    /// Whether a line other than `own` passes `cell`.
    fn other_at(&self, own: &Curve, cell: (u16, u16)) -> bool {
        let n = self.passing.get(&cell).copied().unwrap_or(0);
        n > u16::from(own.set.contains(&cell))
    }
}

/// The cells a polyline through `cells` passes (consecutive cells joined by the straight
/// steps between them, as the canvas draws the line), in order.
pub fn along(cells: &[(u16, u16)]) -> Vec<(u16, u16)> {
    let mut out: Vec<(u16, u16)> = Vec::new();
    for pair in cells.windows(2) {
        let ((c0, r0), (c1, r1)) = (pair[0], pair[1]);
        let (dc, dr) = (i32::from(c1) - i32::from(c0), i32::from(r1) - i32::from(r0));
        let n = dc.abs().max(dr.abs()).max(1);
        for k in 0..n {
            let c = i32::from(c0) + dc * k / n;
            let r = i32::from(r0) + dr * k / n;
            out.push((c as u16, r as u16));
        }
    }
    out.extend(cells.last());
    out.dedup();
    out
}

/// Where a curve's tag `w` cells wide goes (issue 29 item 11: on its curve, not stacked at
/// the right edge): right of the curve's last cell, on its row, when that fits; else starting
/// on a cell of the curve, at that cell's row, trying the curve from its right end leftwards —
/// the first place where the tag covers no other curve (nor a cell its curve shares with
/// another), else the one covering fewest. Never
/// over another tag or a marker's cell; `None` when no place on the curve is free of them
/// (the legend then names the curve). Tested below (`a_tag_sits_on_its_curve`).
pub fn place(plot: Rect, own: &Curve, w: u16, buf: &Buffer, taken: &Taken) -> Option<(u16, u16)> {
    let (tagged, points) = (taken.tags, taken.points);
    let &(last_col, last_row) = own.cells.last()?;
    let candidates =
        std::iter::once((last_col + 1, last_row)).chain(own.cells.iter().rev().copied());
    let mut best: Option<((u16, u16), usize)> = None;
    for (x, y) in candidates {
        let inside = x >= plot.x && x + w <= plot.right() && y >= plot.y && y < plot.bottom();
        let clear = inside
            // a cell apart from another tag, so two never read as one ("nowλ=1")
            && !tagged
                .iter()
                .any(|&(ty, a, b)| ty == y && x < b + 1 && a < x + w + 1)
            // and a cell apart from a marker's glyph ("nowS", issue 51 item 6)
            && !points
                .iter()
                .any(|&(px, py)| py == y && px + 1 >= x && px <= x + w);
        if !clear {
            continue;
        }
        // cells of other curves (or anything drawn) under the tag; its own curve's count
        // only where another runs there too
        let covered = (x..x + w)
            .filter(|&cx| {
                taken.other_at(own, (cx, y))
                    || (!own.set.contains(&(cx, y)) && buf[(cx, y)].symbol() != " ")
            })
            .count();
        if covered == 0 {
            return Some((x, y));
        }
        if best.is_none_or(|(_, c)| covered < c) {
            best = Some(((x, y), covered));
        }
    }
    best.map(|(at, _)| at)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `passing` for `own` and the `others` lines' cells.
    fn count(own: &[(u16, u16)], others: &[(u16, u16)]) -> HashMap<(u16, u16), u16> {
        let mut m = HashMap::new();
        let own: HashSet<_> = own.iter().copied().collect();
        let others: HashSet<_> = others.iter().copied().collect();
        for c in own.into_iter().chain(others) {
            *m.entry(c).or_default() += 1;
        }
        m
    }

    #[test]
    fn a_tag_sits_on_its_curve() {
        let plot = Rect::new(0, 0, 40, 10);
        let buf = Buffer::empty(plot);
        // a curve falling from (0, 2) to (39, 6): its cells, joined
        let cells = along(&[(0, 2), (20, 4), (39, 6)]);
        assert_eq!(cells.first(), Some(&(0, 2)));
        assert!(cells.contains(&(10, 3)) && cells.contains(&(30, 5)));
        let set: HashSet<_> = cells.iter().copied().collect();
        let own = Curve {
            cells: &cells,
            set: &set,
        };
        let passing = count(&cells, &[]);
        let free = |tags, points| Taken {
            tags,
            points,
            passing: &passing,
        };
        // no room right of its end: the tag starts on the curve, on that cell's row
        let (x, y) = place(plot, &own, 3, &buf, &free(&[], &[])).unwrap();
        assert!(set.contains(&(x, y)), "({x}, {y})");
        assert!(x + 3 <= 40);
        // another tag where it would go: further along the curve, on the curve's own row
        // there, a cell apart, never a row off the curve
        let taken = [(y, x, x + 3)];
        let (x2, y2) = place(plot, &own, 3, &buf, &free(&taken, &[])).unwrap();
        assert!(set.contains(&(x2, y2)), "({x2}, {y2})");
        assert!(y2 != y || x2 + 3 < x, "({x2}, {y2}) against ({x}, {y})");
        // a marker's cell is never under a tag
        let marker = [(x2 + 1, y2)];
        let (x3, y3) = place(plot, &own, 3, &buf, &free(&taken, &marker)).unwrap();
        assert!(!(y3 == y2 && (x3..x3 + 3).contains(&(x2 + 1))));
        assert!(set.contains(&(x3, y3)));
    }

    #[test]
    fn a_tag_keeps_off_other_curves_where_it_can() {
        let plot = Rect::new(0, 0, 30, 10);
        let mut buf = Buffer::empty(plot);
        // its curve falls a row every 3 columns to (29, 9); another crosses row 8 at 27…29
        let cells: Vec<(u16, u16)> = (0..30).map(|x| (x, x / 3)).collect();
        let set: HashSet<_> = cells.iter().copied().collect();
        let own = Curve {
            cells: &cells,
            set: &set,
        };
        for &(x, y) in &cells {
            buf[(x, y)].set_symbol("⠉");
        }
        let crossing: Vec<(u16, u16)> = (27..30).map(|x| (x, 8)).collect();
        for &c in &crossing {
            buf[c].set_symbol("⠒");
        }
        // (26, 8) … (24, 8) would cover the other curve: the first place along the curve
        // that covers nothing but its own cells is (23, 7)
        let passing = count(&cells, &crossing);
        let taken = Taken {
            tags: &[],
            points: &[],
            passing: &passing,
        };
        let (x, y) = place(plot, &own, 4, &buf, &taken).unwrap();
        assert_eq!((x, y), (23, 7));
        assert!((x..x + 4).all(|c| set.contains(&(c, y)) || buf[(c, y)].symbol() == " "));
        // where its curve runs with another (the cells shared), the tag goes elsewhere
        let shared: Vec<(u16, u16)> = cells.iter().copied().filter(|&(x, _)| x >= 15).collect();
        let passing = count(&cells, &shared);
        let taken = Taken {
            passing: &passing,
            ..taken
        };
        let (x, y) = place(plot, &own, 4, &buf, &taken).unwrap();
        assert!(
            (x..x + 4).all(|c| !shared.contains(&(c, y))),
            "({x}, {y}) on cells shared with another curve"
        );
        assert!(set.contains(&(x, y)));
    }
}
