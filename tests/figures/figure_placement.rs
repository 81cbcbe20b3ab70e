//! Where a marker's text goes (src/figure/room.rs): its usual place when it has room, off the
//! markers and the texts before it, inside the plot, a line to it when moved; and over
//! markers crowded at random, each text has room, or no place around its marker had. The
//! drawn figures: tests/figures/figure_room.rs.

use bouncelab::figure::room::{Label, Rect, Spacing, leader, place};
use proptest::prelude::*;

const S: Spacing = Spacing {
    half: 26,
    first: (36, -68),
    gap: 12,
};
const PLOT: Rect = Rect {
    x0: 0,
    y0: 0,
    x1: 3000,
    y1: 2000,
};

/// A marker at `at` and its text's `size` (0 wide: no text).
fn label(at: (i32, i32), size: (i32, i32)) -> Label {
    Label { at, size }
}

fn labels() -> impl Strategy<Value = Vec<Label>> {
    let one = (0..3000i32, 0..2000i32, 0..400i32).prop_map(|(x, y, w)| label((x, y), (w, 52)));
    proptest::collection::vec(one, 1..12)
}

proptest! {
    /// Markers crowded at random: each text goes where it has room — clear of every
    /// marker and of the texts before it — or, where no place around its marker has, to
    /// its usual place; and a text whose usual place has room keeps it.
    #[test]
    fn each_text_has_room_or_no_place_had(labels in labels()) {
        let marks: Vec<(i32, i32)> = labels.iter().map(|l| l.at).collect();
        let glyphs: Vec<Rect> = marks
            .iter()
            .map(|&(x, y)| Rect::at((x - 26, y - 26), (52, 52)))
            .collect();
        let at = place(&labels, &marks, PLOT, S);
        let mut placed: Vec<Rect> = Vec::new();
        for (l, &corner) in labels.iter().zip(&at) {
            let b = Rect::at(corner, l.size);
            let usual = (l.at.0 + 36, l.at.1 - 68);
            let clear = |r: &Rect| {
                !glyphs.iter().any(|g| g.overlaps(r)) && !placed.iter().any(|p| p.overlaps(r))
            };
            let usual_box = Rect::at(usual, l.size);
            if l.size.0 > 0 && PLOT.holds(&usual_box) && clear(&usual_box) {
                prop_assert_eq!(corner, usual);
            }
            prop_assert!(clear(&b) || corner == usual, "{:?} at {:?}", l, corner);
            if l.size.0 > 0 {
                placed.push(b);
            }
        }
    }
}

#[test]
fn a_text_with_room_keeps_its_usual_place() {
    let l = label((1000, 1000), (200, 52));
    assert_eq!(place(&[l], &[(1000, 1000)], PLOT, S), [(1036, 932)]);
}

#[test]
fn a_text_moves_off_a_marker_and_off_the_text_before_it() {
    // the second marker sits where the first one's text would go
    let a = label((1000, 1000), (200, 52));
    let b = label((1100, 960), (200, 52));
    let at = place(&[a, b], &[a.at, b.at], PLOT, S);
    assert_eq!(at[0], (1036, 1016), "below: up-right holds b's marker");
    let boxes: Vec<Rect> = at.iter().map(|&c| Rect::at(c, a.size)).collect();
    assert!(!boxes[0].overlaps(&boxes[1]));
    for m in [a.at, b.at] {
        let g = Rect::at((m.0 - 26, m.1 - 26), (52, 52));
        assert!(boxes.iter().all(|b| !b.overlaps(&g)));
    }
}

#[test]
fn a_text_moved_away_gets_a_line_to_its_nearest_point() {
    assert_eq!(leader((36, -68), (200, 52), 60), None, "the usual place");
    assert_eq!(leader((36, -120), (200, 52), 60), Some((36, -68)));
    assert_eq!(
        leader((-236, -26), (200, 52), 60),
        None,
        "beside, to the left"
    );
    assert_eq!(leader((-100, 100), (200, 52), 60), Some((0, 100)));
}

#[test]
fn a_marker_without_a_text_keeps_the_usual_place_and_takes_no_room() {
    // at the top edge, where a text would move; the next marker's text is not pushed off
    let none = label((1000, 10), (0, 52));
    let text = label((1000, 200), (200, 52));
    let at = place(&[none, text], &[none.at, text.at], PLOT, S);
    assert_eq!(at, [(1036, -58), (1036, 132)]);
}

#[test]
fn a_text_stays_inside_the_plot() {
    // at the top right corner: up-right would leave the plot, down-left does not
    let l = label((2990, 10), (200, 52));
    let at = place(&[l], &[l.at], PLOT, S);
    assert_eq!(at, [(2990 - 36 - 200, 10 + 68 - 52)]);
}
