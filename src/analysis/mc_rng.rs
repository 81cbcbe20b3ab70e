//! The words a Monte Carlo sample draws from (docs/scale.md, "Same seed, same answer"):
//! sample i reads the keystream of ChaCha8 keyed by the seed, on stream i, from its first
//! word — the words `ChaCha8Rng::from_seed(key)` gives after `set_stream(i)`, in the same
//! order (`the_words_are_chacha8rngs`), so the samples are those of that generator.
//!
//! Why by hand, beside the `chacha20` crate: its `ChaCha8Rng` computes four blocks of one
//! stream (64 words) each time it is set to a stream, and its ciphers one block of one
//! stream at the cost of four on AVX2, while a sample reads some six words (three normals by
//! the ziggurat, one u64 each) and a Monte Carlo sets a new stream for each sample: three
//! quarters of that work were thrown away (a third of a golf sample's instructions). The
//! crate has no call that gives the first block of four streams, which is what is computed
//! here: ChaCha's block function (8 rounds; RFC 8439 §2.3 with the original 64-bit counter
//! and 64-bit nonce of `ChaCha8Rng`), four streams side by side, one array lane each, so
//! that the compiler keeps the four in one SIMD register. A sample that reads past its 16
//! words (rare: a ziggurat rejection or more parameters) goes on with the crate's own
//! generator from word 16 ([`Words`]).

use chacha20::ChaCha8Rng;
use chacha20::rand_core::{Infallible, SeedableRng, TryRng};
use wide::u32x4;

/// Streams per call of [`first_blocks`].
pub const LANES: usize = 4;

/// Words per ChaCha block.
pub const BLOCK: usize = 16;

/// "expand 32-byte k", ChaCha's first four words.
const CONSTANTS: [u32; 4] = [0x6170_7865, 0x3320_646e, 0x7962_2d32, 0x6b20_6574];

/// One word of four streams, a lane each (`wide`'s SIMD vector).
type Lanes = u32x4;

/// The key `ChaCha8Rng::from_seed(seed)` uses: the seed's bytes as little-endian words.
pub fn key_words(seed: &[u8; 32]) -> [u32; 8] {
    std::array::from_fn(|k| u32::from_le_bytes(std::array::from_fn(|b| seed[4 * k + b])))
}

fn xor_rotate(a: Lanes, b: Lanes, by: u32) -> Lanes {
    let x = a ^ b;
    (x << by) | (x >> (32 - by))
}

/// ChaCha's quarter round on the words a, b, c, d of the four streams.
#[inline(always)]
fn quarter(x: &mut [Lanes; BLOCK], a: usize, b: usize, c: usize, d: usize) {
    x[a] += x[b];
    x[d] = xor_rotate(x[d], x[a], 16);
    x[c] += x[d];
    x[b] = xor_rotate(x[b], x[c], 12);
    x[a] += x[b];
    x[d] = xor_rotate(x[d], x[a], 8);
    x[c] += x[d];
    x[b] = xor_rotate(x[b], x[c], 7);
}

/// The first block (block counter 0) of ChaCha8 under `key` on each of four `streams`:
/// `out[l]` is the 16 words `ChaCha8Rng` keyed so gives first on stream `streams[l]`.
pub fn first_blocks(key: &[u32; 8], streams: [u64; LANES]) -> [[u32; BLOCK]; LANES] {
    let mut init = [Lanes::ZERO; BLOCK];
    for (w, c) in init.iter_mut().zip(CONSTANTS) {
        *w = Lanes::splat(c);
    }
    for (w, k) in init[4..12].iter_mut().zip(key) {
        *w = Lanes::splat(*k);
    }
    // words 12 and 13, the 64-bit block counter, stay 0; 14 and 15 are the stream
    init[14] = Lanes::new(streams.map(|s| s as u32));
    init[15] = Lanes::new(streams.map(|s| (s >> 32) as u32));
    let mut x = init;
    for _ in 0..4 {
        quarter(&mut x, 0, 4, 8, 12);
        quarter(&mut x, 1, 5, 9, 13);
        quarter(&mut x, 2, 6, 10, 14);
        quarter(&mut x, 3, 7, 11, 15);
        quarter(&mut x, 0, 5, 10, 15);
        quarter(&mut x, 1, 6, 11, 12);
        quarter(&mut x, 2, 7, 8, 13);
        quarter(&mut x, 3, 4, 9, 14);
    }
    let mut out = [[0u32; BLOCK]; LANES];
    for (k, (x, init)) in x.into_iter().zip(init).enumerate() {
        for (lane, w) in (x + init).to_array().into_iter().enumerate() {
            out[lane][k] = w;
        }
    }
    out
}

/// One sample's generator: the words of its stream, the first block given, the rest (if it
/// reads past it) from `ChaCha8Rng` set to the same stream at word 16. A `u64` is two words,
/// the first the low half, as `ChaCha8Rng` makes it.
pub struct Words<'a> {
    block: &'a [u32; BLOCK],
    next: usize,
    seed: &'a [u8; 32],
    stream: u64,
    rest: Option<ChaCha8Rng>,
}

impl<'a> Words<'a> {
    /// The generator of `stream` under `seed` (ChaCha8Rng's seed), whose first block is
    /// `block` ([`first_blocks`] under [`key_words`]`(seed)`).
    pub fn new(seed: &'a [u8; 32], stream: u64, block: &'a [u32; BLOCK]) -> Words<'a> {
        Words {
            block,
            next: 0,
            seed,
            stream,
            rest: None,
        }
    }

    #[inline]
    fn word(&mut self) -> u32 {
        match self.block.get(self.next) {
            Some(&w) => {
                self.next += 1;
                w
            }
            None => self.word_past_the_block(),
        }
    }

    #[cold]
    fn word_past_the_block(&mut self) -> u32 {
        self.rest
            .get_or_insert_with(|| {
                let mut r = ChaCha8Rng::from_seed(*self.seed);
                r.set_stream(self.stream);
                r.set_word_pos(BLOCK as u128);
                r
            })
            .try_next_u32()
            .unwrap_or_else(|e: Infallible| match e {})
    }
}

impl TryRng for Words<'_> {
    type Error = Infallible;

    #[inline]
    fn try_next_u32(&mut self) -> Result<u32, Infallible> {
        Ok(self.word())
    }

    #[inline]
    fn try_next_u64(&mut self) -> Result<u64, Infallible> {
        if let Some(&[lo, hi]) = self.block.get(self.next..self.next + 2) {
            self.next += 2;
            return Ok(u64::from(hi) << 32 | u64::from(lo));
        }
        let lo = self.word();
        let hi = self.word();
        Ok(u64::from(hi) << 32 | u64::from(lo))
    }

    /// Four bytes a word, little-endian; a last part of 1–3 bytes takes a whole word (as
    /// rand_core's `BlockRng::fill_bytes`).
    fn try_fill_bytes(&mut self, dest: &mut [u8]) -> Result<(), Infallible> {
        for chunk in dest.chunks_mut(4) {
            let w = self.word().to_le_bytes();
            chunk.copy_from_slice(&w[..chunk.len()]);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use chacha20::rand_core::Rng;

    fn reference(seed: &[u8; 32], stream: u64) -> ChaCha8Rng {
        let mut r = ChaCha8Rng::from_seed(*seed);
        r.set_stream(stream);
        r
    }

    /// Block 0 of four streams (across the 32-bit halves of the stream number) and the words
    /// after it: the crate's generator word for word, and its u64s and bytes.
    #[test]
    fn the_words_are_chacha8rngs() {
        for seed_byte in [0u8, 7, 255] {
            let seed: [u8; 32] = std::array::from_fn(|i| seed_byte.wrapping_mul(i as u8 + 1));
            let streams = [0, 1, (1 << 32) + 5, u64::MAX];
            let blocks = first_blocks(&key_words(&seed), streams);
            for (s, block) in streams.into_iter().zip(blocks) {
                let mut want = reference(&seed, s);
                let mut got = Words::new(&seed, s, &block);
                for _ in 0..40 {
                    assert_eq!(got.next_u32(), want.next_u32(), "stream {s}");
                }
                // a u64 across the first block's end, then bytes with a ragged tail
                let (mut want, mut got) = (reference(&seed, s), Words::new(&seed, s, &block));
                want.set_word_pos(15);
                got.next = 15;
                assert_eq!(got.next_u64(), want.next_u64());
                let (mut a, mut b) = ([0u8; 11], [0u8; 11]);
                got.fill_bytes(&mut a);
                want.fill_bytes(&mut b);
                assert_eq!(a, b);
                assert_eq!(got.next_u32(), want.next_u32());
            }
        }
    }
}
