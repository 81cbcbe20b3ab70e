//! Iso-lines by marching squares.
//!
//! Why not the `contour` crate (0.13, a port of d3-contour): it builds the rings of the region
//! above a threshold, closed along the grid's border, so its lines run along the border where
//! the field is not at the level; it cannot skip the squares of cells without an answer (NaN);
//! and it brings geo-types. What a map needs is the open iso-line itself, each vertex on a grid
//! edge at the level by linear interpolation: that is the small algorithm below.

use super::Axis;
use std::collections::HashMap;

/// One iso-line: its vertices as fractional grid indices (i along λ, j along ζ) and, once
/// placed on the axes, as (λ, ζ). A closed line ends on its first vertex.
#[derive(Debug, Clone, PartialEq)]
pub struct Contour {
    /// The value the line follows.
    pub level: f64,
    /// (i, j): one of them whole, the vertex lying on a grid edge.
    pub index: Vec<(f64, f64)>,
    /// (λ, ζ); empty until [`Contour::on_axes`].
    pub points: Vec<(f64, f64)>,
}

impl Contour {
    /// The vertices placed on the axes (log axes interpolate in log10, as they are spaced).
    pub fn on_axes(mut self, lambda: &Axis, zeta: &Axis) -> Contour {
        self.points = self
            .index
            .iter()
            .map(|&(i, j)| (lambda.at(i), zeta.at(j)))
            .collect();
        self
    }
}

/// A grid edge: between (i, j) and (i, j+1) (`along_j`) or (i, j) and (i+1, j).
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
struct Edge {
    i: usize,
    j: usize,
    along_j: bool,
}

/// The iso-lines at `level` of a field of `rows` × `cols` values (row-major, row = i). A
/// square with a NaN corner is skipped; a saddle is split by its centre value.
pub fn contour_lines(field: &[f64], rows: usize, cols: usize, level: f64) -> Vec<Contour> {
    assert_eq!(field.len(), rows * cols, "field of rows × cols values");
    let v = |i: usize, j: usize| field[i * cols + j];
    let point = |e: Edge| {
        let (p, q) = if e.along_j {
            (v(e.i, e.j), v(e.i, e.j + 1))
        } else {
            (v(e.i, e.j), v(e.i + 1, e.j))
        };
        let t = (level - p) / (q - p);
        if e.along_j {
            (e.i as f64, e.j as f64 + t)
        } else {
            (e.i as f64 + t, e.j as f64)
        }
    };
    join(&segments(field, rows, cols, level))
        .into_iter()
        .map(|edges| Contour {
            level,
            index: edges.into_iter().map(point).collect(),
            points: Vec::new(),
        })
        .collect()
}

/// The level's segments, square by square: each joins two crossed edges.
fn segments(field: &[f64], rows: usize, cols: usize, level: f64) -> Vec<[Edge; 2]> {
    let v = |i: usize, j: usize| field[i * cols + j];
    let above = |x: f64| x >= level;
    let mut segments: Vec<[Edge; 2]> = Vec::new();
    for i in 0..rows.saturating_sub(1) {
        for j in 0..cols.saturating_sub(1) {
            // corners clockwise: a (i, j), b (i, j+1), c (i+1, j+1), d (i+1, j)
            let (a, b, c, d) = (v(i, j), v(i, j + 1), v(i + 1, j + 1), v(i + 1, j));
            if [a, b, c, d].iter().any(|x| x.is_nan()) {
                continue;
            }
            let top = Edge {
                i,
                j,
                along_j: true,
            };
            let right = Edge {
                i,
                j: j + 1,
                along_j: false,
            };
            let bottom = Edge {
                i: i + 1,
                j,
                along_j: true,
            };
            let left = Edge {
                i,
                j,
                along_j: false,
            };
            let cut = [
                (above(a) != above(b), top),
                (above(b) != above(c), right),
                (above(c) != above(d), bottom),
                (above(d) != above(a), left),
            ];
            let crossed: Vec<Edge> = cut.iter().filter(|(x, _)| *x).map(|(_, e)| *e).collect();
            match crossed.len() {
                2 => segments.push([crossed[0], crossed[1]]),
                4 => {
                    // a saddle: a and c on one side, b and d on the other; the centre decides
                    // which pair joins across the square
                    if above((a + b + c + d) / 4.0) == above(a) {
                        segments.push([top, right]);
                        segments.push([bottom, left]);
                    } else {
                        segments.push([left, top]);
                        segments.push([right, bottom]);
                    }
                }
                _ => {}
            }
        }
    }
    segments
}

/// Segments chained into polylines through their shared edges: open lines from their ends
/// first, then the closed loops.
fn join(segments: &[[Edge; 2]]) -> Vec<Vec<Edge>> {
    let mut at: HashMap<Edge, Vec<usize>> = HashMap::new();
    for (k, s) in segments.iter().enumerate() {
        for e in s {
            at.entry(*e).or_default().push(k);
        }
    }
    let mut used = vec![false; segments.len()];
    let mut lines = Vec::new();
    let follow = |start: Edge, first: usize, used: &mut Vec<bool>| {
        let (mut edge, mut seg) = (start, first);
        let mut line = vec![start];
        loop {
            used[seg] = true;
            let s = segments[seg];
            edge = if s[0] == edge { s[1] } else { s[0] };
            line.push(edge);
            match at[&edge].iter().find(|&&k| !used[k]) {
                Some(&k) => seg = k,
                None => break,
            }
        }
        line
    };
    let mut starts: Vec<(Edge, usize)> = at
        .iter()
        .filter(|(_, v)| v.len() == 1)
        .map(|(e, v)| (*e, v[0]))
        .collect();
    // a fixed order, so that the same field gives the same lines
    starts.sort_by_key(|(e, k)| (*k, e.i, e.j, e.along_j));
    for (e, k) in starts {
        if !used[k] {
            lines.push(follow(e, k, &mut used));
        }
    }
    for k in 0..segments.len() {
        if !used[k] {
            lines.push(follow(segments[k][0], k, &mut used));
        }
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cone: the level-r line is one closed loop, each vertex at distance r to the
    /// interpolation's accuracy.
    #[test]
    fn a_cone_gives_one_closed_ring() {
        let n = 21;
        let f: Vec<f64> = (0..n * n)
            .map(|k| (((k / n) as f64 - 10.0).powi(2) + ((k % n) as f64 - 10.0).powi(2)).sqrt())
            .collect();
        let lines = contour_lines(&f, n, n, 5.5);
        assert_eq!(lines.len(), 1);
        let l = &lines[0].index;
        assert_eq!(l.first(), l.last());
        for &(i, j) in l {
            let r = ((i - 10.0).powi(2) + (j - 10.0).powi(2)).sqrt();
            assert!((r - 5.5).abs() < 0.1, "{r}");
        }
    }

    /// A ramp cut by NaN: the line stops at the hole and goes on past it.
    #[test]
    fn nan_squares_are_skipped() {
        let (r, c) = (5, 6);
        let mut f: Vec<f64> = (0..r * c).map(|k| (k % c) as f64).collect();
        f[2 * c + 2] = f64::NAN;
        let lines = contour_lines(&f, r, c, 2.5);
        assert_eq!(lines.len(), 2);
        for l in &lines {
            assert!(l.index.iter().all(|&(_, j)| (j - 2.5).abs() < 1e-15));
        }
    }
}
