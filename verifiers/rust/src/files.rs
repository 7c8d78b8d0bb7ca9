//! Reading the files a run is given (the index, the vector files, the known-failures file): only
//! regular files, looked at by their path before they are opened, so that no load can wait for
//! ever on a named pipe nobody writes or read a device that never ends (CONTRACT.md, "Loading").

use std::fs;
use std::path::Path;

use crate::error::{Error, Result};

/// `Ok` when `path` is a regular file (through any symbolic links); otherwise the contract's
/// message naming it: `<path>: not a regular file (a named pipe)`, `<path>: a loop of symbolic
/// links`. A path that does not exist, or cannot be looked at, is left to the caller's read.
pub(crate) fn check_regular(path: &Path) -> Result<()> {
    match fs::metadata(path) {
        Ok(meta) if meta.is_file() => Ok(()),
        Ok(meta) => Err(Error::new(format!("{}: not a regular file ({})", path.display(), kind(&meta.file_type())))),
        Err(e) if is_loop(&e) => Err(Error::new(format!("{}: a loop of symbolic links", path.display()))),
        Err(_) => Ok(()),
    }
}

/// Whether the error is ELOOP: too many symbolic links were followed.
fn is_loop(e: &std::io::Error) -> bool {
    // ErrorKind::FilesystemLoop is not stable on the crate's rust-version: the OS's own code.
    #[cfg(unix)]
    {
        const ELOOP: i32 =
            if cfg!(any(target_os = "macos", target_os = "ios", target_os = "freebsd")) { 62 } else { 40 };
        e.raw_os_error() == Some(ELOOP)
    }
    #[cfg(not(unix))]
    {
        let _ = e;
        false
    }
}

/// What a file that is not a regular file is, in words.
fn kind(t: &fs::FileType) -> &'static str {
    if t.is_dir() {
        return "a folder";
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "a named pipe";
        }
        if t.is_socket() {
            return "a socket";
        }
        if t.is_char_device() {
            return "a character device";
        }
        if t.is_block_device() {
            return "a block device";
        }
    }
    "not a file"
}

/// A regular file's bytes. The file is opened without waiting (a named pipe put there after the
/// look would otherwise block the open) and looked at again through the descriptor.
pub(crate) fn read_bytes(path: &Path) -> Result<Vec<u8>> {
    use std::io::Read;
    check_regular(path)?;
    let cannot = |e: std::io::Error| Error::new(format!("{}: cannot read: {e}", path.display()));
    let mut file = open_without_waiting(path).map_err(cannot)?;
    if !file.metadata().map_err(cannot)?.is_file() {
        return Err(Error::new(format!("{}: not a regular file", path.display())));
    }
    let mut bytes = Vec::new();
    file.read_to_end(&mut bytes).map_err(cannot)?;
    Ok(bytes)
}

fn open_without_waiting(path: &Path) -> std::io::Result<fs::File> {
    let mut options = fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        // O_NONBLOCK (no libc in this crate): a regular file reads as ever with it.
        const O_NONBLOCK: i32 = if cfg!(any(target_os = "linux", target_os = "android")) { 0o4000 } else { 0x0004 };
        options.custom_flags(O_NONBLOCK);
    }
    options.open(path)
}

/// The bytes as text, or the line and column of the first byte that is not UTF-8.
pub(crate) fn utf8(path: &Path, bytes: Vec<u8>) -> Result<String> {
    String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let before = &e.as_bytes()[..at];
        let line = before.iter().filter(|&&b| b == b'\n').count() + 1;
        let column = at - before.iter().rposition(|&b| b == b'\n').map_or(0, |p| p + 1) + 1;
        Error::new(format!("{}:{line}:{column}: a byte that is not UTF-8 (a damaged copy?)", path.display()))
    })
}

/// A regular file's text.
pub(crate) fn read_text(path: &Path) -> Result<String> {
    utf8(path, read_bytes(path)?)
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;

    #[test]
    fn what_is_not_a_regular_file_is_named_before_it_is_opened() {
        let dir = std::env::temp_dir().join(format!("plcvec-files-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        let file = dir.join("f.json");
        fs::write(&file, "{}").unwrap();
        assert_eq!(check_regular(&file), Ok(()));
        let message = |p: &Path| check_regular(p).unwrap_err().message().to_owned();
        assert_eq!(message(&dir), format!("{}: not a regular file (a folder)", dir.display()));
        let device = dir.join("zero.json");
        std::os::unix::fs::symlink("/dev/zero", &device).unwrap();
        assert_eq!(message(&device), format!("{}: not a regular file (a character device)", device.display()));
        let looped = dir.join("loop.json");
        std::os::unix::fs::symlink("loop.json", &looped).unwrap();
        assert_eq!(message(&looped), format!("{}: a loop of symbolic links", looped.display()));
        // A named pipe nobody writes: refused at once, never opened (an open would block).
        let pipe = dir.join("pipe.json");
        let made = std::process::Command::new("mkfifo").arg(&pipe).status().unwrap();
        assert!(made.success());
        assert_eq!(message(&pipe), format!("{}: not a regular file (a named pipe)", pipe.display()));
        assert_eq!(read_text(&pipe).unwrap_err().message(), message(&pipe));
        fs::remove_dir_all(&dir).unwrap();
    }
}
