//! An inotify watch on the user's presets folder and on every folder of its path
//! (catalog_cache.rs): any event on it means "take the stamp again". Inotify sees a change
//! only where it is made through a watched folder on this machine, so a watch is armed only
//! where that is every change that can move the catalog; elsewhere `Watch::arm` gives `None`
//! and the stamp is taken at each call, as before:
//! - a symbolic link on the path, or among the folder's entries: its target's folder is not
//!   watched (an edit there, a link redirected further on, would go unseen);
//! - a file of the folder with another hard link: an edit through the other name is
//!   reported to the other folder only;
//! - a file system not known to be local (NFS, SMB, FUSE, 9p, …): a change made on another
//!   machine raises no event here;
//! - inotify unavailable (no instance left: `max_user_instances`).
//!
//! A forked child shares its parent's inotify instance, and whichever reads an event takes
//! it from the other: a watch armed before a fork is not trusted after it (`FORKS`).
//!
//! Written on rustix's inotify rather than the `notify` crate: `notify` delivers events from
//! an event thread of its own (a thread in every process that imports bouncelab, and none in
//! a forked child), where here one non-blocking read of a descriptor this module owns
//! answers at the call, in the caller's thread.

use rustix::fd::OwnedFd;
use rustix::fs::inotify::{self, CreateFlags, WatchFlags};
use rustix::io::Errno;
use std::mem::MaybeUninit;
use std::os::unix::fs::MetadataExt;
use std::path::Path;
use std::sync::Once;
use std::sync::atomic::{AtomicU64, Ordering};

/// Forks of this process since the module was loaded, counted in the child (`pthread_atfork`).
static FORKS: AtomicU64 = AtomicU64::new(0);

extern "C" fn forked() {
    FORKS.fetch_add(1, Ordering::Relaxed);
}

/// File systems whose every change passes through this kernel (linux/magic.h): ext2/3/4,
/// XFS, Btrfs, tmpfs, overlayfs, F2FS, ZFS, bcachefs, ramfs.
const LOCAL: [u64; 9] = [
    0xEF53,
    0x5846_5342,
    0x9123_683E,
    0x0102_1994,
    0x794C_7630,
    0xF2F5_2010,
    0x2FC1_2FC1,
    0xCA45_1A4E,
    0x8584_58F6,
];

/// A watch on the presets folder and its path, and the fork count it was armed at.
pub(super) struct Watch {
    fd: OwnedFd,
    /// The folder's own watch (`None`: the folder did not exist when armed).
    folder: Option<i32>,
    forks: u64,
}

/// What a watch has seen since it was armed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum News {
    /// Nothing: the stamp has not moved.
    None,
    /// A change on the folder's path only: the stamp tells whether the folder moved.
    Path,
    /// A change in the folder itself (or events lost, or a fork): read it again, whatever
    /// the stamp says (an edit may keep a file's size and modification time).
    Folder,
}

/// Whether `dir` is a real folder (no link) on a local file system; `None` where it does not
/// exist (its parent's watch sees it made).
fn local_folder(dir: &Path) -> Option<Result<(), ()>> {
    let meta = std::fs::symlink_metadata(dir).ok()?;
    let fs = rustix::fs::statfs(dir).map_err(|_| ());
    Some(match fs {
        Ok(s) if meta.is_dir() && LOCAL.contains(&(s.f_type as u64)) => Ok(()),
        _ => Err(()),
    })
}

/// Whether every entry of the folder `dir` is its only name (no link to elsewhere, no other
/// hard link to a file); true for a folder that does not exist or cannot be read.
fn entries_only_here(dir: &Path) -> bool {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return true;
    };
    entries.flatten().all(|e| {
        std::fs::symlink_metadata(e.path())
            .is_ok_and(|m| !m.file_type().is_symlink() && (m.is_dir() || m.nlink() == 1))
    })
}

impl Watch {
    /// A watch on `dir` (the folder's entries added, removed, renamed, written, their
    /// attributes changed; the folder itself moved or removed) and on each folder of its path
    /// that exists (an entry added, removed, renamed or its attributes changed: the path's
    /// next folder among them); `None` where that would not see every change (module docs).
    pub(super) fn arm(dir: Option<&Path>) -> Option<Watch> {
        let dir = dir.filter(|d| d.is_absolute())?;
        static AT_FORK: Once = Once::new();
        // SAFETY: registers a handler that only adds to an atomic counter (async-signal-safe)
        AT_FORK.call_once(|| unsafe {
            libc::pthread_atfork(None, None, Some(forked));
        });
        let forks = FORKS.load(Ordering::Relaxed);
        let fd = inotify::init(CreateFlags::CLOEXEC | CreateFlags::NONBLOCK).ok()?;
        let path = WatchFlags::CREATE
            | WatchFlags::DELETE
            | WatchFlags::MOVED_FROM
            | WatchFlags::MOVED_TO
            | WatchFlags::ATTRIB
            | WatchFlags::DELETE_SELF
            | WatchFlags::MOVE_SELF
            | WatchFlags::ONLYDIR
            | WatchFlags::DONT_FOLLOW;
        // from the root down: a folder found missing and made meanwhile is an event of its
        // parent's watch, armed before it was looked at
        let folders: Vec<&Path> = dir.ancestors().collect();
        let mut own = None;
        for (i, folder) in folders.into_iter().enumerate().rev() {
            match local_folder(folder) {
                None => continue,
                Some(Err(())) => return None,
                Some(Ok(())) => {}
            }
            let flags = match i {
                0 => path | WatchFlags::MODIFY | WatchFlags::CLOSE_WRITE,
                _ => path,
            };
            let wd = inotify::add_watch(&fd, folder, flags).ok()?;
            if i == 0 {
                own = Some(wd);
            }
        }
        entries_only_here(dir).then_some(Watch {
            fd,
            folder: own,
            forks,
        })
    }

    /// What happened since the watch was armed: every queued event read (a non-blocking
    /// read; nothing queued is one system call), the folder's own among them.
    pub(super) fn news(&self) -> News {
        if FORKS.load(Ordering::Relaxed) != self.forks {
            return News::Folder;
        }
        // room for many events, each at most 16 + 255 + 1 bytes: a buffer shorter than one
        // event makes the read fail (EINVAL), which reads as the folder's news
        let mut buf = [MaybeUninit::<u8>::uninit(); 4096];
        let mut events = inotify::Reader::new(&self.fd, &mut buf);
        let mut news = News::None;
        loop {
            match events.next() {
                Err(Errno::AGAIN) => return news,
                // the overflow event has no watch (-1): events were lost
                Ok(e)
                    if Some(e.wd()) != self.folder
                        && !e.events().contains(inotify::ReadFlags::QUEUE_OVERFLOW) =>
                {
                    news = News::Path;
                }
                // the folder's own, or an error: the watch is armed anew, no need to read on
                _ => return News::Folder,
            }
        }
    }
}
