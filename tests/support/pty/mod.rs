//! The real `bouncelab` explorer under a pseudo-terminal, for the tests that need a terminal:
//! the child gets the pty's slave side as stdin, stdout, stderr and controlling terminal (its
//! own session), 120 × 40 cells; a thread reads everything it writes from the master side, so
//! it never blocks on a full pty buffer. Every wait has a deadline: a stuck child is killed and
//! the test fails with what the child printed, it never hangs.
#![allow(dead_code)] // shared by several test crates, each of which uses a part

use rustix::fd::{AsFd, OwnedFd};
use rustix::fs::{Mode, OFlags};
use rustix::pty::{OpenptFlags, grantpt, openpt, ptsname, unlockpt};
use rustix::termios::{Termios, Winsize, tcgetattr, tcsetwinsize};
use std::fs::File;
use std::io::{ErrorKind, Read, Write};
use std::os::unix::process::{CommandExt, ExitStatusExt};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::mpsc::{Receiver, RecvTimeoutError, channel};
use std::time::{Duration, Instant};

/// Generous: the machine may have two cores and another build running.
pub const TIMEOUT: Duration = Duration::from_secs(30);

/// The sequences the explorer must send around its full-screen use.
pub const ENTER_ALT_SCREEN: &str = "\x1b[?1049h";
pub const LEAVE_ALT_SCREEN: &str = "\x1b[?1049l";
pub const HIDE_CURSOR: &str = "\x1b[?25l";
pub const SHOW_CURSOR: &str = "\x1b[?25h";

/// The explorer running under a pty.
pub struct Explorer {
    child: Child,
    master: File,
    /// Kept open so the terminal's settings can be read after the child exits.
    slave: Option<OwnedFd>,
    rx: Receiver<Vec<u8>>,
    output: Vec<u8>,
    /// Where the next [`Explorer::wait_for`] starts looking.
    seen: usize,
    /// The terminal's settings before the child started.
    pub before: Termios,
}

/// `bouncelab figure cor-zeta --law hertz --points POINTS --out HOME/slow.svg` under a pty with
/// `home` as its config: 3 × POINTS Hertz-law impacts behind a progress bar (`/600 impacts` at
/// 200 points), some seconds of work in a debug build; the figure's path.
pub fn slow_figure(home: &Path, points: u32) -> (Explorer, PathBuf) {
    let out = home.join("slow.svg");
    let points = points.to_string();
    let path = out.to_str().unwrap();
    let args = [
        "figure", "cor-zeta", "--law", "hertz", "--points", &points, "--out", path,
    ];
    (Explorer::spawn(home, None, &args), out)
}

/// The mode flags of a terminal, which raw mode changes (rustix's `Termios` has no `==`).
pub fn modes(t: &Termios) -> String {
    format!(
        "input {:?}\noutput {:?}\ncontrol {:?}\nlocal {:?}",
        t.input_modes, t.output_modes, t.control_modes, t.local_modes
    )
}

impl Explorer {
    /// Start `bouncelab ARGS` with `config` as XDG_CONFIG_HOME and HOME, and
    /// `BOUNCELAB_TEST_FAULT=fault` when given; nothing else of the test's environment.
    pub fn spawn(config: &Path, fault: Option<&str>, args: &[&str]) -> Explorer {
        let master = openpt(OpenptFlags::RDWR | OpenptFlags::NOCTTY).expect("openpt");
        grantpt(&master).expect("grantpt");
        unlockpt(&master).expect("unlockpt");
        let name = ptsname(&master, Vec::new()).expect("ptsname");
        // NOCTTY: the slave must become the child's terminal, never this test process's
        let slave = rustix::fs::open(
            name.as_c_str(),
            OFlags::RDWR | OFlags::NOCTTY | OFlags::CLOEXEC,
            Mode::empty(),
        )
        .expect("open the pty's slave");
        let size = Winsize {
            ws_row: 40,
            ws_col: 120,
            ws_xpixel: 0,
            ws_ypixel: 0,
        };
        tcsetwinsize(&slave, size).expect("set the pty's size");
        let before = tcgetattr(&slave).expect("tcgetattr");
        let stdio = || Stdio::from(slave.try_clone().expect("dup the slave"));
        let child = {
            let mut cmd = Command::new(env!("CARGO_BIN_EXE_bouncelab"));
            cmd.args(args)
                .env_clear()
                .env("XDG_CONFIG_HOME", config)
                .env("HOME", config)
                .env("TERM", "xterm-256color")
                .env("NO_COLOR", "1")
                .env("RUST_BACKTRACE", "0")
                .stdin(stdio())
                .stdout(stdio())
                .stderr(stdio());
            if let Some(f) = fault {
                cmd.env("BOUNCELAB_TEST_FAULT", f);
            }
            // SAFETY: between fork and exec only two system calls, no allocation or locks:
            // a new session whose controlling terminal is the pty (stdin, already in place),
            // as a terminal emulator would set it up
            unsafe {
                cmd.pre_exec(|| {
                    rustix::process::setsid()?;
                    rustix::process::ioctl_tiocsctty(std::io::stdin().as_fd())?;
                    Ok(())
                });
            }
            cmd.spawn().expect("start bouncelab")
            // `cmd` and its copies of the slave are dropped here: only the child holds it
        };
        let master = File::from(master);
        let mut reader = master.try_clone().expect("dup the master");
        let (tx, rx) = channel();
        std::thread::spawn(move || {
            let mut buf = [0u8; 8192];
            loop {
                match reader.read(&mut buf) {
                    // EIO: every slave descriptor is closed
                    Ok(0) => break,
                    Ok(n) => {
                        if tx.send(buf[..n].to_vec()).is_err() {
                            break;
                        }
                    }
                    Err(e) if e.kind() == ErrorKind::Interrupted => {}
                    Err(_) => break,
                }
            }
        });
        Explorer {
            child,
            master,
            slave: Some(slave),
            rx,
            output: Vec::new(),
            seen: 0,
            before,
        }
    }

    /// Resize the terminal to `cols` × `rows`, as a terminal emulator does: the kernel then
    /// sends SIGWINCH to the explorer.
    #[allow(dead_code)]
    pub fn resize(&mut self, cols: u16, rows: u16) {
        let size = Winsize {
            ws_row: rows,
            ws_col: cols,
            ws_xpixel: 0,
            ws_ypixel: 0,
        };
        match &self.slave {
            Some(slave) => tcsetwinsize(slave, size),
            None => tcsetwinsize(&self.master, size),
        }
        .expect("resize the pty");
    }

    /// Type `bytes` (raw mode: `\r` is Enter, `\x1b` Esc).
    pub fn send(&mut self, bytes: &[u8]) {
        self.master.write_all(bytes).expect("write to the pty");
        self.master.flush().expect("flush the pty");
    }

    /// Take what arrived within `wait`.
    fn pump(&mut self, wait: Duration) -> bool {
        match self.rx.recv_timeout(wait) {
            Ok(chunk) => {
                self.output.extend_from_slice(&chunk);
                while let Ok(more) = self.rx.try_recv() {
                    self.output.extend_from_slice(&more);
                }
                true
            }
            Err(RecvTimeoutError::Timeout) => true,
            Err(RecvTimeoutError::Disconnected) => false,
        }
    }

    /// Wait until `needle` appears in the output after the previous match. Needles should
    /// hold no spaces: ratatui skips cells that did not change, so a space can be a cursor
    /// move in the byte stream.
    pub fn wait_for(&mut self, needle: &str) {
        self.wait_for_within(needle, TIMEOUT);
    }

    /// [`Explorer::wait_for`] with its own time limit, for work whose first output takes long
    /// in a debug build on a loaded machine.
    pub fn wait_for_within(&mut self, needle: &str, limit: Duration) {
        let deadline = Instant::now() + limit;
        loop {
            if let Some(i) = find(&self.output[self.seen..], needle.as_bytes()) {
                self.seen += i + needle.len();
                return;
            }
            let exited = self.child.try_wait().ok().flatten();
            if !self.pump(Duration::from_millis(50)) || exited.is_some() && !self.pump_rest() {
                self.fail(&format!(
                    "{needle:?} never came; the explorer exited: {exited:?}"
                ));
            }
            if Instant::now() > deadline {
                self.fail(&format!("{needle:?} did not come within {limit:?}"));
            }
        }
    }

    /// After an exit: whether anything is still arriving.
    fn pump_rest(&mut self) -> bool {
        let before = self.output.len();
        self.pump(Duration::from_millis(200));
        self.output.len() > before
    }

    /// [`Explorer::spawn`], its first frame drawn: the explorer, and the terminal's modes
    /// before it started ([`modes`]), to hold its exit against.
    pub fn started(config: &Path, fault: Option<&str>, args: &[&str]) -> (Explorer, String) {
        let mut x = Explorer::spawn(config, fault, args);
        let before = modes(&x.before);
        x.wait_for_first_draw();
        (x, before)
    }

    /// The first frame is drawn: the explorer reads keys from now on.
    pub fn wait_for_first_draw(&mut self) {
        self.wait_for(ENTER_ALT_SCREEN);
        self.wait_for("bouncelab");
    }

    /// Poll `done` until it holds, reading the output meanwhile; fail after [`TIMEOUT`].
    pub fn wait_until(&mut self, what: &str, mut done: impl FnMut() -> bool) {
        let deadline = Instant::now() + TIMEOUT;
        while !done() {
            self.pump(Duration::from_millis(20));
            if Instant::now() > deadline {
                self.fail(&format!("{what}: not within {TIMEOUT:?}"));
            }
        }
    }

    /// Send `sig` to the child, as `kill -SIG`.
    pub fn signal(&self, sig: rustix::process::Signal) {
        let pid = rustix::process::Pid::from_raw(self.child.id() as i32).expect("a pid");
        rustix::process::kill_process(pid, sig).expect("signal the explorer");
    }

    /// SIGKILL, as `kill -9`.
    pub fn kill(&mut self) {
        self.child.kill().expect("kill the explorer");
    }

    /// Wait for the child to exit (killing it and failing after [`TIMEOUT`]); then the
    /// terminal's settings as the child left them, and everything it printed.
    pub fn finish(mut self) -> (ExitStatus, Termios, String) {
        let deadline = Instant::now() + TIMEOUT;
        let status = loop {
            if let Some(s) = self.child.try_wait().expect("wait for the explorer") {
                break s;
            }
            self.pump(Duration::from_millis(20));
            if Instant::now() > deadline {
                self.fail(&format!("did not exit within {TIMEOUT:?}"));
            }
        };
        let slave = self.slave.take().expect("the slave is open");
        let after = tcgetattr(&slave).expect("tcgetattr after the exit");
        // with the last slave descriptor closed the reader sees EIO and stops: the output is
        // complete once the channel disconnects
        drop(slave);
        let deadline = Instant::now() + TIMEOUT;
        while self.pump(Duration::from_millis(50)) && Instant::now() < deadline {}
        let out = String::from_utf8_lossy(&self.output).into_owned();
        (status, after, out)
    }

    /// [`finish`](Explorer::finish), the explorer having exited 0 and given the terminal back
    /// as `before` (its [`modes`] at the start) had it; everything it printed.
    pub fn finish_restored(self, before: &str) -> String {
        let (status, after, out) = self.finish();
        assert!(status.success(), "{status:?}\n{}", out.escape_debug());
        assert_restored(before, &after, &out);
        out
    }

    /// The child's process id.
    pub fn pid(&self) -> u32 {
        self.child.id()
    }

    /// The terminal's settings now, while the child runs.
    pub fn termios_now(&self) -> Termios {
        tcgetattr(self.slave.as_ref().expect("the slave is open")).expect("tcgetattr")
    }

    /// Everything the child printed so far.
    pub fn output(&self) -> String {
        String::from_utf8_lossy(&self.output).into_owned()
    }

    /// Kill the child and fail with what it printed.
    fn fail(&mut self, why: &str) -> ! {
        let _ = self.child.kill();
        let _ = self.child.wait();
        panic!(
            "{why}\n--- output ---\n{}",
            String::from_utf8_lossy(&self.output).escape_debug()
        );
    }
}

impl Drop for Explorer {
    /// A failed assertion must not leave a child running.
    fn drop(&mut self) {
        if let Ok(None) = self.child.try_wait() {
            let _ = self.child.kill();
            let _ = self.child.wait();
        }
    }
}

/// What every exit must leave: the settings from before the start (`before`, as [`modes`]
/// gives them), in cooked mode, the alternate screen left, the cursor shown after it was last
/// hidden.
pub fn assert_restored(before: &str, after: &Termios, out: &str) {
    use rustix::termios::LocalModes;
    let cooked = LocalModes::ICANON | LocalModes::ECHO;
    assert!(
        after.local_modes.contains(cooked),
        "not back in cooked mode: {:?}",
        after.local_modes
    );
    assert_eq!(modes(after), before, "the terminal's settings changed");
    assert!(
        out.contains(LEAVE_ALT_SCREEN),
        "never left the alternate screen"
    );
    let hidden = out
        .rfind(HIDE_CURSOR)
        .expect("the explorer hides the cursor");
    let shown = out.rfind(SHOW_CURSOR).expect("the cursor is shown again");
    assert!(shown > hidden, "the cursor was last hidden, not shown");
}

/// The signal that ended the child, if one did.
pub fn signal(status: &ExitStatus) -> Option<i32> {
    status.signal()
}

fn find(hay: &[u8], needle: &[u8]) -> Option<usize> {
    hay.windows(needle.len()).position(|w| w == needle)
}
