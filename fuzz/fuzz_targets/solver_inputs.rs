//! Arbitrary solver inputs: raw or well-spread f64 parameters (or λ, ζ), a law, a method, a
//! sample count and the energy flag, into `simulate` / `simulate_normalized` (see `checks`).
#![no_main]

use libfuzzer_sys::fuzz_target;

// The bytes are decoded by `checks::decode_solver_input`, the same function the regression
// test uses, rather than by `fuzz_target!`'s typed form: a committed input then replays
// exactly as it ran here.
fuzz_target!(|data: &[u8]| {
    bouncelab_fuzz::checks::check_solver_bytes(data);
});
