//! The per-vector bound: a thread that ends the run when a vector takes longer than the timeout,
//! and the guard the harness puts around each vector (also driven by the crate's benchmark).

use std::fs::OpenOptions;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use super::record::Record;
use super::EXIT_FAILED;
use crate::implementation::Implementation;
use crate::runner::Plan;
use crate::verdict::Verdict;

/// The per-vector bound and the record of what is running: a thread ends the run when a
/// vector takes longer than the timeout, naming it; the supervising process reads the record
/// when the process ends early.
///
/// Judging a vector of the golden set takes well under a microsecond, and a system call takes
/// longer: what the guard does per vector is two atomic stores. No lock, no clock, no allocation,
/// no system call: the watchdog reads the vectors' states on its tick and times a vector from the
/// tick that first saw it running. Only the child that runs the vectors again to find the one a
/// run ended on (`supervise`) also writes each vector's start and end to its record.
pub(super) struct Watch {
    /// Per vector of the plan: `pass << 1 | 1` while it is judged, `pass << 1` once judged (0:
    /// not yet started). The pass tells the watchdog a vector judged again (the bench's guard
    /// judges a plan many times; the harness, once) from one still running.
    pub(super) states: Box<[AtomicU32]>,
    pub(super) timeout: Duration,
    /// The supervised child's file, for the note that the run came to its end.
    pub(super) progress: Option<PathBuf>,
    /// The record of each vector, when this child runs the vectors again to find one.
    record: Option<Record>,
    /// Set when the watchdog is to end (the bench's guard, dropped).
    pub(super) stopped: AtomicBool,
}

impl Watch {
    pub(super) fn new(vectors: usize, timeout: Duration, progress: Option<PathBuf>, record: Option<Record>) -> Watch {
        let states = (0..vectors).map(|_| AtomicU32::new(0)).collect();
        Watch { states, timeout, progress, record, stopped: AtomicBool::new(false) }
    }

    pub(super) fn begin(&self, index: usize, pass: u32) {
        if let Some(record) = &self.record {
            record.mark(index, Record::RUNNING);
        }
        self.states[index].store(pass << 1 | 1, Ordering::Relaxed);
    }

    pub(super) fn end(&self, index: usize, pass: u32) {
        self.states[index].store(pass << 1, Ordering::Relaxed);
        if let Some(record) = &self.record {
            record.mark(index, Record::JUDGED);
        }
    }

    /// The watchdog thread, which calls `late` with a vector that took longer than the timeout:
    /// it never holds the process (a thread does not keep it running). A vector started at most
    /// one tick before the tick that first sees it running, and is late once that tick is a
    /// timeout old: never before it has taken the timeout, at most two ticks after.
    pub(super) fn start(watch: &Arc<Watch>, late: impl Fn(usize) + Send + 'static) {
        let watch = Arc::clone(watch);
        let tick = (watch.timeout / 10).clamp(Duration::from_millis(5), Duration::from_millis(250));
        let spawned = std::thread::Builder::new().name("plcvec-watchdog".into()).spawn(move || {
            // (index, its state, the tick that first saw it running in that state)
            let mut running: Vec<(usize, u32, Instant)> = Vec::new();
            loop {
                std::thread::sleep(tick);
                if watch.stopped.load(Ordering::Relaxed) {
                    return;
                }
                let now = Instant::now();
                running.retain(|&(i, state, _)| watch.states[i].load(Ordering::Relaxed) == state);
                for (i, state) in watch.states.iter().enumerate() {
                    let state = state.load(Ordering::Relaxed);
                    if state & 1 == 1 && !running.iter().any(|&(j, s, _)| j == i && s == state) {
                        running.push((i, state, now));
                    }
                }
                if let Some(&(index, _, _)) = running.iter().find(|(_, _, seen)| now - *seen >= watch.timeout) {
                    late(index);
                }
            }
        });
        if let Err(e) = spawned {
            eprintln!("plcvec: cannot start the watchdog thread ({e}); vectors run without a time bound");
        }
    }
}

/// The guard the harness puts around each vector (the watchdog's states, and the record of each
/// vector in the child that runs the vectors again after a run ended early), driven from outside
/// the harness around [`judge_plan`]'s judging: the crate's benchmark sets the judging with it
/// beside the same judging without. Not part of the API; it may change in any release.
///
/// [`judge_plan`]: crate::judge_plan
#[doc(hidden)]
pub struct Guard {
    watch: Arc<Watch>,
    /// The passes judged so far.
    passes: AtomicU32,
}

#[doc(hidden)]
impl Guard {
    /// The guard a supervised child puts on a run of `plan`: the watchdog started with
    /// `timeout`, and `progress` (an existing file), when given, opened as the child opens the
    /// file its parent made; with `each_vector`, each vector recorded in it, as the child that
    /// runs the vectors again to find the one a run ended on records them. A vector that takes
    /// longer ends the process (status 101).
    pub fn start(
        plan: &Plan<'_>,
        timeout: Duration,
        progress: Option<&std::path::Path>,
        each_vector: bool,
    ) -> std::io::Result<Guard> {
        let file = progress.map(|path| OpenOptions::new().write(true).open(path)).transpose()?;
        let record = match (file, each_vector) {
            (Some(file), true) => Some(Record::create(file, plan.vectors().iter().map(|v| v.id()))?),
            _ => None,
        };
        let progress = progress.map(std::path::Path::to_path_buf);
        let watch = Arc::new(Watch::new(plan.len(), timeout, progress, record));
        Watch::start(&watch, move |late| {
            eprintln!("plcvec: the vector at {late} of the plan took longer than {} s", timeout.as_secs_f64());
            std::process::exit(i32::from(EXIT_FAILED));
        });
        Ok(Guard { watch, passes: AtomicU32::new(0) })
    }

    /// [`judge_plan`](crate::judge_plan) of the plan the guard was started with, the guard around
    /// each vector as the harness puts it around each test.
    pub fn judge_plan<I: Implementation + ?Sized>(&self, plan: &Plan<'_>, implementation: &mut I) -> Vec<Verdict> {
        assert_eq!(plan.len(), self.watch.states.len(), "the plan the guard was started with");
        let pass = self.passes.fetch_add(1, Ordering::Relaxed).wrapping_add(1) & (u32::MAX >> 1);
        crate::runner::judge_plan_marked(plan, implementation, |index, starts| {
            if starts {
                self.watch.begin(index, pass);
            } else {
                self.watch.end(index, pass);
            }
        })
    }
}

impl Drop for Guard {
    fn drop(&mut self) {
        self.watch.stopped.store(true, Ordering::Relaxed);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Instant;

    #[test]
    fn the_watchdog_names_a_vector_late_only_once_it_took_the_timeout() {
        let timeout = Duration::from_millis(100);
        let watch = Arc::new(Watch::new(3, timeout, None, None));
        let (tx, rx) = std::sync::mpsc::channel();
        let started = Instant::now();
        Watch::start(&watch, move |late| {
            let _ = tx.send((late, started.elapsed()));
            std::thread::sleep(Duration::from_secs(3600));
        });
        // Vector 0 judged over and over, each time quickly (a new pass each time), for longer than
        // the timeout; vector 2 never returns.
        watch.begin(2, 1);
        let mut pass = 0;
        while started.elapsed() < timeout * 3 {
            pass += 1;
            watch.begin(0, pass);
            watch.end(0, pass);
        }
        let (late, after) = rx.recv_timeout(Duration::from_secs(10)).expect("the watchdog named no vector");
        assert_eq!(late, 2);
        assert!(after >= timeout, "named after {after:?}, before the timeout");
        watch.stopped.store(true, Ordering::Relaxed);
    }
}
