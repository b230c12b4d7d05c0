"""write_atomic(path, write): a file written whole or not at all, for the bench scripts.

write(f) fills a binary file object; it goes to a temporary file in the same folder (mode
that of a normal new file: 0666 less the umask), which is then renamed over path. On any
error the temporary is removed and the error raised again.
"""
import os
import tempfile
from pathlib import Path


def write_atomic(path, write):
    """Writes through a temporary file in the same folder, then renames it over path."""
    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
    umask = os.umask(0)
    os.umask(umask)
    try:
        os.chmod(tmp, 0o666 & ~umask)  # mkstemp makes it private; give it a normal file's mode
        with os.fdopen(fd, "wb") as f:
            write(f)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise
