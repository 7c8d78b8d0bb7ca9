//! The record a supervised child shares with its parent: whether the run came to its end and,
//! in the child that runs the vectors again after a run ended early, which vectors were being
//! judged when it ended.

use std::fs::File;

/// The file the supervised child shares with its parent (`PROGRESS_ENV`), which the parent reads
/// when the child has ended: the number of vectors (8 bytes, little-endian), a byte that says the
/// run came to its end, a byte per vector (not started, being judged, judged), then each vector's
/// id (its length in bytes, 4 bytes little-endian, then the id: an id may hold any character). A child that runs the vectors for the first time writes only the byte that
/// says it came to its end (the rest reads as no vector); the child that runs them again to find
/// the one a run ended on writes it all: each mark is one write of one byte at the vector's own
/// place, so that the file says exactly what was running whatever the test threads.
pub(super) struct Record {
    pub(super) file: File,
}

impl Record {
    pub(super) const RUNNING: u8 = 1;
    pub(super) const JUDGED: u8 = 2;
    /// Where the byte that says the run came to its end is.
    const END_AT: u64 = 8;
    /// Where the vectors' bytes begin.
    const MARKS_AT: u64 = 9;

    /// The record of a plan of these ids, written whole before any vector starts.
    pub(super) fn create<'a>(file: File, ids: impl ExactSizeIterator<Item = &'a str>) -> std::io::Result<Record> {
        let mut head = Vec::new();
        head.extend_from_slice(&(ids.len() as u64).to_le_bytes());
        head.push(0);
        head.resize(head.len() + ids.len(), 0);
        for id in ids {
            head.extend_from_slice(&u32::try_from(id.len()).unwrap_or(u32::MAX).to_le_bytes());
            head.extend_from_slice(id.as_bytes());
        }
        write_at(&file, &head, 0)?;
        Ok(Record { file })
    }

    pub(super) fn mark(&self, index: usize, state: u8) {
        let _ = write_at(&self.file, &[state], Record::MARKS_AT + index as u64);
    }

    /// Note in the file at `path` that the run came to its end, through a descriptor opened for
    /// it: one the implementation closed (or replaced) in the meantime cannot lose the note.
    pub(super) fn came_to_end_at(path: &std::path::Path) {
        if let Ok(file) = std::fs::OpenOptions::new().write(true).open(path) {
            Record::came_to_end(&file);
        }
    }

    /// Note in `file` that the run came to its end (not ended half way).
    pub(super) fn came_to_end(file: &File) {
        let _ = write_at(file, &[1], Record::END_AT);
    }

    /// What a record says: the ids of the vectors being judged, how many were judged, and
    /// whether the run came to its end.
    pub(super) fn read(bytes: &[u8]) -> (Vec<String>, usize, bool) {
        let Some((n, rest)) = bytes.split_first_chunk::<8>() else { return (Vec::new(), 0, false) };
        let Some((&end, rest)) = rest.split_first() else { return (Vec::new(), 0, false) };
        let n = usize::try_from(u64::from_le_bytes(*n)).unwrap_or(usize::MAX).min(rest.len());
        let (marks, mut rest) = rest.split_at(n);
        let mut ids = Vec::new();
        while let Some((len, after)) = rest.split_first_chunk::<4>() {
            let len = usize::try_from(u32::from_le_bytes(*len)).unwrap_or(usize::MAX).min(after.len());
            let (id, after) = after.split_at(len);
            ids.push(id);
            rest = after;
        }
        let running = (0..n)
            .filter(|&i| marks[i] == Record::RUNNING)
            .map(|i| {
                ids.get(i).map_or_else(
                    || format!("the vector at {i} of the plan"),
                    |id| String::from_utf8_lossy(id).into_owned(),
                )
            })
            .collect();
        (running, marks.iter().filter(|&&m| m == Record::JUDGED).count(), end != 0)
    }
}

/// One write of `bytes` at `offset` in `file` (whatever the file's position).
fn write_at(file: &File, bytes: &[u8], offset: u64) -> std::io::Result<()> {
    #[cfg(unix)]
    {
        std::os::unix::fs::FileExt::write_all_at(file, bytes, offset)
    }
    #[cfg(windows)]
    {
        let written = std::os::windows::fs::FileExt::seek_write(file, bytes, offset)?;
        if written == bytes.len() {
            Ok(())
        } else {
            Err(std::io::Error::new(std::io::ErrorKind::WriteZero, "a short write to the progress record"))
        }
    }
    #[cfg(not(any(unix, windows)))]
    {
        let _ = (file, bytes, offset);
        Err(std::io::Error::new(std::io::ErrorKind::Unsupported, "no positioned writes on this platform"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::PathBuf;

    fn scratch(name: &str) -> PathBuf {
        std::env::temp_dir().join(format!("plcvec-harness-{name}-{}", std::process::id()))
    }

    #[test]
    fn the_record_says_which_vectors_were_running_whatever_their_ids() {
        let path = scratch("record");
        let ids = ["a/1", "b\nwith a line break", "", "d/4"];
        let record = Record::create(File::create(&path).unwrap(), ids.iter().copied()).unwrap();
        // Nothing started yet, the run not at its end.
        assert_eq!(Record::read(&std::fs::read(&path).unwrap()), (vec![], 0, false));
        record.mark(0, Record::RUNNING);
        record.mark(1, Record::RUNNING);
        record.mark(3, Record::RUNNING);
        record.mark(0, Record::JUDGED);
        let expected = vec!["b\nwith a line break".to_owned(), "d/4".to_owned()];
        assert_eq!(Record::read(&std::fs::read(&path).unwrap()), (expected.clone(), 1, false));
        Record::came_to_end(&record.file);
        assert_eq!(Record::read(&std::fs::read(&path).unwrap()), (expected, 1, true));
        std::fs::remove_file(&path).unwrap();
    }

    #[test]
    fn a_first_run_notes_only_its_end() {
        // A child that records no vector writes the end's byte alone (into the empty file its
        // parent made); one that ended early, nothing.
        assert_eq!(Record::read(&[]), (vec![], 0, false));
        let path = scratch("end");
        let file = File::create(&path).unwrap();
        Record::came_to_end(&file);
        assert_eq!(Record::read(&std::fs::read(&path).unwrap()), (vec![], 0, true));
        std::fs::remove_file(&path).unwrap();
    }
}
