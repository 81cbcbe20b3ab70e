//! Where a marker's text goes (src/figure/room.rs), over markers crowded at random: each text
//! has room, or no place around its marker had. The drawn figures: tests/figure_room.rs.

use bouncelab::figure::room::{Label, Rect, Spacing, place};
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

fn labels() -> impl Strategy<Value = Vec<Label>> {
    let one = (0..3000i32, 0..2000i32, 0..400i32).prop_map(|(x, y, w)| Label {
        at: (x, y),
        size: (w, 52),
    });
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
