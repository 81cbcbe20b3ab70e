//! Arbitrary bytes as a preset file: the catalog's UTF-8 check, `Preset::parse`, and on success
//! the derived parameters, both parameter sets and a run of each (see `checks`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    bouncelab_fuzz::checks::check_preset_bytes(data);
});
