//! How fast the crate judges the golden set with the reference implementation, in process,
//! after loading: `cargo run --release --example bench` (or `verifiers/rust/bench`).
//!
//! Loading (parsing the embedded copy and working out every vector's expectation) is timed
//! apart. A pass judges every vector once; the figure is the median of the passes after a few
//! warm-up passes. The last line is the JSON object `plcvec bench-native` reads.
#![forbid(unsafe_code)]

use std::time::Instant;

use plcvec::reference::Reference;
use plcvec::{Choices, OnMemory, Plan, Status, Suite};

const WARM_UP: usize = 3;
const PASSES: usize = 20;

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
    let mut seconds = Vec::with_capacity(PASSES);
    for pass in 0..WARM_UP + PASSES {
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
    }
    seconds.sort_by(f64::total_cmp);
    let median = seconds[seconds.len() / 2];
    let n = plan.len();
    let rate = n as f64 / median;
    println!("{:50} {:>8} {:>12}", "judging the golden set in process (rust reference)", "vectors", "vectors/s");
    println!("{:50} {:>8} {:>12.0}", format!("load + expectations {load_seconds:.3} s, pass {median:.6} s"), n, rate);
    println!(
        "{{\"lang\": \"rust\", \"vectors\": {n}, \"passes\": {PASSES}, \"load_seconds\": {load_seconds:.4}, \"seconds\": {median:.6}, \"vectors_per_s\": {rate:.0}, \"note\": \"median of {PASSES} passes after {WARM_UP} warm-up\"}}"
    );
    std::process::ExitCode::SUCCESS
}
