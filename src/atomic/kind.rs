//! The kinds of file no output replaces (`atomic::Outputs::commit`, `cli::outputs::check`).

use std::fs;
use std::path::Path;

/// What an existing `path` is when it is no regular file, no link and no directory — "a
/// character device", "a block device", "a FIFO", "a socket" — which no output replaces: a
/// rename over a device puts a regular file in its place, so `/dev/null` itself would go
/// (tests/cli/outputs_regular_only.rs). A symbolic link is replaced itself, never
/// what it leads to; a directory is refused by the callers' own check.
pub fn refused_kind(path: &Path) -> Option<&'static str> {
    let t = fs::symlink_metadata(path).ok()?.file_type();
    if t.is_file() || t.is_symlink() || t.is_dir() {
        return None;
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_char_device() {
            return Some("a character device");
        }
        if t.is_block_device() {
            return Some("a block device");
        }
        if t.is_fifo() {
            return Some("a FIFO");
        }
        if t.is_socket() {
            return Some("a socket");
        }
    }
    Some("no regular file")
}

/// The refusal's words: "a FIFO, not a regular file (outputs replace regular files only)".
pub fn not_regular(kind: &str) -> String {
    format!("{kind}, not a regular file (outputs replace regular files only)")
}
