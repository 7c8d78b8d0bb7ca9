//! Reading the `PLCVEC_*` environment variables (CONTRACT.md, "The environment"): a setting under
//! its name or, until the release its table names, its old name; and one warning line per
//! variable that is an old name or no setting at all, once per run whatever the entry point.
//! The table itself is generated (`generated::settings`), never retyped.

use std::ffi::OsString;
use std::sync::Once;
use std::time::Duration;

use crate::error::{Error, Result};

use crate::generated::settings::{DEPRECATED, NEAREST_DISTANCE, RESERVED, RESERVED_PREFIXES, SETTINGS, TIMEOUT_MAX_S};

const PREFIX: &str = "PLCVEC_";

static WARNED: Once = Once::new();

/// A bound in seconds given as `source=text`: digits with an optional fraction (`10`, `2.5`; no
/// sign, no exponent), above 0 and at most [`TIMEOUT_MAX_S`]; else the contract's message.
pub(crate) fn seconds(source: &str, text: &str) -> Result<Duration> {
    let (whole, fraction) = text.split_once('.').unwrap_or((text, "0"));
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    match text.parse::<f64>() {
        Ok(s) if digits(whole) && digits(fraction) && s > 0.0 && s <= TIMEOUT_MAX_S => Ok(Duration::from_secs_f64(s)),
        _ => Err(Error::new(format!(
            "{source}={text}: the bound must be a number of seconds above 0 and at most {TIMEOUT_MAX_S}, \
             written as digits with an optional fraction (2, 0.5)"
        ))),
    }
}

/// A setting's value and the variable it came from: the setting itself, or its old name when only
/// that is set. `None` when neither is set or the value is empty.
pub(crate) fn var(name: &str) -> Option<(&'static str, OsString)> {
    let setting = SETTINGS.iter().find(|s| s.name == name).map_or("", |s| s.name);
    if let Some(value) = std::env::var_os(name) {
        return (!value.is_empty()).then_some((setting, value));
    }
    let old = DEPRECATED.iter().find(|d| d.replacement == name)?;
    std::env::var_os(old.name).filter(|v| !v.is_empty()).map(|v| (old.name, v))
}

/// [`var`] as text (a value that is not Unicode is read lossily: it is then refused by its rule).
pub(crate) fn text(name: &str) -> Option<(&'static str, String)> {
    var(name).map(|(source, v)| (source, v.to_string_lossy().into_owned()))
}

/// Print the environment's warnings on standard error, once per process.
pub(crate) fn warn_once() {
    WARNED.call_once(|| {
        let names = std::env::vars_os().filter_map(|(k, _)| k.into_string().ok());
        for line in warnings(names) {
            eprintln!("plcvec: {line}");
        }
    });
}

/// Print nothing from now on: a process the harness started of itself, whose parent warned.
pub(crate) fn already_warned() {
    WARNED.call_once(|| {});
}

/// The warnings the variables `names` earn, sorted by variable (settings.py's `warnings`).
pub(crate) fn warnings(names: impl IntoIterator<Item = String>) -> Vec<String> {
    let mut names: Vec<String> = names.into_iter().filter(|n| n.starts_with(PREFIX)).collect();
    names.sort();
    let set = |name: &str| names.iter().any(|n| n == name);
    let mut out = Vec::new();
    for name in &names {
        let known = SETTINGS.iter().any(|s| s.name == name) || RESERVED.contains(&name.as_str());
        if known || RESERVED_PREFIXES.iter().any(|p| name.starts_with(p)) {
            continue;
        }
        if let Some(d) = DEPRECATED.iter().find(|d| d.name == name) {
            out.push(if set(d.replacement) {
                format!("warning: {name} is ignored: it is the old name of {}, which is set too", d.replacement)
            } else {
                format!(
                    "warning: {name} is the old name of {r}, read as it until plcvec {}; set {r} instead",
                    d.until,
                    r = d.replacement
                )
            });
            continue;
        }
        out.push(match nearest(name) {
            Some(guess) => format!("warning: {name} is not a plcvec setting; did you mean {guess}?"),
            None => {
                let all: Vec<&str> = SETTINGS.iter().map(|s| s.name).collect();
                format!("warning: {name} is not a plcvec setting; the settings are {}", all.join(", "))
            }
        });
    }
    out
}

/// The setting `name` most likely misspells: the first by name among those at the smallest edit
/// distance, if that is at most [`NEAREST_DISTANCE`]; an old name counts as its replacement.
fn nearest(name: &str) -> Option<&'static str> {
    let upper = name.to_uppercase();
    let mut candidates: Vec<&'static str> =
        SETTINGS.iter().map(|s| s.name).chain(DEPRECATED.iter().map(|d| d.name)).collect();
    candidates.sort_unstable();
    candidates.dedup();
    let best = candidates.into_iter().min_by_key(|c| (edit_distance(&upper, c), *c))?;
    if edit_distance(&upper, best) > NEAREST_DISTANCE {
        return None;
    }
    Some(DEPRECATED.iter().find(|d| d.name == best).map_or(best, |d| d.replacement))
}

/// Levenshtein distance over characters (insert, delete, replace: 1 each).
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut previous: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut current = vec![i + 1];
        for (j, &cb) in b.iter().enumerate() {
            current.push((previous[j + 1] + 1).min(current[j] + 1).min(previous[j] + usize::from(ca != cb)));
        }
        previous = current;
    }
    previous[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn warn(names: &[&str]) -> Vec<String> {
        warnings(names.iter().map(|n| (*n).to_owned()))
    }

    #[test]
    fn one_rule_for_the_bound() {
        for (text, ms) in [("10", 10_000), ("2.5", 2_500), ("0.5", 500), ("86400", 86_400_000), ("007.250", 7_250)] {
            assert_eq!(seconds("PLCVEC_TIMEOUT", text), Ok(Duration::from_millis(ms)), "{text}");
        }
        for text in
            ["0", "0.0", "86400.5", "86401", "1e9", "1e12", "-1", "+2", " 2", "2.", ".5", "inf", "NaN", "", "1_0"]
        {
            let e = seconds("PLCVEC_TIMEOUT", text).unwrap_err();
            assert_eq!(
                e.message(),
                format!(
                    "PLCVEC_TIMEOUT={text}: the bound must be a number of seconds above 0 and at most 86400, \
                     written as digits with an optional fraction (2, 0.5)"
                )
            );
        }
    }

    #[test]
    fn the_lines_of_the_contract() {
        // CONTRACT.md, "Old names and misspellings": the four lines, word for word.
        assert_eq!(
            warn(&["PLCVEC_EXPECTATIONS"]),
            ["warning: PLCVEC_EXPECTATIONS is the old name of PLCVEC_KNOWN_FAILURES, read as it until plcvec \
              0.3.0; set PLCVEC_KNOWN_FAILURES instead"]
        );
        assert_eq!(
            warn(&["PLCVEC_KNOWN_FAILURES", "PLCVEC_EXPECTATIONS"]),
            ["warning: PLCVEC_EXPECTATIONS is ignored: it is the old name of PLCVEC_KNOWN_FAILURES, which is set too"]
        );
        assert_eq!(warn(&["PLCVEC_TAGG"]), ["warning: PLCVEC_TAGG is not a plcvec setting; did you mean PLCVEC_TAG?"]);
        let colour = warn(&["PLCVEC_COLOUR"]);
        assert!(
            colour[0].starts_with(
                "warning: PLCVEC_COLOUR is not a plcvec setting; the settings are PLCVEC_VECTORS, PLCVEC_ID, "
            ),
            "{colour:?}"
        );
    }

    #[test]
    fn settings_reserved_names_and_other_variables_earn_nothing() {
        let quiet =
            ["PLCVEC_TAG", "PLCVEC_HOSTILE", "PLCVEC_HARNESS_PROGRESS", "PLCVEC_TEST_ANYTHING", "HOME", "plcvec_tag"];
        assert_eq!(warn(&quiet), Vec::<String>::new());
    }

    #[test]
    fn in_variable_order_and_by_the_nearest_name() {
        // Sorted by variable; an old name counts as its replacement (PLCVEC_EXPECTATION is one
        // letter from PLCVEC_EXPECTATIONS); the first by name among equals (PLCVEC_IB is 2 from
        // PLCVEC_ID and 3 from PLCVEC_TAG).
        assert_eq!(
            warn(&["PLCVEC_TIMOUT", "PLCVEC_EXPECTATION", "PLCVEC_IB"]),
            [
                "warning: PLCVEC_EXPECTATION is not a plcvec setting; did you mean PLCVEC_KNOWN_FAILURES?",
                "warning: PLCVEC_IB is not a plcvec setting; did you mean PLCVEC_ID?",
                "warning: PLCVEC_TIMOUT is not a plcvec setting; did you mean PLCVEC_TIMEOUT?",
            ]
        );
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        assert_eq!(nearest("PLCVEC_FAMILLY"), Some("PLCVEC_FAMILY"));
        assert_eq!(nearest("PLCVEC_WHATEVER_ELSE"), None);
    }
}
