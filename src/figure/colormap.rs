//! Viridis, the perceptually uniform, colour-blind-safe colour map of the heat maps (the SVG
//! design map; the explorer's map view may take it too).
//!
//! Source: the `_viridis_data` table of matplotlib's colormaps by Nathaniel J. Smith, Stéfan
//! van der Walt and Eric Firing (2015, released CC0; matplotlib `_cm_listed.py`). Its 256
//! entries are sampled here every 16th (entries 0, 16, …, 240), then 248 (where the blue
//! channel dips and turns) and the last (255), as published, and interpolated linearly
//! between: the published entries between anchors are met within two 8-bit levels
//! (`anchors_interpolate_the_published_entries` below; the largest, 1.8 levels of red, is
//! near entry 152 where red turns), far below a visible step.

/// (entry of the 256-entry table, sRGB in 0 … 1).
const ANCHORS: [(u8, [f64; 3]); 18] = [
    (0, [0.267004, 0.004874, 0.329415]),
    (16, [0.282327, 0.094955, 0.417331]),
    (32, [0.278826, 0.175490, 0.483397]),
    (48, [0.258965, 0.251537, 0.524736]),
    (64, [0.229739, 0.322361, 0.545706]),
    (80, [0.199430, 0.387607, 0.554642]),
    (96, [0.172719, 0.448791, 0.557885]),
    (112, [0.149039, 0.508051, 0.557250]),
    (128, [0.127568, 0.566949, 0.550556]),
    (144, [0.120638, 0.625828, 0.533488]),
    (160, [0.157851, 0.683765, 0.501686]),
    (176, [0.246070, 0.738910, 0.452024]),
    (192, [0.369214, 0.788888, 0.382914]),
    (208, [0.515992, 0.831158, 0.294279]),
    (224, [0.678489, 0.863742, 0.189503]),
    (240, [0.845561, 0.887322, 0.099702]),
    (248, [0.926106, 0.897330, 0.104071]),
    (255, [0.993248, 0.906157, 0.143936]),
];

/// The colour of `t` in 0 … 1 (clamped; NaN gives the low end), as 8-bit sRGB.
pub fn viridis(t: f64) -> (u8, u8, u8) {
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    let x = t * 255.0;
    let k = ANCHORS
        .windows(2)
        .position(|w| x <= f64::from(w[1].0))
        .unwrap_or(ANCHORS.len() - 2);
    let ((a, ca), (b, cb)) = (ANCHORS[k], ANCHORS[k + 1]);
    let f = (x - f64::from(a)) / f64::from(b - a);
    let ch = |i: usize| ((ca[i] + (cb[i] - ca[i]) * f) * 255.0).round() as u8;
    (ch(0), ch(1), ch(2))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Published entries between the anchors (matplotlib's table), within two 8-bit levels.
    #[test]
    fn anchors_interpolate_the_published_entries() {
        let published = [
            (8, [0.277018, 0.050344, 0.375715]),
            (72, [0.214298, 0.355619, 0.551184]),
            (136, [0.120565, 0.596422, 0.543611]),
            (152, [0.132268, 0.655014, 0.519661]),
            (168, [0.196571, 0.711827, 0.479221]),
            (200, [0.440137, 0.811138, 0.340967]),
            (244, [0.886271, 0.892374, 0.095374]),
            (252, [0.964894, 0.902323, 0.123941]),
        ];
        for (entry, rgb) in published {
            let got = viridis(f64::from(entry) / 255.0);
            let want = rgb.map(|c: f64| (c * 255.0).round() as i32);
            for (g, w) in [got.0, got.1, got.2].into_iter().zip(want) {
                assert!(
                    (i32::from(g) - w).abs() <= 2,
                    "entry {entry}: {got:?} vs {want:?}"
                );
            }
        }
        assert_eq!(viridis(0.0), (68, 1, 84));
        assert_eq!(viridis(1.0), (253, 231, 37));
    }

    /// Perceptually ordered: lightness (a luma proxy) rises along the map.
    #[test]
    fn lightness_rises() {
        let luma = |t| {
            let (r, g, b) = viridis(t);
            0.2126 * f64::from(r) + 0.7152 * f64::from(g) + 0.0722 * f64::from(b)
        };
        let l: Vec<f64> = (0..=50).map(|i| luma(f64::from(i) / 50.0)).collect();
        assert!(l.windows(2).all(|w| w[1] > w[0]));
    }
}
