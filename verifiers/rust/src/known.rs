//! The expectations file: vectors an implementation is known to fail, each with a reason.
//!
//! ```toml
//! [[known-failure]]
//! id = "fx5-date-compare/LDDT</nonexistent/2024-2-30/s1/vs-previous"
//! reason = "our calendar check rejects 2008/02/31 (tracked as #12)"
//! ```
//!
//! The same file the Python runner reads. A listed vector that fails is `xfail` and does not fail
//! the run; a listed vector that passes is `stale` and fails it, and so does a listed id the suite
//! does not have: the list can only shrink. Ids are exact, never patterns.

use std::collections::BTreeMap;
use std::path::Path;

use crate::error::{Error, Result};
use crate::files::check_regular;
use crate::verdict::{Status, Verdict};

const SECTION: &str = "known-failure";

/// One entry.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct KnownFailure {
    /// The vector id.
    pub id: String,
    /// Why it fails.
    pub reason: String,
    /// The line of its `[[known-failure]]` header.
    pub line: usize,
}

/// A loaded expectations file.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct KnownFailures {
    path: String,
    entries: BTreeMap<String, KnownFailure>,
    /// The ids in the file's order (stale ids are reported in it).
    order: Vec<String>,
}

impl KnownFailures {
    /// Read and check a file.
    pub fn load(path: impl AsRef<Path>) -> Result<KnownFailures> {
        let path = path.as_ref();
        check_regular(path)?;
        let text = std::fs::read_to_string(path)
            .map_err(|e| Error::new(format!("{}: cannot read the expectations file: {e}", path.display())))?;
        KnownFailures::parse(&path.display().to_string(), &text)
    }

    /// Check the text of a file named `path`.
    pub fn parse(path: &str, text: &str) -> Result<KnownFailures> {
        let line_at = |offset: usize| text[..offset.min(text.len())].matches('\n').count() + 1;
        let data: toml::Table = toml::from_str(text).map_err(|e| {
            let line = e.span().map_or(1, |s| line_at(s.start));
            Error::new(format!("{path}:{line}: not valid TOML: {}", e.message()))
        })?;
        if let Some(key) = data.keys().find(|k| *k != SECTION) {
            let line = text
                .lines()
                .position(|l| {
                    l.trim_start().starts_with(key.as_str()) || l.trim_start().starts_with(&format!("[{key}"))
                })
                .map_or(1, |n| n + 1);
            return Err(Error::new(format!(
                "{path}:{line}: unknown key {key:?}; an expectations file holds only [[{SECTION}]] entries"
            )));
        }
        let headers: Vec<usize> = text
            .lines()
            .enumerate()
            .filter(|(_, l)| l.trim_start().starts_with(&format!("[[{SECTION}]]")))
            .map(|(n, _)| n + 1)
            .collect();
        let mut entries = BTreeMap::new();
        let mut order = Vec::new();
        let list = match data.get(SECTION) {
            None => Vec::new(),
            Some(toml::Value::Array(items)) => items.clone(),
            Some(_) => return Err(Error::new(format!("{path}:1: {SECTION} must be written [[{SECTION}]]"))),
        };
        for (n, entry) in list.iter().enumerate() {
            let line = headers.get(n).copied().unwrap_or(0);
            let table =
                entry.as_table().ok_or_else(|| Error::new(format!("{path}:{line}: [[{SECTION}]] must be a table")))?;
            if let Some(extra) = table.keys().find(|k| *k != "id" && *k != "reason") {
                return Err(Error::new(format!(
                    "{path}:{line}: unknown key {extra:?} (an entry has `id` and `reason`)"
                )));
            }
            let id = match table.get("id").and_then(toml::Value::as_str) {
                Some(id) if !id.is_empty() => id.to_owned(),
                _ => return Err(Error::new(format!("{path}:{line}: entry without an `id`"))),
            };
            if id.trim() != id {
                return Err(Error::new(format!(
                    "{path}:{line}: id {id:?} starts or ends with a space; an id holds none (copied with a padded test name?)"
                )));
            }
            let reason = match table.get("reason").and_then(toml::Value::as_str) {
                Some(r) if !r.trim().is_empty() => r.trim().to_owned(),
                _ => return Err(Error::new(format!("{path}:{line}: {id}: every known failure needs a `reason`"))),
            };
            if let Some(first) = entries.get(&id) {
                let first: &KnownFailure = first;
                return Err(Error::new(format!("{path}:{line}: {id} is listed twice (first at line {})", first.line)));
            }
            order.push(id.clone());
            entries.insert(id.clone(), KnownFailure { id, reason, line });
        }
        Ok(KnownFailures { path: path.to_owned(), entries, order })
    }

    /// The file's path.
    pub fn path(&self) -> &str {
        &self.path
    }

    /// The entry for a vector id.
    pub fn get(&self, id: &str) -> Option<&KnownFailure> {
        self.entries.get(id)
    }

    /// Every entry, by id.
    pub fn entries(&self) -> impl Iterator<Item = &KnownFailure> {
        self.entries.values()
    }

    /// Listed ids for which `exists` says the suite has no vector, in the file's order.
    pub fn unknown_ids<'a>(
        &'a self,
        exists: impl Fn(&str) -> bool + 'a,
    ) -> impl Iterator<Item = &'a KnownFailure> + 'a {
        self.order.iter().filter_map(|id| self.entries.get(id)).filter(move |e| !exists(&e.id))
    }

    /// A listed failure becomes `xfail`, a listed pass `stale`.
    pub fn apply(&self, id: &str, verdict: Verdict) -> Verdict {
        let Some(entry) = self.entries.get(id) else { return verdict };
        let at = format!("{}:{}", self.path, entry.line);
        match verdict.status {
            // The differing fields stay: the block shows them (--verbose), and the roll-up judges
            // the known failure under the other readings.
            Status::Fail | Status::Error => {
                let mut message = format!("known failure ({at}): {}", entry.reason);
                if !verdict.message.is_empty() {
                    message.push_str(&format!("; {}", verdict.message));
                }
                Verdict { status: Status::XFail, problems: verdict.problems, message }
            }
            Status::Pass => Verdict {
                status: Status::Stale,
                problems: Vec::new(),
                message: format!(
                    "listed as a known failure ({at}: {}) but it passes; remove it from the expectations file",
                    entry.reason
                ),
            },
            _ => verdict,
        }
    }

    /// The message for a listed id the suite does not have.
    pub fn unknown_message(&self, entry: &KnownFailure) -> String {
        self.stale_message(entry, None)
    }

    /// The message for a listed id the suite does not have, naming the vector it was merged into
    /// when the vector files' `merged` map names one (TEXT.md, "Known-failure messages").
    pub fn stale_message(&self, entry: &KnownFailure, merged_into: Option<&str>) -> String {
        let at = format!("{}:{}", self.path, entry.line);
        match merged_into {
            Some(new) => format!(
                "listed as a known failure ({at}) but the suite has no such vector: it was merged into {new}; list that id instead"
            ),
            None => format!(
                "listed as a known failure ({at}) but the suite has no such vector; remove it from the expectations file"
            ),
        }
    }
}

/// Write `ids` (the failing vectors of a run) as a new known-failures file with one `reason`
/// each, for adopting the suite; the file is replaced whole or not at all. Returns how many.
pub fn write_expectations<'a>(path: &Path, ids: impl IntoIterator<Item = &'a str>, reason: &str) -> Result<usize> {
    let mut ids: Vec<&str> = ids.into_iter().collect();
    ids.sort_unstable();
    ids.dedup();
    let mut text = String::from("# Known failures: each passing entry fails the run as stale, so fix and delete.\n\n");
    for id in &ids {
        text.push_str(&format!("[[{SECTION}]]\nid = {}\nreason = {}\n\n", toml_str(id), toml_str(reason)));
    }
    text.pop();
    // A named pipe or a device where the file goes is refused, not written through (a write could
    // wait for ever); a rename would replace it, which is not what was asked either.
    check_regular(path)?;
    let name = path.file_name().map_or_else(|| "known-failures".into(), |n| n.to_string_lossy().into_owned());
    let partial = path.with_file_name(format!(".{name}.{}.partial", std::process::id()));
    let written = std::fs::write(&partial, text).and_then(|()| std::fs::rename(&partial, path));
    if let Err(e) = written {
        let _ = std::fs::remove_file(&partial);
        return Err(Error::new(format!("{}: cannot write the known failures: {e}", path.display())));
    }
    Ok(ids.len())
}

/// A TOML basic string.
fn toml_str(s: &str) -> String {
    format!("\"{}\"", s.replace('\\', "\\\\").replace('"', "\\\""))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn entries_and_their_lines() {
        let k = KnownFailures::parse(
            "k.toml",
            "# x\n[[known-failure]]\nid = \"a\"\nreason = \"r\"\n\n[[known-failure]]\nid = \"b\"\nreason = \"s\"\n",
        )
        .unwrap();
        assert_eq!(k.get("b").unwrap().line, 6);
        assert_eq!(k.get("a").unwrap().reason, "r");
    }

    #[test]
    fn bad_files_name_the_line() {
        let e = KnownFailures::parse("k.toml", "[[known-failure]]\nid = \"a\"\n").unwrap_err();
        assert_eq!(e.message(), "k.toml:1: a: every known failure needs a `reason`");
        let e = KnownFailures::parse(
            "k.toml",
            "[[known-failure]]\nid = \"a\"\nreason = \"r\"\n[[known-failure]]\nid = \"a\"\nreason = \"r\"\n",
        )
        .unwrap_err();
        assert!(e.message().starts_with("k.toml:4: a is listed twice"), "{e}");
        let e = KnownFailures::parse("k.toml", "x = 1\n").unwrap_err();
        assert!(e.message().starts_with("k.toml:1: unknown key \"x\""), "{e}");
        let e = KnownFailures::parse("k.toml", "[[known-failure]\n").unwrap_err();
        assert!(e.message().starts_with("k.toml:1: not valid TOML"), "{e}");
    }
}
