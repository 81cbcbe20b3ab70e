//! The order statistics behind the Monte Carlo's quantiles (`mc_stats`, docs/scale.md), found
//! without a sort and without a copy of the values: one pass counts the values in equal
//! `Bins` between the extremes, a second gathers the few bins that hold a rank asked for, and
//! selection (`select_nth_unstable`) within them names each rank's value — the value a full
//! sort puts there (`mc_stats`' `binned_ranks_are_a_full_sorts`). `unbinned` answers where
//! the range cannot be divided; `quantiles`, selection on a copy, is the tests' reference.

/// The bin of x is ⌊(x − min)·scale⌋ (the last bin closed), which never decreases as x grows
/// (a subtraction, a product by a positive number and a truncation each keep the order under
/// rounding), so the values of bin b are the order statistics cum_b … cum_{b+1} − 1 of the
/// whole (cum_b: the count below bin b). A rank's value is therefore the value of its rank
/// less cum_b within its bin, found by selection among that bin's values alone.
pub(super) struct Bins {
    min: f64,
    scale: f64,
    top: f64,
    counts: Vec<usize>,
}

impl Bins {
    /// Bins for `n` values within `range`, some 32 a bin and at most 2¹⁵ (their counts stay
    /// in L2); `None` where the range cannot be divided (all values equal, max − min
    /// subnormal or above f64::MAX).
    pub(super) fn new(n: usize, range: (f64, f64)) -> Option<Bins> {
        let (min, max) = range;
        let bins = (n / 32).clamp(1, 1 << 15);
        let scale = bins as f64 / (max - min);
        (scale.is_finite() && scale > 0.0).then(|| Bins {
            min,
            scale,
            top: (bins - 1) as f64,
            counts: vec![0; bins],
        })
    }

    fn of(&self, x: f64) -> usize {
        // within [0, top] before the cast: a u32 in range, converted exactly
        ((x - self.min) * self.scale).min(self.top) as u32 as usize
    }

    pub(super) fn count(&mut self, x: f64) {
        let b = self.of(x);
        self.counts[b] += 1;
    }

    /// The values of the `ranks` (ascending, distinct; 0 the smallest) among the finite
    /// entries of `values`, which were counted; the values themselves are not moved.
    pub(super) fn order_statistics(&self, values: &[f64], ranks: &[usize]) -> Vec<f64> {
        // each rank's bin and its rank within it, by the running count
        let mut wanted: Vec<(usize, usize)> = Vec::with_capacity(ranks.len());
        let (mut b, mut below) = (0usize, 0usize);
        for &r in ranks {
            while below + self.counts[b] <= r {
                below += self.counts[b];
                b += 1;
            }
            wanted.push((b, r - below));
        }
        // the wanted bins' values, gathered in one pass: slot[b] is 1 + its place in `held`
        let mut slot = vec![0u8; self.counts.len()];
        let mut held: Vec<Vec<f64>> = Vec::new();
        for &(b, _) in &wanted {
            if slot[b] == 0 {
                held.push(Vec::with_capacity(self.counts[b]));
                slot[b] = held.len() as u8;
            }
        }
        for &x in values.iter().filter(|x| x.is_finite()) {
            let s = slot[self.of(x)];
            if s != 0 {
                held[s as usize - 1].push(x);
            }
        }
        wanted
            .iter()
            .map(|&(b, r)| {
                let bin_values = &mut held[slot[b] as usize - 1];
                *bin_values.select_nth_unstable_by(r, f64::total_cmp).1
            })
            .collect()
    }
}

/// The values of `ranks` (ascending, distinct) among the finite entries of `values` within
/// `range`, which `Bins` cannot divide: min where the values are all equal, else by
/// selection on a copy.
pub(super) fn unbinned(values: &[f64], range: (f64, f64), ranks: &[usize]) -> Vec<f64> {
    if range.0 == range.1 {
        return vec![range.0; ranks.len()];
    }
    let mut kept: Vec<f64> = values.iter().copied().filter(|x| x.is_finite()).collect();
    select_ranks_copy(&mut kept, ranks)
}

/// `Bins::order_statistics` of the `n` finite `values` within `range`, or `unbinned`'s.
#[cfg(test)]
pub(super) fn order_statistics(
    values: &[f64],
    n: usize,
    range: (f64, f64),
    ranks: &[usize],
) -> Vec<f64> {
    let Some(mut bins) = Bins::new(n, range) else {
        return unbinned(values, range, ranks);
    };
    values
        .iter()
        .filter(|x| x.is_finite())
        .for_each(|&x| bins.count(x));
    bins.order_statistics(values, ranks)
}

/// The values of `ranks` (ascending, distinct) in `values`, reordered: `quantiles`'
/// selection.
fn select_ranks_copy(values: &mut [f64], ranks: &[usize]) -> Vec<f64> {
    select_ranks(values, ranks, 0);
    ranks.iter().map(|&r| values[r]).collect()
}

/// Type-7 quantiles at `percents` (ascending) of `values` (finite, not empty), which are
/// reordered: the tests' reference for `stats`' (selection on a copy). The order statistics
/// needed are selected by divide and conquer: the middle rank first, then the ranks below it
/// in the part left of it and those above in the part right of it, so the work is
/// O(n log k) for k ranks, not O(n k).
#[cfg(test)]
pub(super) fn quantiles<const K: usize>(values: &mut [f64], percents: &[f64; K]) -> [f64; K] {
    debug_assert!(
        percents.windows(2).all(|w| w[0] <= w[1]),
        "ascending percents"
    );
    let n = values.len();
    let hs: Vec<f64> = percents
        .iter()
        .map(|p| (n - 1) as f64 * p / 100.0)
        .collect();
    let mut ranks: Vec<usize> = hs
        .iter()
        .flat_map(|h| {
            let lo = h.floor() as usize;
            [lo, (lo + 1).min(n - 1)]
        })
        .collect();
    ranks.sort_unstable();
    ranks.dedup();
    select_ranks(values, &ranks, 0);
    let mut out = [0.0; K];
    for (k, h) in hs.iter().enumerate() {
        let lo = h.floor() as usize;
        let (x_lo, x_hi) = (values[lo], values[(lo + 1).min(n - 1)]);
        out[k] = x_lo + (h - lo as f64) * (x_hi - x_lo);
    }
    out
}

/// Put the order statistic of each rank in `ranks` (ascending, relative to `values`' start
/// plus `offset`) at its index.
fn select_ranks(values: &mut [f64], ranks: &[usize], offset: usize) {
    if ranks.is_empty() {
        return;
    }
    let mid = ranks.len() / 2;
    let r = ranks[mid] - offset;
    values.select_nth_unstable_by(r, f64::total_cmp);
    let (left, right) = values.split_at_mut(r);
    select_ranks(left, &ranks[..mid], offset);
    select_ranks(&mut right[1..], &ranks[mid + 1..], offset + r + 1);
}
