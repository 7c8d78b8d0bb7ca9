//! A test process that ends half way (an implementation calling `exit(0)`) fails the run, named
//! by the vector it ended on: the child that runs the vectors records nothing per vector, so the
//! harness runs them once more, each recorded, its output set aside, and names the vector that
//! run ends on. When that second run does not end early, the run fails all the same and says the
//! vector cannot be named; the second run writes no expectations file. A process stopped from
//! outside (SIGTERM) is not run again.
//!
//! A test binary of its own (`harness = false`): its `main` is the supervised run when
//! `PLCVEC_TEST_EARLY_END` is set (the harness starts the binary again for its children), and
//! otherwise starts that run and checks what it says.

use std::path::Path;
use std::process::{Command, ExitCode};

use plcvec::harness::{Arguments, Harness};
use plcvec::{Execute, Memory, OnMemory, Refusal, Selection, Step, Suite, Vector};
use plcvec_reference::Reference;

/// Set for the supervised run: `always`, `once:<file>` (end the process only when the file does
/// not exist yet, creating it: the first run ends, the second does not), or `term:<file>` (add a
/// line to the file, and stop the process with SIGTERM as from outside).
const CHILD: &str = "PLCVEC_TEST_EARLY_END";
/// Set for the supervised run: the log file libtest-mimic writes (`--logfile`).
const LOG: &str = "PLCVEC_TEST_EARLY_END_LOG";
const ON: &str = "fx5-time-add/TADD/manual-example/program";

struct EndsEarly {
    reference: Reference,
    mode: String,
}

impl Execute for EndsEarly {
    fn supports(&self, instruction: &str) -> bool {
        self.reference.supports(instruction)
    }

    fn begin(&mut self, vector: &Vector) -> Result<(), Refusal> {
        self.reference.begin(vector)
    }

    fn execute(&mut self, vector: &Vector, step: &Step, memory: &mut Memory<'_>) -> Result<Option<bool>, Refusal> {
        if vector.id() == ON {
            if let Some(marker) = self.mode.strip_prefix("once:") {
                if std::fs::File::create_new(marker).is_ok() {
                    std::process::exit(0);
                }
            } else if let Some(count) = self.mode.strip_prefix("term:") {
                use std::io::Write;
                let mut file = std::fs::OpenOptions::new().create(true).append(true).open(count).unwrap();
                file.write_all(b"reached\n").unwrap();
                Command::new("kill").args(["-TERM", &std::process::id().to_string()]).status().unwrap();
                loop {
                    std::thread::sleep(std::time::Duration::from_secs(1));
                }
            } else {
                std::process::exit(0);
            }
        }
        self.reference.execute(vector, step, memory)
    }
}

fn tadd() -> Selection {
    Selection::all().family("fx5-time-add")
}

/// The supervised run (and, started by it, its children): two test threads.
fn supervised_run(mode: &str) -> ExitCode {
    let mode = mode.to_owned();
    Harness::new(move || OnMemory(EndsEarly { reference: Reference::new(), mode: mode.clone() }))
        .suite(Suite::embedded().unwrap())
        .select(tadd())
        .arguments(Arguments { test_threads: Some(2), logfile: std::env::var(LOG).ok(), ..Arguments::default() })
        .run()
}

/// Run the supervised run in `mode` with `PLCVEC_WRITE_EXPECTATIONS=expectations` (and
/// `--logfile log`, if given): its exit status and stdout.
fn supervise(mode: &str, expectations: &Path, log: Option<&Path>) -> (Option<i32>, String) {
    let mut run = Command::new(std::env::current_exe().unwrap());
    match log {
        Some(log) => run.env(LOG, log),
        None => run.env_remove(LOG),
    };
    let out = run
        .env(CHILD, mode)
        .env("PLCVEC_WRITE_EXPECTATIONS", expectations)
        .env_remove("PLCVEC_KNOWN_FAILURES")
        .output()
        .unwrap();
    (out.status.code(), String::from_utf8_lossy(&out.stdout).into_owned())
}

fn main() -> ExitCode {
    if let Ok(mode) = std::env::var(CHILD) {
        return supervised_run(&mode);
    }
    let scratch = std::env::temp_dir().join(format!("plcvec-rust-early-end-{}", std::process::id()));
    std::fs::create_dir_all(&scratch).unwrap();
    let expectations = scratch.join("known.toml");
    let log = scratch.join("log.txt");

    // Ends on the vector every time: the second run ends on it too, and names it.
    let (code, stdout) = supervise("always", &expectations, None);
    assert_eq!(code, Some(101), "{stdout}");
    let named = format!(
        "\n\nFAIL {ON}\n    the test process ended (exit status 0) before the run came to its end; run again with \
         each vector recorded, it ended the same way while the implementation ran this vector; a run that ends early \
         is never a pass\n"
    );
    assert!(stdout.contains(&named), "{stdout}");
    assert!(!stdout.contains("cannot be named"), "{stdout}");
    // The second run's output is set aside: the first run's header alone.
    let n = tadd().apply(Suite::embedded().unwrap().vectors()).len();
    assert_eq!(stdout.matches(&format!("\nrunning {n} tests\n")).count(), 1, "{stdout}");

    // Ends only the first time: the run fails all the same, the vector not named, and the second
    // run (which came to its end) wrote no expectations file, nor its log over the first run's.
    let marker = scratch.join("ended-once");
    let (code, stdout) = supervise(&format!("once:{}", marker.display()), &expectations, Some(&log));
    assert_eq!(code, Some(101), "{stdout}");
    assert!(marker.exists(), "the implementation never ended the process\n{stdout}");
    let unnamed = "\n\nFAIL the run\n    the test process ended (exit status 0) before the run came to its end; run \
                   again with each vector recorded, it did not end early, so the vector it ended on cannot be named; \
                   a run that ends early is never a pass\n";
    assert!(stdout.contains(unnamed), "{stdout}");
    assert!(!stdout.contains(&format!("FAIL {ON}")), "{stdout}");
    assert!(!expectations.exists(), "the second run wrote the expectations file\n{stdout}");
    let logged = std::fs::read_to_string(&log).unwrap_or_default();
    assert!(!logged.contains("test result"), "the second run wrote the log file:\n{logged}");

    // Stopped from outside: the run fails, and the vectors are not run again.
    if cfg!(unix) {
        let reached = scratch.join("reached");
        let (code, stdout) = supervise(&format!("term:{}", reached.display()), &expectations, None);
        assert_eq!(code, Some(101), "{stdout}");
        let stopped = "\n\nFAIL the run\n    the test process ended (killed by signal 15 (SIGTERM)) before the run \
                       came to its end, stopped from outside";
        assert!(stdout.contains(stopped), "{stdout}");
        let times = std::fs::read_to_string(&reached).unwrap_or_default().lines().count();
        assert_eq!(times, 1, "the implementation reached {ON} {times} times\n{stdout}");
    }
    std::fs::remove_dir_all(&scratch).unwrap();
    println!("an early end is named by the vector it ended on: ok");
    ExitCode::SUCCESS
}
