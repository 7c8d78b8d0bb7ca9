//! How fast the crate judges the golden set with the reference implementation, in process,
//! after loading: `cargo run --release --example bench` (or `verifiers/rust/bench`).
//!
//! Loading (parsing the embedded copy and working out every vector's expectation) is timed
//! apart. A pass judges every vector once; the figure is the median of the passes after a few
//! warm-up passes (at least `PASSES`, and as many more as fit in `SECONDS`, so that the thread's
//! CPU time over them is measured to well under 1%). The last line is the JSON object
//! `plcvec bench-native` reads.
//!
//! Then the guard a user's test run puts around each vector (`plcvec::harness`: the watchdog of
//! `PLCVEC_TIMEOUT`, in the supervised child that notes in a file its parent made that the run
//! came to its end), through the harness's own guard (`plcvec::harness::Guard`, hidden from the
//! API's documentation: it exists for this bench) around the same judging as an unguarded pass,
//! with the file as the child has it. Each iteration times an unguarded pass and a guarded pass
//! back to back, which goes first alternating, so that both see the same state of a noisy
//! machine; then the same for the guard of a run in process, and for the guard of the child that
//! runs the vectors again, each recorded, after a run ended early:
//!
//! - `guarded_ratio`: the median over iterations of unguarded seconds / guarded seconds of the
//!   same iteration (1.0: the guard costs nothing per vector);
//! - `guarded_ratio_fastest`: the fastest unguarded pass / the fastest guarded pass;
//! - `guarded_vectors_per_s`, `unguarded_loop_vectors_per_s`: the vectors / the median guarded
//!   pass, and / the median unguarded pass paired with them (`vectors_per_s` is from the
//!   unguarded passes before, run alone);
//! - `guard_fixed_seconds`: what the guard costs once per run, not per vector (opening the file,
//!   starting the watchdog thread, and stopping it), the median of `FIXED_SAMPLES` starts, kept
//!   out of the passes above: the guard is started once, before them. A test run also starts the
//!   test binary a second time (the supervised child, which loads the suite again: about
//!   `load_seconds`); that is not measured here. The guarded passes hold none of it, so
//!   `guarded_ratio` is already the per-vector figure;
//! - `guarded_in_process_vectors_per_s`, `guarded_in_process_ratio`: the same for the guard of a
//!   run in process (`Harness::in_process`: the watchdog, no child, no file);
//! - `each_vector_guarded_ratio`: as `guarded_ratio`, for the guard of the child that runs the
//!   vectors again to name the one a run ended on (two one-byte writes to its record per vector):
//!   paid only after a run ended early, never by a run that comes to its end.
//!
//! The harness's own work per test that is not the guard (an implementation built per vector,
//! the known-failures bookkeeping, the verdicts kept for the run's text) and libtest-mimic's
//! per-test cost are in no pass.
#![forbid(unsafe_code)]

use std::fs::File;
use std::path::Path;
use std::time::{Duration, Instant};

use plcvec::harness::Guard;
use plcvec::{Choices, OnMemory, Plan, Status, Suite, Verdict};
use plcvec_reference::Reference;

const WARM_UP: usize = 3;
const PASSES: usize = 20;
/// Passes go on until this much time has gone by (the kernel counts a thread's CPU time in
/// scheduler ticks, up to 10 ms: one pass is far shorter than that).
const SECONDS: f64 = 2.0;
/// A bound on the passes, whatever the clock says.
const MAX_PASSES: usize = 1_000_000;
/// Paired iterations (an unguarded and a guarded pass each): at least this many, and as many more
/// as fit in `PAIRED_SECONDS`, up to `MAX_PAIRED`.
const PAIRED: usize = 300;
const PAIRED_SECONDS: f64 = 2.5;
/// The same for the guard of a run in process.
const IN_PROCESS_SECONDS: f64 = 1.0;
const MAX_PAIRED: usize = 100_000;
/// The same for the guard that records each vector (ten times slower a pass).
const EACH_VECTOR_PAIRED: usize = 50;
const EACH_VECTOR_SECONDS: f64 = 0.5;
/// Starts of the guard timed for its fixed cost.
const FIXED_SAMPLES: usize = 21;

#[allow(
    clippy::too_many_lines,
    reason = "over 80 lines: the bench's passes one after the other, each figure beside the pass that \
              measures it, as the header of its JSON line lists them"
)]
fn main() -> std::process::ExitCode {
    let started = Instant::now();
    let suite = match Suite::from_env() {
        Ok(s) => s,
        Err(e) => {
            eprintln!("bench: {e}");
            return std::process::ExitCode::from(2);
        }
    };
    let plan = Plan::new(&suite, suite.vectors().iter().collect(), &Choices::new()).expect("the expectations");
    let load_seconds = started.elapsed().as_secs_f64();

    let mut reference = OnMemory(Reference::new());
    let mut seconds = Vec::new();
    let mut measuring = None; // (the clock, this thread's CPU time) when the first measured pass began
    for pass in 0..WARM_UP + MAX_PASSES {
        if pass == WARM_UP {
            measuring = Some((Instant::now(), thread_cpu_seconds()));
        }
        let start = Instant::now();
        let verdicts = plcvec::judge_plan(&plan, &mut reference);
        let elapsed = start.elapsed().as_secs_f64();
        if !all_pass(&plan, &verdicts) {
            return std::process::ExitCode::from(1);
        }
        if pass >= WARM_UP {
            seconds.push(elapsed);
        }
        if seconds.len() >= PASSES && measuring.is_some_and(|(since, _)| since.elapsed().as_secs_f64() >= SECONDS) {
            break;
        }
    }
    let passes = seconds.len();
    let cpu_total = measuring.and_then(|(_, start)| Some(thread_cpu_seconds()? - start?));
    let wall = median(&mut seconds);
    let fastest = seconds[0]; // sorted by median()
    let n = plan.len();
    let rate = n as f64 / wall;
    println!("{:50} {:>8} {:>12}", "judging the golden set in process (rust reference)", "vectors", "vectors/s");
    println!("{:50} {:>8} {:>12.0}", format!("wall clock, median: pass {wall:.6} s"), n, rate);
    println!("{:50} {:>8} {:>12.0}", format!("wall clock, fastest: pass {fastest:.6} s"), n, n as f64 / fastest);
    // On a shared machine the wall clock counts the time other processes hold the CPU; the
    // thread's own CPU time is shown beside it, over all the passes (one pass is shorter than
    // the tick the kernel counts it in).
    // The CPU figure leads the note: `plcvec bench-native` shows the note's first 40-odd characters.
    // `cpu_vectors_per_s` is the key `plcvec bench-native` sets beside the other side's (its
    // "by CPU time" ratio), as the Go and TypeScript benches give it.
    let (cpu_note, cpu_key) = match cpu_total.filter(|&t| t > 0.0) {
        Some(total) => {
            let cpu = total / passes as f64;
            println!(
                "{:50} {:>8} {:>12.0}",
                format!("this thread's CPU time, mean: pass {cpu:.6} s"),
                n,
                n as f64 / cpu
            );
            let cpu_rate = n as f64 / cpu;
            (format!("{cpu_rate:.0}/s by CPU time, "), format!(", \"cpu_vectors_per_s\": {cpu_rate:.0}"))
        }
        None => (String::new(), String::new()),
    };
    let fastest_rate = n as f64 / fastest;
    println!("{:50}", format!("loading and expectations: {load_seconds:.3} s"));

    let guarded = match guarded(&plan, &mut reference) {
        Ok(Some(g)) => g,
        Ok(None) => return std::process::ExitCode::from(1),
        Err(e) => {
            eprintln!("bench: the guard's progress file: {e}");
            return std::process::ExitCode::from(1);
        }
    };
    let (child, in_process, each) = (&guarded.child, &guarded.in_process, &guarded.each_vector);
    let guarded_rate = n as f64 / child.seconds;
    println!(
        "{:50} {:>8} {:>12.0}",
        format!("under the harness's guard, median: pass {:.6} s", child.seconds),
        n,
        guarded_rate
    );
    println!(
        "{:50}",
        format!(
            "  guarded ratio {:.3} (median of {} paired passes), {:.3} fastest to fastest; once a run {:.6} s",
            child.ratio, child.iterations, child.ratio_fastest, guarded.fixed
        )
    );
    println!(
        "{:50} {:>8} {:>12.0}",
        format!("  unguarded beside it, median: pass {:.6} s", child.unguarded),
        n,
        n as f64 / child.unguarded
    );
    println!(
        "{:50} {:>8} {:>12.0}",
        format!("in process, median: pass {:.6} s", in_process.seconds),
        n,
        n as f64 / in_process.seconds
    );
    println!("{:50}", format!("  ratio {:.3} (median of {} paired passes)", in_process.ratio, in_process.iterations));
    println!(
        "{:50} {:>8} {:>12.0}",
        format!("recording each vector, median: pass {:.6} s", each.seconds),
        n,
        n as f64 / each.seconds
    );
    println!(
        "{:50}",
        format!(
            "  ratio {:.3} (median of {} paired passes; only after a run ended early)",
            each.ratio, each.iterations
        )
    );
    println!(
        "{{\"lang\": \"rust\", \"vectors\": {n}, \"passes\": {passes}, \"load_seconds\": {load_seconds:.4}, \"seconds\": {wall:.6}, \"vectors_per_s\": {rate:.0}{cpu_key}, \"guarded_vectors_per_s\": {guarded_rate:.0}, \"unguarded_loop_vectors_per_s\": {:.0}, \"guarded_in_process_vectors_per_s\": {:.0}, \"guarded_ratio\": {:.3}, \"guarded_ratio_fastest\": {:.3}, \"guarded_iterations\": {}, \"guard_fixed_seconds\": {:.6}, \"guarded_in_process_ratio\": {:.3}, \"each_vector_guarded_ratio\": {:.3}, \"note\": \"{cpu_note}median of {passes} passes after {WARM_UP} warm-up, {fastest_rate:.0}/s in the fastest pass\"}}",
        n as f64 / child.unguarded,
        n as f64 / in_process.seconds,
        child.ratio,
        child.ratio_fastest,
        child.iterations,
        guarded.fixed,
        in_process.ratio,
        each.ratio
    );
    std::process::ExitCode::SUCCESS
}

/// Whether every verdict is a pass (a fast wrong answer is not a figure); if not, says which.
fn all_pass(plan: &Plan<'_>, verdicts: &[Verdict]) -> bool {
    match plan.vectors().iter().zip(verdicts).find(|(_, v)| v.status != Status::Pass) {
        Some((v, verdict)) => {
            eprintln!("bench: the reference did not pass {}: {:?}", v.id(), verdict);
            false
        }
        None => true,
    }
}

struct Guarded {
    /// The guard of a run's child.
    child: Paired,
    /// The guard of a run in process (`Harness::in_process`: the watchdog alone).
    in_process: Paired,
    /// The guard of the child that runs the vectors again, each recorded, after a run ended early.
    each_vector: Paired,
    /// The guard's cost once per run, seconds.
    fixed: f64,
}

/// Unguarded and guarded passes, paired.
struct Paired {
    /// The median guarded pass, seconds.
    seconds: f64,
    /// The median unguarded pass, seconds.
    unguarded: f64,
    ratio: f64,
    ratio_fastest: f64,
    iterations: usize,
}

/// The paired passes of both guards, their file in the temporary folder as the supervised child's;
/// `None` when a pass did not pass.
fn guarded(plan: &Plan<'_>, reference: &mut OnMemory<Reference>) -> std::io::Result<Option<Guarded>> {
    let path = std::env::temp_dir().join(format!("plcvec-bench-progress-{}", std::process::id()));
    let result = both(plan, reference, &path);
    let _ = std::fs::remove_file(&path);
    result
}

fn both(plan: &Plan<'_>, reference: &mut OnMemory<Reference>, path: &Path) -> std::io::Result<Option<Guarded>> {
    File::create(path)?;
    let timeout = Duration::from_secs_f64(plcvec::harness::DEFAULT_TIMEOUT_S);
    let mut fixed = Vec::new();
    for _ in 0..FIXED_SAMPLES {
        let start = Instant::now();
        drop(Guard::start(plan, timeout, Some(path), false)?);
        fixed.push(start.elapsed().as_secs_f64());
    }
    let guard = Guard::start(plan, timeout, Some(path), false)?;
    let Some(child) = paired(plan, reference, &guard, PAIRED, PAIRED_SECONDS) else { return Ok(None) };
    drop(guard);
    let guard = Guard::start(plan, timeout, None, false)?;
    let Some(in_process) = paired(plan, reference, &guard, PAIRED, IN_PROCESS_SECONDS) else { return Ok(None) };
    drop(guard);
    // Apart, after: its passes are ten times slower, and would slow the passes after them.
    let guard = Guard::start(plan, timeout, Some(path), true)?;
    let Some(each_vector) = paired(plan, reference, &guard, EACH_VECTOR_PAIRED, EACH_VECTOR_SECONDS) else {
        return Ok(None);
    };
    Ok(Some(Guarded { child, in_process, each_vector, fixed: median(&mut fixed) }))
}

/// Iterations of an unguarded pass and a pass under `guard`, back to back, which goes first
/// alternating: at least `at_least`, and as many more as fit in `seconds`.
fn paired(
    plan: &Plan<'_>,
    reference: &mut OnMemory<Reference>,
    guard: &Guard,
    at_least: usize,
    seconds: f64,
) -> Option<Paired> {
    let (mut unguarded, mut guarded, mut ratios) = (Vec::new(), Vec::new(), Vec::new());
    let mut measuring = None;
    for iteration in 0..WARM_UP + MAX_PAIRED {
        if iteration == WARM_UP {
            measuring = Some(Instant::now());
        }
        let mut took = [0.0; 2]; // unguarded, guarded
        for which in [iteration % 2, 1 - iteration % 2] {
            let start = Instant::now();
            let verdicts =
                if which == 0 { plcvec::judge_plan(plan, reference) } else { guard.judge_plan(plan, reference) };
            took[which] = start.elapsed().as_secs_f64();
            if !all_pass(plan, &verdicts) {
                return None;
            }
        }
        if iteration >= WARM_UP {
            unguarded.push(took[0]);
            guarded.push(took[1]);
            ratios.push(took[0] / took[1]);
        }
        if ratios.len() >= at_least && measuring.is_some_and(|since: Instant| since.elapsed().as_secs_f64() >= seconds)
        {
            break;
        }
    }
    let iterations = ratios.len();
    Some(Paired {
        unguarded: median(&mut unguarded),
        seconds: median(&mut guarded),
        ratio: median(&mut ratios),
        ratio_fastest: unguarded[0] / guarded[0],
        iterations,
    })
}

fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// The CPU time this thread has run, from Linux's /proc/thread-self/schedstat (nanoseconds on
/// the CPU first, brought up to date at each scheduler tick and switch); `None` where it is not
/// available.
fn thread_cpu_seconds() -> Option<f64> {
    let text = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    let ns: f64 = text.split_whitespace().next()?.parse().ok()?;
    Some(ns / 1e9)
}
