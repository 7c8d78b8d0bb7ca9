//! Loading a vector set: the copy compiled into the crate, or another one on disk.
//!
//! `PLCVEC_VECTORS` names another copy: a folder holding `index.json` and `<family>.jsonl` files
//! (what `plcvec export` writes), or the repository's `vectors/` folder (`manifest.json` and
//! `<family>.json`), or a single family file. A damaged file, a vector the contract cannot run,
//! or a schema major version other than 1 is refused with the file, the line or the vector id.

use std::collections::{BTreeMap, HashMap};

use std::path::Path;

use serde::Deserialize;

use crate::error::{Error, Result};
use crate::files::{check_regular, read_bytes, read_text, utf8};
use crate::generated::embedded;
use crate::unique::{self, Unique};
use crate::vector::{RawVector, Vector};

/// The major schema version this crate reads (CONTRACT.md, "Versioning"): a 2.x file may mean
/// something else by the same fields, so it is refused rather than misread.
pub const SCHEMA_MAJOR: &str = "1";

/// The environment variable that points the crate at another copy of the vectors.
pub const VECTORS_ENV: &str = "PLCVEC_VECTORS";

/// What a family file's header says about one interpretation.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InterpretationInfo {
    /// The id (`FX5-SM709-SCOPE`).
    pub id: String,
    /// The question the manual leaves open.
    #[serde(default)]
    pub question: String,
    /// The alternative that holds unless another is declared.
    pub default: String,
    /// Every alternative's id.
    #[serde(deserialize_with = "alternative_ids")]
    pub alternatives: Vec<String>,
}

/// A map of names that holds no key twice (`unique`), kept as the `BTreeMap` the public field is.
fn unique_map<'de, D: serde::Deserializer<'de>, V: Deserialize<'de>>(
    d: D,
) -> std::result::Result<BTreeMap<String, V>, D::Error> {
    Ok(Unique::<V>::deserialize(d)?.0)
}

fn alternative_ids<'de, D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Vec<String>, D::Error> {
    #[derive(Deserialize)]
    #[serde(deny_unknown_fields)]
    struct Alt {
        id: String,
        #[serde(default, rename = "says")]
        _says: unique::NoRepeats,
    }
    Ok(Vec::<Alt>::deserialize(d)?.into_iter().map(|a| a.id).collect())
}

/// A family file's header: everything but its vectors.
///
/// Every key a file holds must be one the schema defines (CONTRACT.md, "Loading"): an unknown
/// key is a damaged or hand-edited file, refused rather than half read.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FamilyHeader {
    /// The family (`fx5-time-add`).
    pub family: String,
    /// The family's title.
    #[serde(default)]
    pub title: String,
    /// The rule kind (`clock_add`).
    #[serde(default)]
    pub kind: String,
    /// The file's schema version.
    pub schema_version: String,
    /// The hash of the spec the file was generated from.
    #[serde(default)]
    pub spec_sha256: String,
    /// The family's instructions.
    #[serde(default)]
    pub instructions: Vec<String>,
    /// Every tag with its meaning.
    #[serde(default, deserialize_with = "unique_map")]
    pub tags: BTreeMap<String, String>,
    /// The family's interpretations.
    #[serde(default)]
    pub interpretations: Vec<InterpretationInfo>,
    /// How many vectors the file holds.
    #[serde(default)]
    pub count: Option<usize>,
    /// Where the spec lives (`spec/fx5-time-add.yaml`).
    #[serde(default)]
    pub spec_file: String,
    /// The note that the file is generated.
    #[serde(default)]
    pub generated: String,
}

/// The old name of [`FamilyHeader`].
#[deprecated(since = "0.3.0", note = "use FamilyHeader, the shared name of a family file's header")]
pub type FamilyInfo = FamilyHeader;

/// A loaded vector set.
#[derive(Clone, Debug)]
pub struct Suite {
    source: String,
    suite_version: String,
    schema_version: String,
    spec_sha256: String,
    families: Vec<FamilyHeader>,
    vectors: Vec<Vector>,
    by_id: HashMap<String, usize>,
    /// Old id -> the id of the vector it was merged into (every family's `merged`).
    merged: HashMap<String, String>,
}

/// Old id -> the id of the vector it was merged into, per family (`merged`).
type Merged = Unique<Unique<String>>;

#[derive(Deserialize)]
struct Index {
    #[serde(default)]
    suite_version: String,
    #[serde(default)]
    spec_sha256: String,
    families: Unique<IndexEntry>,
    #[serde(default)]
    merged: Merged,
}

#[derive(Deserialize)]
struct IndexEntry {
    file: String,
    count: Option<usize>,
    /// The sha256 of the file's bytes: a copy cut short or edited is refused before it is read.
    sha256: Option<String>,
}

#[derive(Deserialize)]
struct Manifest {
    /// The suite version; `generator_version` is its old name, written beside it until 0.3.0.
    #[serde(default)]
    suite_version: String,
    #[serde(default)]
    generator_version: String,
    #[serde(default)]
    spec_sha256: String,
    families: Unique<IndexEntry>,
    #[serde(default)]
    merged: Merged,
}

impl Suite {
    /// The copy compiled into the crate.
    pub fn embedded() -> Result<Suite> {
        let index: Index =
            serde_json::from_str(embedded::INDEX).map_err(|e| Error::new(format!("(embedded) index.json: {e}")))?;
        let mut parts = Vec::new();
        for (family, file, text) in embedded::FAMILIES {
            let count = index.families.get(*family).and_then(|e| e.count);
            parts.push(parse_jsonl(&format!("(embedded) {file}"), text, count)?);
        }
        Suite::assemble("(embedded vectors)".into(), index.suite_version, index.spec_sha256, parts, index.merged)
    }

    /// The copy `PLCVEC_VECTORS` names, or the embedded one when it is unset or empty.
    pub fn from_env() -> Result<Suite> {
        match std::env::var_os(VECTORS_ENV) {
            Some(path) if !path.is_empty() => {
                Suite::load(&path).map_err(|e| Error::new(format!("{e} (from {VECTORS_ENV})")))
            }
            _ => Suite::embedded(),
        }
    }

    /// A copy on disk: a folder with `index.json` (+ `*.jsonl`) or `manifest.json` (+ `*.json`),
    /// or one family file (`.jsonl` or `.json`).
    pub fn load(path: impl AsRef<Path>) -> Result<Suite> {
        let path = path.as_ref();
        let source = path.display().to_string();
        // Whatever lies there (a named pipe, a loop of links) is the index, refused by its name.
        let present = |p: &Path| std::fs::symlink_metadata(p).is_ok();
        if path.is_dir() {
            if present(&path.join("index.json")) {
                return Suite::load_index(path, source);
            }
            if present(&path.join("manifest.json")) {
                return Suite::load_manifest(path, source);
            }
            return Err(Error::new(format!(
                "{source}: neither index.json nor manifest.json; is this a plcvec vector folder?"
            )));
        }
        check_regular(path)?;
        if !path.exists() {
            return Err(Error::new(format!("{source}: no such vector folder or file")));
        }
        let part = if path.extension().is_some_and(|e| e == "jsonl") {
            parse_jsonl(&source, &read_text(path)?, None)?
        } else {
            parse_family_json(path, &read_text(path)?, None)?
        };
        Suite::assemble(source, String::new(), String::new(), vec![part], Merged::default())
    }

    /// A JSON-lines copy: `index.json` and a sealed `.jsonl` file per family.
    fn load_index(path: &Path, source: String) -> Result<Suite> {
        let index_path = path.join("index.json");
        let index: Index = read_json(&index_path)?;
        let mut parts = Vec::new();
        for (family, entry) in index.families.iter() {
            let file = path.join(&entry.file);
            let Some(sha256) = &entry.sha256 else {
                return Err(Error::new(format!(
                    "{}: family {family} has no sha256 (a copy's files are checked against their index)",
                    index_path.display()
                )));
            };
            let (text, seal) = read_sealed(&file, sha256, &index_path)?;
            parts.push(seal.check(parse_jsonl(&file.display().to_string(), &text, entry.count))?);
        }
        Suite::assemble(source, index.suite_version, index.spec_sha256, parts, index.merged)
    }

    /// The repository's form: `manifest.json` and a `.json` file per family.
    fn load_manifest(path: &Path, source: String) -> Result<Suite> {
        let manifest_path = path.join("manifest.json");
        let manifest: Manifest = read_json(&manifest_path)?;
        let mut parts = Vec::new();
        for entry in manifest.families.values() {
            let file = path.join(&entry.file);
            let (text, seal) = match &entry.sha256 {
                Some(sha256) => read_sealed(&file, sha256, &manifest_path)?,
                None => (read_text(&file)?, Seal(None)),
            };
            parts.push(seal.check(parse_family_json(&file, &text, entry.count))?);
        }
        let version =
            if manifest.suite_version.is_empty() { manifest.generator_version } else { manifest.suite_version };
        Suite::assemble(source, version, manifest.spec_sha256, parts, manifest.merged)
    }

    fn assemble(
        source: String,
        suite_version: String,
        spec_sha256: String,
        parts: Vec<(FamilyHeader, Vec<Vector>)>,
        merged: Merged,
    ) -> Result<Suite> {
        let merged = merged.into_iter().flat_map(|(_, ids)| ids).collect();
        let mut families = Vec::new();
        let mut vectors = Vec::new();
        let mut versions: Vec<String> = Vec::new();
        for (info, vs) in parts {
            if !versions.contains(&info.schema_version) {
                versions.push(info.schema_version.clone());
            }
            families.push(info);
            vectors.extend(vs);
        }
        versions.sort();
        let mut by_id = HashMap::with_capacity(vectors.len());
        for (i, v) in vectors.iter().enumerate() {
            if by_id.insert(v.id().to_owned(), i).is_some() {
                return Err(Error::new(format!("{source}: vector id {} appears twice", v.id())));
            }
        }
        let spec_sha256 = if spec_sha256.is_empty() {
            families.iter().map(|f| f.spec_sha256.clone()).filter(|h| !h.is_empty()).collect::<Vec<_>>().join(", ")
        } else {
            spec_sha256
        };
        let schema_version = versions.join(", ");
        let suite = Suite { source, suite_version, schema_version, spec_sha256, families, vectors, by_id, merged };
        suite.interpretations()?;
        Ok(suite)
    }

    /// Where the vectors came from (a path, or "(embedded vectors)").
    pub fn source(&self) -> &str {
        &self.source
    }
    /// The suite version (empty for a single family file).
    pub fn suite_version(&self) -> &str {
        &self.suite_version
    }
    /// The schema version(s) of the files.
    pub fn schema_version(&self) -> &str {
        &self.schema_version
    }
    /// The spec hash the vectors were generated from.
    pub fn spec_sha256(&self) -> &str {
        &self.spec_sha256
    }
    /// Every family file's header.
    pub fn families(&self) -> &[FamilyHeader] {
        &self.families
    }
    /// One family's header.
    pub fn family(&self, name: &str) -> Option<&FamilyHeader> {
        self.families.iter().find(|f| f.family == name)
    }
    /// Every vector, family by family, each family sorted by id.
    pub fn vectors(&self) -> &[Vector] {
        &self.vectors
    }
    /// A vector by id.
    pub fn get(&self, id: &str) -> Option<&Vector> {
        self.by_id.get(id).map(|&i| &self.vectors[i])
    }

    /// The id of the vector an id the suite no longer has was merged into, the vector files'
    /// `merged` map followed to its end (a vector merged into one that was merged again is named
    /// by the one it is now); `None` for an id that was never merged.
    pub fn merged_into(&self, id: &str) -> Option<&str> {
        let mut now = self.merged.get(id)?;
        // A map that loops (a damaged file) ends after as many steps as it has entries.
        for _ in 0..self.merged.len() {
            match self.merged.get(now.as_str()) {
                Some(next) if !self.by_id.contains_key(now.as_str()) => now = next,
                _ => break,
            }
        }
        Some(now)
    }

    /// Every interpretation, each once (the FX5 time and date comparisons share theirs): id ->
    /// (its description, the families that share it). An interpretation must say the same in
    /// every family that has it.
    pub fn interpretations(&self) -> Result<BTreeMap<&str, (&InterpretationInfo, Vec<&str>)>> {
        let mut out: BTreeMap<&str, (&InterpretationInfo, Vec<&str>)> = BTreeMap::new();
        for f in &self.families {
            for i in &f.interpretations {
                let entry = out.entry(&i.id).or_insert((i, Vec::new()));
                if (&entry.0.default, &entry.0.alternatives) != (&i.default, &i.alternatives) {
                    return Err(Error::new(format!(
                        "{}: interpretation {} has other alternatives or another default in {} than in {}",
                        self.source, i.id, f.family, entry.1[0]
                    )));
                }
                entry.1.push(&f.family);
            }
        }
        Ok(out)
    }

    /// interpretation id -> default alternative.
    pub fn defaults(&self) -> BTreeMap<&str, &str> {
        self.families
            .iter()
            .flat_map(|f| f.interpretations.iter().map(|i| (i.id.as_str(), i.default.as_str())))
            .collect()
    }
}

/// Whether a file's bytes are those its index records: `Some` error when they differ.
struct Seal(Option<Error>);

impl Seal {
    /// The file's parse, refused when the seal is broken. A parse error comes first, since it
    /// names the line; a file that parses but differs from its index is still refused.
    fn check<T>(self, parsed: Result<T>) -> Result<T> {
        match (parsed, self.0) {
            (Err(e), Some(_)) => {
                Err(Error::new(format!("{e} (and the file's sha256 is not the one its index records)")))
            }
            (Err(e), None) | (Ok(_), Some(e)) => Err(e),
            (Ok(t), None) => Ok(t),
        }
    }
}

/// A file whose sha256 its index records, with the check of its seal: a copy cut short,
/// interrupted or edited is refused.
fn read_sealed(path: &Path, sha256: &str, index: &Path) -> Result<(String, Seal)> {
    use sha2::{Digest, Sha256};
    let bytes = read_bytes(path)?;
    let digest = Sha256::digest(&bytes);
    let hex: String = digest.iter().map(|b| format!("{b:02x}")).collect();
    let seal = (!hex.eq_ignore_ascii_case(sha256)).then(|| {
        Error::new(format!(
            "{}: sha256 {hex}, but {} records {sha256} (a damaged, cut or edited copy; copy the vectors again)",
            path.display(),
            index.display()
        ))
    });
    Ok((utf8(path, bytes)?, Seal(seal)))
}

/// An index (`index.json`, `manifest.json`): small, so checked whole for a repeated key first
/// (its keys this crate does not read included), then read.
fn read_json<T: serde::de::DeserializeOwned>(path: &Path) -> Result<T> {
    let text = read_text(path)?;
    let refused = |e: serde_json::Error| {
        let what =
            if unique::is_repeated(&e) { unique::message(&e) } else { format!("not a readable plcvec file ({e})") };
        Error::new(format!("{}:{}: {what}", path.display(), e.line()))
    };
    serde_json::from_str::<unique::NoRepeats>(&text).map_err(refused)?;
    serde_json::from_str(&text).map_err(refused)
}

fn check_header(name: &str, header: &FamilyHeader) -> Result<()> {
    let major = header.schema_version.split('.').next().unwrap_or("");
    if major != SCHEMA_MAJOR {
        return Err(Error::new(format!(
            "{name}: schema_version {} is not {SCHEMA_MAJOR}.x; this crate reads {SCHEMA_MAJOR}.x files only (see CONTRACT.md, Versioning)",
            if header.schema_version.is_empty() { "(none)" } else { &header.schema_version }
        )));
    }
    Ok(())
}

fn check_vector(name: &str, where_: &str, header: &FamilyHeader, raw: RawVector) -> Result<Vector> {
    if raw.family != header.family {
        return Err(Error::new(format!(
            "{where_}: vector {}: family {:?} in a {:?} file",
            raw.id, raw.family, header.family
        )));
    }
    let v = Vector::from_raw(raw, true).map_err(|e| Error::new(format!("{where_}: {e}")))?;
    for i in v.interpretations() {
        if !header.interpretations.iter().any(|h| &h.id == i) {
            return Err(Error::new(format!(
                "{name}: vector {}: depends on interpretation {i}, which the header does not define",
                v.id()
            )));
        }
    }
    Ok(v)
}

fn check_count(name: &str, count: Option<usize>, found: usize) -> Result<()> {
    match count {
        Some(n) if n != found => {
            Err(Error::new(format!("{name}: {found} vectors, but the index says {n} (a truncated or damaged copy?)")))
        }
        _ => Ok(()),
    }
}

/// One family in JSON Lines: line 1 the header, then one vector a line.
fn parse_jsonl(name: &str, text: &str, count: Option<usize>) -> Result<(FamilyHeader, Vec<Vector>)> {
    let mut lines = text.lines().enumerate().filter(|(_, l)| !l.trim().is_empty());
    let (_, first) = lines.next().ok_or_else(|| Error::new(format!("{name}: empty file")))?;
    let header: FamilyHeader = serde_json::from_str(first).map_err(|e| {
        let what =
            if unique::is_repeated(&e) { unique::message(&e) } else { format!("not a plcvec family header ({e})") };
        Error::new(format!("{name}:1: {what}"))
    })?;
    check_header(name, &header)?;
    let mut vectors = Vec::new();
    for (n, line) in lines {
        let where_ = format!("{name}:{}", n + 1);
        let raw: RawVector = serde_json::from_str(line).map_err(|e| {
            let id = id_of(line).map(|s| format!(" vector {s}:")).unwrap_or_default();
            if unique::is_repeated(&e) {
                return Error::new(format!("{where_}:{id} {}", unique::message(&e)));
            }
            Error::new(format!("{where_}:{id} not a plcvec vector ({e})"))
        })?;
        vectors.push(check_vector(name, &where_, &header, raw)?);
    }
    check_count(name, count, vectors.len())?;
    Ok((header, vectors))
}

/// The `id` of a vector's JSON text, read leniently (for a message about a vector that is refused).
fn id_of(text: &str) -> Option<String> {
    let v = serde_json::from_str::<serde_json::Value>(text).ok()?;
    v.get("id").and_then(|i| i.as_str()).map(str::to_owned)
}

/// A repeated key anywhere in a family file of the repository's form, by line and vector id: the
/// file is read whole into a tree (where the last of two values would silently win), so it is
/// checked first (this form is not the one the crate embeds; the JSON-lines form is checked in its
/// one parse).
fn check_repeats(name: &str, text: &str) -> Result<()> {
    let Err(e) = serde_json::from_str::<unique::NoRepeats>(text) else { return Ok(()) };
    if !unique::is_repeated(&e) {
        return Ok(()); // not JSON: said by the parse that follows, as before
    }
    #[derive(Deserialize)]
    struct Vectors<'a> {
        #[serde(borrow, default)]
        vectors: Vec<&'a serde_json::value::RawValue>,
    }
    let line_of = |offset: usize| text[..offset].matches('\n').count() + 1;
    let id = serde_json::from_str::<Vectors<'_>>(text).ok().and_then(|file| {
        let inside = file.vectors.into_iter().find(|raw| {
            let start = raw.get().as_ptr() as usize - text.as_ptr() as usize;
            (line_of(start)..=line_of(start + raw.get().len())).contains(&e.line())
        })?;
        id_of(inside.get())
    });
    let id = id.map(|id| format!(" vector {id}:")).unwrap_or_default();
    Err(Error::new(format!("{name}:{}:{id} {}", e.line(), unique::message(&e))))
}

/// One family file as `plcvec generate` writes it: a JSON object with `vectors`.
fn parse_family_json(path: &Path, text: &str, count: Option<usize>) -> Result<(FamilyHeader, Vec<Vector>)> {
    let name = path.display().to_string();
    check_repeats(&name, text)?;
    let mut data: serde_json::Value = serde_json::from_str(text)
        .map_err(|e| Error::new(format!("{name}:{}: not a readable plcvec file ({e})", e.line())))?;
    let vectors = match data.as_object_mut().and_then(|o| o.remove("vectors")) {
        Some(serde_json::Value::Array(vs)) => vs,
        _ => return Err(Error::new(format!("{name}: not a plcvec vector file (no `vectors` list)"))),
    };
    let header =
        FamilyHeader::deserialize(&data).map_err(|e| Error::new(format!("{name}: not a plcvec vector file ({e})")))?;
    check_header(&name, &header)?;
    let mut out = Vec::with_capacity(vectors.len());
    for (k, v) in vectors.into_iter().enumerate() {
        let label = v.get("id").and_then(|i| i.as_str()).map_or(format!("#{k}"), str::to_owned);
        let raw = RawVector::deserialize(&v).map_err(|e| {
            Error::new(format!("{name}: vector {label}: {e} (is the file a plcvec vector file, unedited?)"))
        })?;
        out.push(check_vector(&name, &name, &header, raw)?);
    }
    check_count(&name, count, out.len())?;
    Ok((header, out))
}
