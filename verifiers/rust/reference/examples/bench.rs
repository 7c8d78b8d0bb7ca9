//! How fast the crate judges the golden set with the reference implementation, in process,
//! after loading: `cargo run --release --example bench` (or `verifiers/rust/bench`).
//!
//! Loading (parsing the embedded copy and working out every vector's expectation) is timed
//! apart. A pass judges every vector once; the figure is the median of the passes after a few
//! warm-up passes (at least `PASSES`, and as many more as fit in `SECONDS`, so that the thread's
//! CPU time over them is measured to well under 1%). The last line is the JSON object
//! `plcvec bench-native` reads.
#![forbid(unsafe_code)]

use std::time::Instant;

use plcvec::{Choices, OnMemory, Plan, Status, Suite};
use plcvec_reference::Reference;

const WARM_UP: usize = 3;
const PASSES: usize = 20;
/// Passes go on until this much time has gone by (the kernel counts a thread's CPU time in
/// scheduler ticks, up to 10 ms: one pass is far shorter than that).
const SECONDS: f64 = 2.0;
/// A bound on the passes, whatever the clock says.
const MAX_PASSES: usize = 1_000_000;

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
        // Every pass must be a passing run: a fast wrong answer is not a figure.
        if let Some((v, verdict)) = plan.vectors().iter().zip(&verdicts).find(|(_, v)| v.status != Status::Pass) {
            eprintln!("bench: the reference did not pass {}: {:?}", v.id(), verdict);
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
    println!(
        "{{\"lang\": \"rust\", \"vectors\": {n}, \"passes\": {passes}, \"load_seconds\": {load_seconds:.4}, \"seconds\": {wall:.6}, \"vectors_per_s\": {rate:.0}{cpu_key}, \"note\": \"{cpu_note}median of {passes} passes after {WARM_UP} warm-up, {fastest_rate:.0}/s in the fastest pass\"}}"
    );
    std::process::ExitCode::SUCCESS
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
