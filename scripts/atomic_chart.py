"""Charts written whole or not at all (docs/RELIABILITY.md, Outputs), for every plotting
script in the project: scripts/plot_figures.py and bench/growth/plot_growth.py."""
import os
import tempfile


def save(fig, path):
    """Saves the chart to a hidden temporary beside `path`, then renames it over `path`, so a
    failed or killed run leaves the old chart."""
    folder, name = os.path.split(path)
    fd, tmp = tempfile.mkstemp(dir=folder or ".", prefix=f".{name}.tmp-")
    try:
        with os.fdopen(fd, "wb") as f:
            fig.savefig(f, format="png", dpi=110)
            f.flush()
            os.fsync(f.fileno())
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise
