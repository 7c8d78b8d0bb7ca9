//! The supervisor: the test binary started once more as the child that runs the vectors, and the
//! judgement of how that child ended (an implementation that ends the process fails the run,
//! named by a second child that records each vector).

use std::fs::File;
use std::io::Write;
use std::process::ExitCode;

use super::record::Record;
use super::{EXIT_FAILED, EXIT_USAGE};

/// Set by the supervising process for the child that runs the vectors: the file in which the
/// child notes that the run came to its end (internal; not for users).
pub(super) const PROGRESS_ENV: &str = "PLCVEC_HARNESS_PROGRESS";
/// Set by the supervising process, with `PROGRESS_ENV`, for the child that runs the vectors once
/// more to find the one a run ended on: it records each vector as it starts and ends, and writes
/// no expectations file (internal; not for users).
pub(super) const EACH_VECTOR_ENV: &str = "PLCVEC_HARNESS_EACH_VECTOR";

/// The file a supervised child tells its parent through, and whether it records each vector.
pub(super) struct Progress {
    pub(super) path: std::path::PathBuf,
    pub(super) file: File,
    pub(super) each_vector: bool,
}

/// Run this test binary once more as a child that runs the vectors, and judge how it ended:
/// a child that exits (with any status, 0 included) or dies before the run came to its end
/// fails the run, naming the vector(s) it was running.
///
/// The child records nothing per vector (a system call per vector costs more than judging it,
/// and nothing else a safe program can write outlives a process that dies): when it ends early,
/// the vectors are run once more by a child that records each as it starts and ends, its output
/// set aside, and the vector that child ends on is named. An implementation that ends the process
/// on a vector does so again; when the second run does not end early, the run still fails, and
/// says that the vector cannot be named. A child stopped from outside (`stopped_from_outside`) is
/// not run again.
pub(super) fn supervise() -> ExitCode {
    let (status, record) = match run_child(false) {
        Ok(ended) => ended,
        Err(code) => return code,
    };
    if Record::read(&record).2 {
        return ExitCode::from(status.code().map_or(EXIT_FAILED, |c| u8::try_from(c).unwrap_or(EXIT_FAILED)));
    }
    let how = describe_status(&status);
    if stopped_from_outside(&status) {
        let _ = std::io::stdout().flush();
        println!(
            "\n\nFAIL the run\n    the test process ended ({how}) before the run came to its end, stopped from outside \
             (a signal that asks a process to stop, or the kernel's out-of-memory killer), so the vectors are not run \
             again to name the one it was running; a run that ends early is never a pass"
        );
        eprintln!("plcvec: the test process ended early ({how})");
        return ExitCode::from(EXIT_FAILED);
    }
    eprintln!("plcvec: the test process ended early ({how}); running the vectors again, each recorded, to find the one it ended on");
    let again = run_child(true);
    let _ = std::io::stdout().flush();
    let ended_again = match &again {
        Ok((status, record)) => {
            let (running, finished, done) = Record::read(record);
            let how_again = describe_status(status);
            let same = if how_again == how { "the same way".to_owned() } else { format!("({how_again})") };
            (!done).then_some((running, finished, same))
        }
        Err(_) => None,
    };
    match ended_again {
        Some((running, finished, same)) if running.is_empty() => println!(
            "\n\nFAIL the run\n    the test process ended ({how}) before the run came to its end; run again with each \
             vector recorded, it ended {same} after {finished} vectors and while none was being judged; a run that \
             ends early is never a pass"
        ),
        Some((running, _, same)) => {
            for id in &running {
                println!(
                    "\n\nFAIL {id}\n    the test process ended ({how}) before the run came to its end; run again with \
                     each vector recorded, it ended {same} while the implementation ran this vector; a run that ends \
                     early is never a pass"
                );
            }
        }
        None => println!(
            "\n\nFAIL the run\n    the test process ended ({how}) before the run came to its end; run again with each \
             vector recorded, it did not end early, so the vector it ended on cannot be named; a run that ends early \
             is never a pass"
        ),
    }
    eprintln!("plcvec: the test process ended early ({how})");
    ExitCode::from(EXIT_FAILED)
}

/// Run this test binary as the child that runs the vectors (with `each_vector`, recording each,
/// its output set aside): how it ended, and its record.
fn run_child(each_vector: bool) -> std::result::Result<(std::process::ExitStatus, Vec<u8>), ExitCode> {
    let progress = std::env::temp_dir().join(format!(
        "plcvec-progress-{}-{}",
        std::process::id(),
        std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_nanos())
    ));
    if let Err(e) = File::create(&progress) {
        eprintln!("plcvec: cannot create {}: {e}", progress.display());
        return Err(ExitCode::from(EXIT_USAGE));
    }
    let status = std::env::current_exe().and_then(|exe| {
        let mut child = std::process::Command::new(exe);
        child.args(std::env::args_os().skip(1)).env(PROGRESS_ENV, &progress);
        if each_vector {
            child.env(EACH_VECTOR_ENV, "1").stdout(std::process::Stdio::null()).stderr(std::process::Stdio::null());
        } else {
            child.env_remove(EACH_VECTOR_ENV);
        }
        child.status()
    });
    let record = std::fs::read(&progress).unwrap_or_default();
    let _ = std::fs::remove_file(&progress);
    match status {
        Ok(s) => Ok((s, record)),
        Err(e) => {
            eprintln!("plcvec: cannot start the test binary again to run the vectors: {e}");
            Err(ExitCode::from(EXIT_USAGE))
        }
    }
}

/// Whether the child was stopped by a signal that comes from outside, not from the implementation
/// (which ends the process by exiting, aborting or crashing): SIGHUP, SIGINT, SIGTERM, or SIGKILL
/// (a person's `kill -9`, or the kernel's out-of-memory killer). Running the vectors again then
/// would only be stopped again, or fill the memory again.
fn stopped_from_outside(status: &std::process::ExitStatus) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        matches!(status.signal(), Some(1 | 2 | 9 | 15))
    }
    #[cfg(not(unix))]
    {
        let _ = status;
        false
    }
}

fn describe_status(status: &std::process::ExitStatus) -> String {
    if let Some(code) = status.code() {
        return format!("exit status {code}");
    }
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        if let Some(signal) = status.signal() {
            let name = match signal {
                1 => " (SIGHUP)",
                2 => " (SIGINT)",
                6 => " (SIGABRT)",
                9 => " (SIGKILL)",
                11 => " (SIGSEGV)",
                15 => " (SIGTERM)",
                _ => "",
            };
            return format!("killed by signal {signal}{name}");
        }
    }
    status.to_string()
}
