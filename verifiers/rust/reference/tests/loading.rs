//! Loading, selection, known failures, the declared alternatives and the protocol loop: what a
//! user gets when something is wrong (a clear error naming the file and line or the vector id),
//! and the rules the crate shares with the Python runner.

use std::path::{Path, PathBuf};

use plcvec::names::{Family, TaddOnError, TOTAL};
use plcvec::{Choices, KnownFailures, OnMemory, Selection, Status, Suite};
use plcvec_reference::Reference;

const MANUAL_EXAMPLE: &str = "fx5-time-add/TADD/manual-example/program";

/// The `plcvec` crate's folder (this crate's parent), which holds the exported vectors.
fn crate_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// A scratch folder, removed when dropped.
struct Scratch(PathBuf);

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

impl AsRef<Path> for Scratch {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

/// A scratch folder holding a copy of the exported vectors, edited by `edit(file name, text)`.
fn edited_copy(name: &str, edit: impl Fn(&str, String) -> String) -> Scratch {
    let dir = std::env::temp_dir().join(format!("plcvec-rust-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for entry in std::fs::read_dir(crate_dir().join("vectors")).unwrap() {
        let path = entry.unwrap().path();
        let file = path.file_name().unwrap().to_str().unwrap().to_owned();
        let text = std::fs::read_to_string(&path).unwrap();
        std::fs::write(dir.join(&file), edit(&file, text)).unwrap();
    }
    Scratch(dir)
}

/// `edited_copy` with the index's sha256 of each file brought up to date, so that the edit is
/// the only damage.
fn resealed_copy(name: &str, edit: impl Fn(&str, String) -> String) -> Scratch {
    use sha2::{Digest, Sha256};
    let dir = edited_copy(name, edit);
    let index_path = dir.0.join("index.json");
    let mut index: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&index_path).unwrap()).unwrap();
    for (_, entry) in index["families"].as_object_mut().unwrap() {
        let bytes = std::fs::read(dir.0.join(entry["file"].as_str().unwrap())).unwrap();
        let hex: String = Sha256::digest(&bytes).iter().map(|b| format!("{b:02x}")).collect();
        entry["sha256"] = hex.into();
    }
    std::fs::write(&index_path, serde_json::to_string_pretty(&index).unwrap()).unwrap();
    dir
}

fn edit_tadd(name: &str, from: &'static str, to: &'static str) -> Scratch {
    resealed_copy(name, move |file, text| if file == "fx5-time-add.jsonl" { text.replacen(from, to, 1) } else { text })
}

#[test]
fn a_file_that_differs_from_its_index_is_refused() {
    // Still valid JSON and a valid vector: only the recorded sha256 tells.
    let dir = edited_copy("sha", |file, text| {
        if file == "fx5-time-add.jsonl" {
            text.replacen("manual example program", "manual example programme", 1)
        } else {
            text
        }
    });
    let err = Suite::load(&dir).unwrap_err().to_string();
    assert!(err.contains("fx5-time-add.jsonl: sha256 ") && err.contains("index.json records"), "{err}");
}

#[test]
fn unknown_keys_are_refused() {
    let err = Suite::load(edit_tadd("key", "\"final\":", "\"surprise\":1,\"final\":")).unwrap_err().to_string();
    assert!(
        err.contains("fx5-time-add.jsonl:2: vector fx5-time-add/") && err.contains("unknown field `surprise`"),
        "{err}"
    );
    let err = Suite::load(edit_tadd("header", "{\"count\":", "{\"surprise\":1,\"count\":")).unwrap_err().to_string();
    assert!(err.contains("fx5-time-add.jsonl:1:") && err.contains("unknown field `surprise`"), "{err}");
}

#[test]
fn a_device_keeps_one_type() {
    // SM700 is a bit in `final`; a 2 in `initial` makes it a word there.
    let err = Suite::load(edit_tadd("type", "\"SM700\":false", "\"SM700\":2")).unwrap_err().to_string();
    assert!(err.contains("SM700") && err.contains("a device keeps one type"), "{err}");
}

#[test]
fn a_final_the_steps_do_not_add_up_to_is_refused() {
    // The first vector's first `final` is its alternative's under TADD-ERROR-ORDER=field-range-first:
    // D100 ends at 24 there. Edited to 25, or without D100, it is refused.
    let choices: Choices = [("TADD-ERROR-ORDER", "field-range-first")].into_iter().collect();
    for (name, to) in
        [("final-value", "\"final\":{\"devices\":{\"D100\":25,"), ("final-missing", "\"final\":{\"devices\":{")]
    {
        let suite = Suite::load(edit_tadd(name, "\"final\":{\"devices\":{\"D100\":24,", to)).unwrap();
        let selection = Selection::all().family("fx5-time-add");
        let mut reference = OnMemory(Reference::with_choices(choices.clone()));
        match plcvec::run(&suite, &mut reference, &selection, None) {
            Ok(report) => panic!("{name}: the run was not refused:\n{}", report.summary()),
            Err(err) => assert!(err.to_string().contains("do not add up to `final`"), "{name}: {err}"),
        }
    }
}

#[test]
fn the_embedded_copy_holds_every_family_and_vector() {
    let suite = Suite::embedded().unwrap();
    assert_eq!(suite.vectors().len(), TOTAL);
    for f in Family::ALL {
        assert!(suite.family(f.as_str()).is_some(), "{f} missing");
        for i in f.instructions() {
            assert!(suite.family(f.as_str()).unwrap().instructions.iter().any(|x| x == i.as_str()));
        }
    }
    let v = suite.get(MANUAL_EXAMPLE).unwrap();
    assert_eq!(v.instruction(), "TADD");
    assert_eq!(v.operand("d").and_then(|o| o.device()).map(|a| a.name()), Some("D30"));
}

#[test]
fn the_repository_vectors_load_the_same() {
    // PLCVEC_VECTORS may name the repository's vectors/ folder (manifest.json + *.json). The
    // crate as published has no repository around it: then there is nothing to compare with.
    let repo = crate_dir().join("../../vectors");
    if !crate_dir().join("../../spec").is_dir() {
        eprintln!("not in the plcvec repository: the repository's vectors/ are not there to compare");
        return;
    }
    let from_repo = Suite::load(&repo).unwrap();
    let embedded = Suite::embedded().unwrap();
    assert_eq!(from_repo.vectors(), embedded.vectors());
    assert_eq!(from_repo.spec_sha256(), embedded.spec_sha256());
    let exported = Suite::load(crate_dir().join("vectors")).unwrap();
    assert_eq!(exported.vectors(), embedded.vectors());
}

#[test]
fn a_truncated_copy_is_refused() {
    let dir = edited_copy("truncated", |file, text| {
        if file == "fx5-time-add.jsonl" {
            let mut lines: Vec<&str> = text.lines().collect();
            lines.pop();
            lines.join("\n") + "\n"
        } else {
            text
        }
    });
    let err = Suite::load(&dir).unwrap_err().to_string();
    assert!(err.contains("fx5-time-add.jsonl") && err.contains("vectors, but the index says"), "{err}");
}

#[test]
fn a_damaged_vector_is_named_by_file_line_and_id() {
    let dir = edited_copy("damaged", |file, text| {
        if file == "fx5-time-add.jsonl" {
            text.replacen("\"final\"", "\"finale\"", 1)
        } else {
            text
        }
    });
    let err = Suite::load(&dir).unwrap_err().to_string();
    // Line 1 is the header: the first vector is on line 2.
    assert!(err.contains("fx5-time-add.jsonl:2: vector fx5-time-add/"), "{err}");
    assert!(err.contains("unknown field `finale`"), "{err}");
}

#[test]
fn a_word_out_of_range_is_refused() {
    let dir = edited_copy("word", |file, text| {
        if file == "fx5-time-add.jsonl" {
            text.replacen("\"D10\":10,", "\"D10\":65536,", 1).replacen("\"D10\": 10,", "\"D10\": 65536,", 1)
        } else {
            text
        }
    });
    let err = Suite::load(&dir).unwrap_err().to_string();
    assert!(err.contains(MANUAL_EXAMPLE) && err.contains("65536 is neither a word"), "{err}");
}

#[test]
fn another_major_schema_version_is_refused() {
    let dir = edited_copy("schema", |file, text| {
        if file == "fc6a-hour-meter.jsonl" {
            text.replacen("\"schema_version\":\"1.", "\"schema_version\":\"2.", 1).replacen(
                "\"schema_version\": \"1.",
                "\"schema_version\": \"2.",
                1,
            )
        } else {
            text
        }
    });
    let err = Suite::load(&dir).unwrap_err().to_string();
    assert!(err.contains("fc6a-hour-meter.jsonl: schema_version 2.") && err.contains("is not 1.x"), "{err}");
}

#[test]
fn a_missing_copy_is_named() {
    let err = Suite::load("/nonexistent/plcvec").unwrap_err().to_string();
    assert_eq!(err, "/nonexistent/plcvec: no such vector folder or file");
}

#[test]
fn shards_follow_the_python_rule() {
    // zlib.crc32(id) % N + 1, as computed by Python's zlib.
    assert_eq!(plcvec::shard_of(MANUAL_EXAMPLE, 4), 3);
    assert_eq!(plcvec::shard_of(MANUAL_EXAMPLE, 7), 3);
    assert_eq!(plcvec::shard_of("cp1e-time-compare/LD =DT/latch/already-on-valid-data", 4), 2);
    assert_eq!(plcvec::shard_of("cp1e-time-compare/LD =DT/latch/already-on-valid-data", 7), 6);
    let suite = Suite::embedded().unwrap();
    let mut seen = 0;
    for k in 1..=4 {
        let shard = Selection::all().shard(k, 4).unwrap().apply(suite.vectors());
        assert!(!shard.is_empty());
        seen += shard.len();
    }
    assert_eq!(seen, suite.vectors().len(), "the shards partition the suite");
}

#[test]
fn selections_filter_and_refuse_what_selects_nothing() {
    let suite = Suite::embedded().unwrap();
    let taddp = Selection::all().instruction("TADDP").apply(suite.vectors());
    assert!(!taddp.is_empty() && taddp.iter().all(|v| v.instruction() == "TADDP"));
    let prefix = "fx5-time-add/TADD/manual-example/";
    let glob = Selection::all().id_glob(&format!("{prefix}*")).unwrap().apply(suite.vectors());
    assert_eq!(glob.len(), suite.vectors().iter().filter(|v| v.id().starts_with(prefix)).count());
    assert!(glob.iter().any(|v| v.id() == MANUAL_EXAMPLE));
    assert_eq!(Selection::all().id_glob(MANUAL_EXAMPLE).unwrap().apply(suite.vectors()).len(), 1);
    let tagged = Selection::all().tag("manual-example").family("cp1e-time-compare").apply(suite.vectors());
    assert!(tagged.iter().all(|v| v.family() == "cp1e-time-compare" && v.tags().iter().any(|t| t == "manual-example")));

    let mut reference = OnMemory(Reference::new());
    let err = plcvec::run(&suite, &mut reference, &Selection::all().family("fx5-time-ad"), None).unwrap_err();
    assert!(err.to_string().contains("family \"fx5-time-ad\""), "{err}");
    let err = plcvec::run(&suite, &mut reference, &Selection::all().id_glob("nothing/*").unwrap(), None).unwrap_err();
    assert!(err.to_string().contains("keeps none of the"), "{err}");
}

#[test]
fn an_unknown_declaration_is_refused() {
    let suite = Suite::embedded().unwrap();
    let mut choices = Choices::new();
    choices.declare("TADD-ON-ERROR", "sometimes");
    let mut reference = OnMemory(Reference::with_choices(choices));
    let err = plcvec::run(&suite, &mut reference, &Selection::all(), None).unwrap_err().to_string();
    assert!(err.contains("TADD-ON-ERROR=sometimes") && err.contains("not-executed, computed"), "{err}");
}

#[test]
fn declared_alternatives_choose_the_expectation() {
    // Judged by the default, an implementation that computes on error fails the vectors that
    // depend on TADD-ON-ERROR; declared, it passes them.
    let suite = Suite::embedded().unwrap();
    let selection = Selection::all().interpretation("TADD-ON-ERROR");
    let computed = Choices::new().with(TaddOnError::Computed);
    let mut honest = OnMemory(Reference::with_choices(computed.clone()));
    assert!(plcvec::run(&suite, &mut honest, &selection, None).unwrap().passed());

    struct Undeclared(OnMemory<Reference>);
    impl plcvec::Implementation for Undeclared {
        fn run(&mut self, v: &plcvec::Vector, steps: &mut plcvec::Steps<'_>) -> Result<(), plcvec::Refusal> {
            self.0.run(v, steps)
        }
    }
    let mut undeclared = Undeclared(OnMemory(Reference::with_choices(computed)));
    let report = plcvec::run(&suite, &mut undeclared, &selection, None).unwrap();
    assert!(!report.passed());
    let summary = report.summary();
    assert!(
        summary.lines().any(|l| l.starts_with("    judged by: ") && l.contains("TADD-ON-ERROR=not-executed")),
        "{summary}"
    );
}

#[test]
fn known_failures_turn_into_xfail_and_stale() {
    let suite = Suite::embedded().unwrap();
    let selection = Selection::all().family("fx5-time-add");
    let known = KnownFailures::parse(
        "known.toml",
        "[[known-failure]]\nid = \"fx5-time-add/TADD/carry/below-wrap/flags-on-before\"\nreason = \"SM8022 not modelled\"\n",
    )
    .unwrap();
    let mut mutant = OnMemory(Reference::mutant(plcvec_reference::Mutant::TaddSm8022NotWritten, Choices::new()));
    let report = plcvec::run(&suite, &mut mutant, &selection, Some(&known)).unwrap();
    assert_eq!(report.verdict("fx5-time-add/TADD/carry/below-wrap/flags-on-before").unwrap().status, Status::XFail);

    let mut reference = OnMemory(Reference::new());
    let report = plcvec::run(&suite, &mut reference, &selection, Some(&known)).unwrap();
    let verdict = report.verdict("fx5-time-add/TADD/carry/below-wrap/flags-on-before").unwrap();
    assert_eq!(verdict.status, Status::Stale);
    assert!(verdict.message.contains("known.toml:1"), "{}", verdict.message);
    assert!(!report.passed());

    let unknown =
        KnownFailures::parse("known.toml", "[[known-failure]]\nid = \"no/such/vector\"\nreason = \"x\"\n").unwrap();
    let report = plcvec::run(&suite, &mut reference, &selection, Some(&unknown)).unwrap();
    assert!(!report.passed());
    assert_eq!(report.count(Status::Stale), 1);
}

#[test]
fn skipping_everything_does_not_pass() {
    struct Nothing;
    impl plcvec::Implementation for Nothing {
        fn run(&mut self, _: &plcvec::Vector, _: &mut plcvec::Steps<'_>) -> Result<(), plcvec::Refusal> {
            Err(plcvec::Refusal::Skip("not implemented".into()))
        }
    }
    let suite = Suite::embedded().unwrap();
    let report = plcvec::run(&suite, &mut Nothing, &Selection::all().family("fx5-time-add"), None).unwrap();
    assert_eq!(report.count(Status::Skip), report.plan.len());
    assert!(!report.passed());
}
