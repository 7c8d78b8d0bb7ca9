//! Serving an [`Implementation`] over the stdio protocol (PROTOCOL.md), so that
//! `plcvec verify --adapter CMD` drives it as one long-lived process. Any implementation gets an
//! adapter binary in a few lines; the repository's reference adapter (`plcvec-reference-adapter`,
//! in the `plcvec-reference` crate) is one.
//!
//! Malformed input never crashes the loop: a line that is not a protocol message is answered
//! with `fatal` (the runner stops with exit 2), a vector that cannot be read with an `error`
//! result for its id, and a panic of the implementation with an `error` result.

use std::io::{BufRead, Write};
use std::panic::{catch_unwind, AssertUnwindSafe};

use serde_json::{json, Map, Value as Json};

use crate::compare::Steps;
use crate::implementation::{Implementation, Refusal};
use crate::vector::Vector;

/// The protocol version spoken.
pub const PROTOCOL_VERSION: u64 = 1;

/// Who the adapter says it is in its hello.
#[derive(Clone, Debug)]
pub struct AdapterInfo {
    /// The adapter's name.
    pub name: String,
    /// The adapter's version.
    pub version: String,
}

/// Answer the runner on `input`/`output` until `bye` or the end of input. Returns the exit
/// status (0, or 1 after a `fatal`). Errors writing to `output` end the loop.
pub fn serve<I: Implementation + ?Sized>(
    implementation: &mut I,
    info: &AdapterInfo,
    input: impl BufRead,
    mut output: impl Write,
) -> std::io::Result<i32> {
    for line in input.lines() {
        let line = line?;
        if line.trim().is_empty() {
            continue;
        }
        let message: Json = match serde_json::from_str(&line) {
            Ok(m) => m,
            Err(e) => return fatal(&mut output, &format!("a line that is not JSON ({e}): {}", preview(&line))),
        };
        match message.get("type").and_then(Json::as_str) {
            Some("hello") => {
                if message.get("protocol").and_then(Json::as_u64) != Some(PROTOCOL_VERSION) {
                    return fatal(
                        &mut output,
                        &format!(
                            "this adapter speaks protocol {PROTOCOL_VERSION}, not {}",
                            message.get("protocol").unwrap_or(&Json::Null)
                        ),
                    );
                }
                let answer = hello(implementation, info, &message);
                writeln!(output, "{answer}")?;
                output.flush()?;
            }
            Some("run") => {
                let Some(vectors) = message.get("vectors").and_then(Json::as_array) else {
                    return fatal(&mut output, "a run message without a `vectors` list");
                };
                for request in vectors {
                    writeln!(output, "{}", result(implementation, request))?;
                }
                output.flush()?;
            }
            Some("bye") => return Ok(0),
            other => {
                return fatal(
                    &mut output,
                    &format!("unknown message type {}", other.map_or("(none)".to_owned(), |t| format!("{t:?}"))),
                );
            }
        }
    }
    Ok(0)
}

fn preview(line: &str) -> String {
    let cut: String = line.chars().take(120).collect();
    if cut.len() < line.len() {
        format!("{cut}...")
    } else {
        cut
    }
}

fn fatal(output: &mut impl Write, message: &str) -> std::io::Result<i32> {
    writeln!(output, "{}", json!({ "type": "fatal", "message": message }))?;
    output.flush()?;
    Ok(1)
}

fn hello<I: Implementation + ?Sized>(implementation: &I, info: &AdapterInfo, request: &Json) -> Json {
    let declared = implementation.interpretations();
    let mut instructions = Vec::new();
    let mut interpretations = Map::new();
    if let Some(families) = request.get("families").and_then(Json::as_object) {
        for family in families.values() {
            for i in family.get("instructions").and_then(Json::as_array).into_iter().flatten().filter_map(Json::as_str)
            {
                if implementation.supports(i) && !instructions.contains(&i) {
                    instructions.push(i);
                }
            }
            for (id, interp) in family.get("interpretations").and_then(Json::as_object).into_iter().flatten() {
                let alternative = declared.declared(id).or_else(|| interp.get("default").and_then(Json::as_str));
                if let Some(a) = alternative {
                    interpretations.insert(id.clone(), a.into());
                }
            }
        }
    }
    instructions.sort_unstable();
    let mut hello = json!({
        "type": "hello", "protocol": PROTOCOL_VERSION,
        "adapter": { "name": info.name, "version": info.version },
        "instructions": instructions, "interpretations": interpretations,
    });
    let cpu_writes = implementation.cpu_writes();
    if !cpu_writes.is_empty() {
        hello["cpu_writes"] = json!(cpu_writes);
    }
    hello
}

fn result<I: Implementation + ?Sized>(implementation: &mut I, request: &Json) -> Json {
    let id = request.get("id").and_then(Json::as_str).unwrap_or("").to_owned();
    let vector = match Vector::from_request(request) {
        Ok(v) => v,
        Err(e) => return json!({ "type": "result", "id": id, "error": e.to_string() }),
    };
    let ran = catch_unwind(AssertUnwindSafe(|| {
        let mut steps = Steps::record(&vector);
        let ran = implementation.run(&vector, &mut steps);
        (ran, steps.into_recorded())
    }));
    match ran {
        Ok((Ok(()), steps)) => {
            // A JSON object keeps one value per name: a device reported twice would reach the
            // runner as whichever value came last. Say so instead.
            for (n, s) in steps.iter().enumerate() {
                for (i, (name, v)) in s.devices.iter().enumerate() {
                    if let Some((_, w)) = s.devices[..i].iter().find(|(other, _)| other == name) {
                        let why = format!("step {n} reports {name} twice ({w} and {v})");
                        return json!({ "type": "result", "id": id, "error": why });
                    }
                }
            }
            let steps: Vec<Json> = steps
                .into_iter()
                .map(|s| {
                    let devices: Map<String, Json> = s.devices.into_iter().map(|(n, v)| (n, v.to_json())).collect();
                    let mut step = Map::new();
                    if let Some(r) = s.result {
                        step.insert("result".into(), r.into());
                    }
                    step.insert("devices".into(), devices.into());
                    Json::Object(step)
                })
                .collect();
            json!({ "type": "result", "id": id, "steps": steps })
        }
        Ok((Err(Refusal::Skip(why)), _)) => json!({ "type": "result", "id": id, "skip": why }),
        Ok((Err(Refusal::Error(why)), _)) => json!({ "type": "result", "id": id, "error": why }),
        Err(panic) => {
            let what =
                panic.downcast_ref::<&str>().map(|s| s.to_string()).or_else(|| panic.downcast_ref::<String>().cloned());
            json!({ "type": "result", "id": id, "error": format!("the implementation panicked: {}", what.unwrap_or_default()) })
        }
    }
}
