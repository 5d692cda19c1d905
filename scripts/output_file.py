"""Charts saved by the rule every fb89 output follows (docs/RELIABILITY.md, Outputs;
protocol/output_file.h), for every plotting script in the project: scripts/plot_figures.py
and bench/growth/plot_growth.py.

- "-", /dev/stdout and other names of an open descriptor: written there.
- A regular file or a new path: whole or not at all (a hidden temporary beside it, synced,
  then renamed over it), so a failed or killed run leaves the old chart.
- A device, FIFO or socket: written in place, never renamed over.
- A directory: an error naming it."""
import os
import re
import socket
import stat
import sys
import tempfile


def _descriptor(path):
    """The descriptor `path` names ("-", /dev/stdout, /dev/fd/N, /proc/self/fd/N), else None."""
    if path == "-":
        return 1
    pattern = re.compile(r"^/(?:dev/fd|proc/self/fd|proc/%d/fd)/(\d+)$" % os.getpid())
    p = path
    for _ in range(40):
        m = pattern.match(os.path.normpath(p))
        if m:
            return int(m.group(1))
        if not os.path.islink(p):
            return None
        target = os.readlink(p)
        p = target if os.path.isabs(target) else os.path.join(os.path.dirname(p), target)
    return None


def _write_png(fig, f):
    fig.savefig(f, format="png", dpi=110)
    f.flush()


def save(fig, path):
    """Saves the chart `fig` as PNG to `path` by the rule above."""
    fd = _descriptor(path)
    if fd is not None:
        sys.stdout.flush()
        with os.fdopen(os.dup(fd), "wb") as f:
            _write_png(fig, f)
        return
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        mode = None
    if mode is not None and stat.S_ISDIR(mode):
        raise IsADirectoryError(f"{path}: is a directory, not a file to write")
    if mode is not None and stat.S_ISSOCK(mode):
        with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as s:
            s.connect(path)
            with s.makefile("wb") as f:
                _write_png(fig, f)
        return
    if mode is not None and not stat.S_ISREG(mode):
        with open(path, "wb") as f:  # a device or FIFO: in place
            _write_png(fig, f)
        return
    target = os.path.realpath(path)  # a symbolic link is replaced through the link
    folder, name = os.path.split(target)
    fd, tmp = tempfile.mkstemp(dir=folder or ".", prefix=f".{name}.tmp-")
    try:
        with os.fdopen(fd, "wb") as f:
            _write_png(fig, f)
            os.fsync(f.fileno())
        if mode is not None:
            os.chmod(tmp, stat.S_IMODE(mode))
        else:
            umask = os.umask(0)
            os.umask(umask)
            os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, target)
    except BaseException:
        os.unlink(tmp)
        raise
