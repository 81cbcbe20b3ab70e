//! Keys typed ahead of an answer the loop gives itself (issue 51, found walking the explorer):
//! `G` and `↓ Enter` in one burst — as a fast typist or a paste sends them — once picked
//! nothing, the keys behind `G` landing before the picker had its list; `g` the same.
#![cfg(unix)]

use crate::pty;

use pty::Explorer;

const DOWN: &[u8] = b"\x1b[B";

/// The explorer sent `keys` in one write: `needle` comes, and `q q` quits it cleanly.
fn typed_ahead(keys: &[&[u8]], needle: &str) {
    let home = tempfile::tempdir().unwrap();
    let mut x = Explorer::spawn(home.path(), None, &[]);
    x.wait_for_first_draw();
    std::thread::sleep(std::time::Duration::from_millis(300));
    x.send(&keys.concat());
    x.wait_for(needle);
    x.send(b"qq");
    let (status, _, _) = x.finish();
    assert!(status.success(), "{status:?}");
}

#[test]
fn keys_typed_ahead_of_the_surface_picker_pick() {
    // the list: steel-plate, then concrete
    typed_ahead(&[b"G", DOWN, b"\r"], "surface concrete");
}

#[test]
fn keys_typed_ahead_of_the_preset_picker_pick() {
    // the picker opens on the superball; the next one down is the golf ball (the header)
    typed_ahead(&[b"g", DOWN, b"\r"], "golf · ");
}
