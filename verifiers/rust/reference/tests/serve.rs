//! The stdio protocol loop (PROTOCOL.md): the handshake, a batch, and malformed input answered
//! with `fatal` or an `error` result instead of a crash.

use plcvec::serve::{serve, AdapterInfo};
use plcvec::{OnMemory, Suite};
use plcvec_reference::Reference;
use serde_json::{json, Value as Json};

fn talk(input: &str) -> (i32, Vec<Json>) {
    let mut out = Vec::new();
    let info = AdapterInfo { name: "test".into(), version: "1".into() };
    let status = serve(&mut OnMemory(Reference::new()), &info, input.as_bytes(), &mut out).unwrap();
    let lines = String::from_utf8(out).unwrap().lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    (status, lines)
}

#[test]
fn a_handshake_and_a_batch() {
    let suite = Suite::embedded().unwrap();
    let request = suite.get("fx5-time-add/TADD/manual-example/program").unwrap().to_request();
    let hello = json!({"type": "hello", "protocol": 1, "families": {"fx5-time-add": {
        "instructions": ["TADD", "TADDP", "TADDX"],
        "interpretations": {"TADD-ON-ERROR": {"default": "not-executed", "alternatives": ["not-executed", "computed"]}}}}});
    let run = json!({"type": "run", "batch": 0, "vectors": [request, {"id": "broken", "family": "fx5-time-add"}]});
    let (status, lines) = talk(&format!("{hello}\n{run}\n{{\"type\": \"bye\"}}\n"));
    assert_eq!(status, 0);
    assert_eq!(lines[0]["type"], "hello");
    assert_eq!(lines[0]["instructions"], json!(["TADD", "TADDP"]));
    assert_eq!(lines[0]["interpretations"], json!({"TADD-ON-ERROR": "not-executed"}));
    // The manual's example: 10:30:10 + 3:10:05 = 13:40:15 in D30..D32.
    let devices = &lines[1]["steps"][0]["devices"];
    assert_eq!((&devices["D30"], &devices["D31"], &devices["D32"]), (&json!(13), &json!(40), &json!(15)));
    assert_eq!(devices["SM700"], json!(false));
    assert!(lines[1]["steps"][0].get("result").is_none());
    assert_eq!(lines[2]["id"], "broken");
    assert!(lines[2]["error"].as_str().unwrap().starts_with("not a vector request"), "{}", lines[2]);
}

#[test]
fn malformed_input_is_answered_with_fatal() {
    let (status, lines) = talk("{\"type\": \"hello\", \"protocol\": 2}\n");
    assert_eq!(status, 1);
    assert_eq!(lines, [json!({"type": "fatal", "message": "this adapter speaks protocol 1, not 2"})]);
    let (status, lines) = talk("not json\n");
    assert_eq!(status, 1);
    assert!(lines[0]["message"].as_str().unwrap().starts_with("a line that is not JSON"));
    let (status, lines) = talk("{\"type\": \"dance\"}\n");
    assert_eq!(status, 1);
    assert_eq!(lines[0]["message"], "unknown message type \"dance\"");
}
