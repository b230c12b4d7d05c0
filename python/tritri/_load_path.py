"""load_mesh's path handling (tritri.load_mesh): any name the system takes, also names that
are not UTF-8 (bytes, or the str with surrogate escapes that os.fsdecode makes of them).

The C++ loader (tritri._tritri.load_mesh) takes UTF-8 text and passes its bytes on to the
system unchanged, so a name that is UTF-8 goes to it as it is. A name that is not is
reached through a symbolic link with a UTF-8 name (same extension) in a fresh private
folder, removed afterwards; messages then name the file as given, with the bytes that are
not UTF-8 shown as \\xHH. Where no link can be made, ValueError says so.
"""

import os
import tempfile


def load_mesh_file(raw, load):
    """load(path) on the file named by raw (bytes, without NUL)."""
    try:
        text = raw.decode("utf-8")  # strict: exactly the bytes of raw again on the C++ side
    except UnicodeDecodeError:
        text = None
    if text is not None:
        return load(text)
    shown = raw.decode("utf-8", "backslashreplace")
    # Relative to the working folder, not normalized: ".." resolves as the system resolves it.
    target = raw if os.path.isabs(raw) else os.path.join(os.getcwdb(), raw)
    extension = os.path.splitext(os.path.basename(raw))[1].decode("utf-8", "backslashreplace")
    folder = tempfile.mkdtemp(prefix="tritri-load-")
    link = os.path.join(folder, "mesh" + extension)
    try:
        try:
            os.symlink(target, os.fsencode(link))
        except OSError as e:
            raise ValueError(f"tritri.load_mesh: {shown}: a name that is not UTF-8, which cannot be "
                             f"passed on here ({e.strerror})") from None
        try:
            return load(link)
        except ValueError as e:
            raise ValueError(str(e).replace(link, shown)) from None
    finally:
        if os.path.lexists(link):
            os.unlink(link)
        os.rmdir(folder)
