//! The work behind each request, bounded: [`WORKERS`] threads answer the requests whose
//! head is complete; a command runs as a child process of this same binary (the CLI
//! itself), at most [`RUNNING`] at a time and [`ADMITTED`] admitted (running or waiting
//! at most [`TURN_WAIT`] for a turn), and is killed when the request's time budget runs
//! out (`503`). A request beyond the
//! admitted ones, or beyond the queue of [`QUEUE`] heads waiting for a worker, is `503` at
//! once. So pages and errors are answered while every computation is busy, and no
//! computation outlives its budget.

use super::api::{route, Prints, Route};
use super::http::{drain, send, Ready, Reply};
use crate::cli::io::message_of;
use std::ffi::OsString;
use std::io::Read;
use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::sync::mpsc::{Receiver, SyncSender, TrySendError};
use std::sync::{Arc, Condvar, Mutex};
use std::time::{Duration, Instant};

/// Threads answering requests (more than the computations admitted, so that pages and
/// errors are served while they all wait).
pub const WORKERS: usize = 16;
/// Computations running at once (more than the development machine's 2 cores, so that a
/// quick request is not held behind two long ones: the system shares the cores).
pub const RUNNING: usize = 4;
/// Computations admitted at once, running or waiting for their turn.
pub const ADMITTED: usize = 12;
/// Complete request heads waiting for a worker.
pub const QUEUE: usize = 64;
/// The longest a computation waits for its turn (then `503`: a client is told at once
/// that the server is busy, rather than after its whole budget).
pub const TURN_WAIT: Duration = Duration::from_millis(1500);

/// What every worker shares.
pub struct Shared {
    /// The binary run for a command (this one).
    pub exe: PathBuf,
    /// The time from a request's head to its answer that a computation may take.
    pub budget: Duration,
    /// Whether each request is logged on standard error.
    pub verbose: bool,
    slots: Slots,
}

impl Shared {
    /// What the workers share.
    pub fn new(exe: PathBuf, budget: Duration, verbose: bool) -> Shared {
        Shared {
            exe,
            budget,
            verbose,
            slots: Slots::default(),
        }
    }
}

/// The computations admitted: (running, waiting).
#[derive(Default)]
struct Slots {
    count: Mutex<(usize, usize)>,
    freed: Condvar,
}

/// A running computation's place, given back on drop.
struct Slot<'a>(&'a Slots);

impl Drop for Slot<'_> {
    fn drop(&mut self) {
        let mut c = self.0.count.lock().unwrap_or_else(|e| e.into_inner());
        c.0 -= 1;
        self.0.freed.notify_one();
    }
}

impl Slots {
    /// A place to run before `deadline`, or the reply that refuses the request (also when
    /// the client has gone meanwhile).
    fn enter(&self, deadline: Instant, gone: &dyn Fn() -> bool) -> Result<Slot<'_>, Reply> {
        let mut c = self.count.lock().unwrap_or_else(|e| e.into_inner());
        if c.0 + c.1 >= ADMITTED {
            return Err(busy(format!(
                "the server is busy: {ADMITTED} computations are running or waiting; retry, or use the command line"
            )));
        }
        c.1 += 1;
        while c.0 >= RUNNING {
            let now = Instant::now();
            if gone() {
                c.1 -= 1;
                return Err(Reply::error(499, "the client closed the connection".into()));
            }
            if now >= deadline {
                c.1 -= 1;
                return Err(busy(format!(
                    "the server is busy: {RUNNING} computations are running and none finished within {} s; retry, or use the command line",
                    TURN_WAIT.as_secs_f64()
                )));
            }
            c = self
                .freed
                .wait_timeout(c, (deadline - now).min(GONE_POLL))
                .unwrap_or_else(|e| e.into_inner())
                .0;
        }
        c.1 -= 1;
        c.0 += 1;
        Ok(Slot(self))
    }
}

fn busy(message: String) -> Reply {
    Reply::error(503, message)
}

/// The workers' queue: a complete head is handed over, or refused at once when it is full.
pub fn start(shared: Arc<Shared>) -> SyncSender<(Ready, Instant)> {
    let (tx, rx) = std::sync::mpsc::sync_channel::<(Ready, Instant)>(QUEUE);
    let rx = Arc::new(Mutex::new(rx));
    for _ in 0..WORKERS {
        let (rx, shared) = (Arc::clone(&rx), Arc::clone(&shared));
        std::thread::spawn(move || work(&rx, &shared));
    }
    tx
}

/// Hands `ready` to a worker, or answers `503` when the queue is full.
pub fn hand_over(tx: &SyncSender<(Ready, Instant)>, ready: Ready) {
    if let Err(TrySendError::Full((ready, _)) | TrySendError::Disconnected((ready, _))) =
        tx.try_send((ready, Instant::now()))
    {
        let reply = busy(format!(
            "the server is busy: {QUEUE} requests are waiting; retry"
        ));
        send(ready.stream, &reply);
    }
}

fn work(rx: &Mutex<Receiver<(Ready, Instant)>>, shared: &Shared) {
    loop {
        let next = rx.lock().unwrap_or_else(|e| e.into_inner()).recv();
        let Ok((ready, arrived)) = next else { return };
        // a panic here is a bug of ours: the connection is dropped, the worker goes on
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            answer(ready, arrived, shared)
        }));
    }
}

fn answer(ready: Ready, arrived: Instant, shared: &Shared) {
    let Ready { mut stream, head } = ready;
    let (what, reply) = match head {
        Err(reply) => (String::from("-"), reply),
        Ok(head) => {
            drain(&mut stream, head.body_left);
            let reply = match route(&head.method, &head.target) {
                Route::Reply(r) => r,
                Route::Run { args, prints } => {
                    let deadline = arrived + shared.budget;
                    let gone = || client_gone(&stream);
                    match shared.slots.enter(deadline.min(arrived + TURN_WAIT), &gone) {
                        Ok(_slot) => run(shared, &args, prints, (deadline, &gone)),
                        Err(r) => r,
                    }
                }
            };
            (format!("{} {}", head.method, head.target), reply)
        }
    };
    if shared.verbose {
        eprintln!(
            "{what} {} {:.1} ms",
            reply.status,
            arrived.elapsed().as_secs_f64() * 1e3
        );
    }
    send(stream, &reply);
}

/// What a child process left: its exit code (`None`: killed by a signal) and its output.
struct Finished {
    code: Option<i32>,
    out: Vec<u8>,
    err: Vec<u8>,
}

/// Runs `args` as a child of `shared.exe`; the reply is its output: a command's JSON
/// (exit 0 or 1: `200`; exit 2: `400`), a figure's SVG or the report's HTML (exit 1, no
/// figure: `422`).
fn run(
    shared: &Shared,
    args: &[OsString],
    prints: Prints,
    until: (Instant, &dyn Fn() -> bool),
) -> Reply {
    let done = match child(&shared.exe, args, until) {
        Ok(Ended::Exited(done)) => done,
        Ok(Ended::ClientGone) => {
            return Reply::error(499, "the client closed the connection".into())
        }
        Ok(Ended::OverBudget) => {
            return busy(format!(
                "the computation was stopped after the server's time budget of {} s (serve --budget); the command line has no such limit",
                shared.budget.as_secs_f64()
            ))
        }
        Err(e) => return Reply::error(500, format!("internal error: cannot run the command: {e}")),
    };
    let content_type = match prints {
        Prints::Json => "application/json",
        Prints::Svg => "image/svg+xml",
        Prints::Html => "text/html; charset=utf-8",
    };
    match (done.code, prints) {
        (Some(0), _) | (Some(1), Prints::Json) => Reply {
            status: 200,
            content_type,
            body: done.out,
        },
        (Some(1), _) => Reply::error(422, message_of(&done.err)),
        (Some(2), Prints::Json) if !done.out.is_empty() => Reply::json(400, done.out),
        (Some(2), _) => Reply::error(400, message_of(&done.err)),
        _ => Reply::error(
            500,
            "internal error: the command failed (a bug: please report the request)".into(),
        ),
    }
}

/// How a child process ended.
enum Ended {
    /// By itself.
    Exited(Finished),
    /// Killed at the deadline.
    OverBudget,
    /// Killed because the client closed the connection (its answer is not wanted).
    ClientGone,
}

/// How often a waiting request checks that its client is still there.
const GONE_POLL: Duration = Duration::from_millis(20);

/// Whether the client has closed its side of the connection (a read would see its end).
fn client_gone(stream: &std::net::TcpStream) -> bool {
    if stream.set_nonblocking(true).is_err() {
        return true;
    }
    let mut b = [0u8; 1];
    let gone = match stream.peek(&mut b) {
        Ok(0) => true,
        Ok(_) => false,
        Err(e) => e.kind() != std::io::ErrorKind::WouldBlock,
    };
    let _ = stream.set_nonblocking(false);
    gone
}

/// Runs `exe args` until it exits, the deadline passes or the client goes (killed then).
fn child(
    exe: &std::path::Path,
    args: &[OsString],
    (deadline, gone): (Instant, &dyn Fn() -> bool),
) -> std::io::Result<Ended> {
    let mut c = Command::new(exe)
        .args(args)
        .env(crate::cli::progress::PROGRESS_ENV, "off")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()?;
    let collect = |mut r: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut v = Vec::new();
            let _ = r.read_to_end(&mut v);
            v
        })
    };
    let out = c.stdout.take().map(|o| collect(Box::new(o)));
    let err = c.stderr.take().map(|e| collect(Box::new(e)));
    let mut nap = Duration::from_micros(50);
    let mut checked = Instant::now();
    let status = loop {
        if let Some(s) = c.try_wait()? {
            break Ok(s);
        }
        let over = Instant::now() >= deadline;
        let left = checked.elapsed() >= GONE_POLL && {
            checked = Instant::now();
            gone()
        };
        if over || left {
            let _ = c.kill();
            let _ = c.wait();
            break Err(if over {
                Ended::OverBudget
            } else {
                Ended::ClientGone
            });
        }
        std::thread::sleep(nap.min(deadline.saturating_duration_since(Instant::now())));
        nap = (nap * 2).min(Duration::from_millis(5));
    };
    let join = |h: Option<std::thread::JoinHandle<Vec<u8>>>| {
        h.and_then(|h| h.join().ok()).unwrap_or_default()
    };
    let (out, err) = (join(out), join(err));
    Ok(match status {
        Ok(s) => Ended::Exited(Finished {
            code: s.code(),
            out,
            err,
        }),
        Err(why) => why,
    })
}
