"""Reproducible archives: the same files give the same bytes of .tar.gz and .zip on every run.

What would otherwise vary is fixed: entries in sorted order, every timestamp 1980-01-01 00:00:00
(the earliest a zip can hold), owner and group 0 with no names, mode 0644, the gzip header's
mtime 0 and no file name in it.
"""
import gzip
import io
import tarfile
import zipfile

EPOCH = 315532800                 # 1980-01-01T00:00:00Z
ZIP_EPOCH = (1980, 1, 1, 0, 0, 0)
FILE_MODE = 0o644


def tar_gz(files):
    """The bytes of a .tar.gz of {archive path: bytes}."""
    raw = io.BytesIO()
    with tarfile.open(fileobj=raw, mode="w", format=tarfile.PAX_FORMAT) as tar:
        for name in sorted(files):
            info = tarfile.TarInfo(name)
            info.size = len(files[name])
            info.mtime, info.mode = EPOCH, FILE_MODE
            info.uid = info.gid = 0
            info.uname = info.gname = ""
            tar.addfile(info, io.BytesIO(files[name]))
    out = io.BytesIO()
    with gzip.GzipFile(filename="", mode="wb", fileobj=out, mtime=0, compresslevel=9) as gz:
        gz.write(raw.getvalue())
    return out.getvalue()


def zip_bytes(files):
    """The bytes of a .zip of {archive path: bytes}."""
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w") as z:
        for name in sorted(files):
            info = zipfile.ZipInfo(name, date_time=ZIP_EPOCH)
            info.compress_type = zipfile.ZIP_DEFLATED
            info.create_system = 3                      # unix, so the mode below is read
            info.external_attr = (0o100000 | FILE_MODE) << 16
            z.writestr(info, files[name], compresslevel=9)
    return out.getvalue()
