"""fb89 from Python: render the paper's hidden-surface methods, get the controller's image and
the face-id buffer as numpy arrays, read command streams, replay them under a controller.

    import fb89
    r = fb89.render("demo", method="zbuffer")
    r.image.shape, r.ids.shape, r.split

The module is a thin layer over the libraries the fb89 command line uses: every call reads
its arguments and does its work as the matching command does, and raises fb89.Error (or one
of its subclasses) with the command's message. docs/PYTHON.md is the tour.
"""
from ._fb89 import (  # noqa: F401
    COMMAND_DTYPE,
    EmulatorError,
    Error,
    FileError,
    OptionError,
    Render,
    SceneError,
    Stream,
    experiments,
    hosts,
    methods,
    profiles,
    render,
    replay,
    scenes,
)

__all__ = [
    "COMMAND_DTYPE", "EmulatorError", "Error", "FileError", "OptionError", "Render",
    "SceneError", "Stream", "experiments", "hosts", "methods", "profiles", "render", "replay",
    "scenes",
]

# Opcodes of COMMAND_DTYPE's "opcode" field (docs/PROTOCOL.md).
FRAME_BEGIN, FILL_RECT, DRAW_SPAN, MARKER, FRAME_END = 1, 2, 3, 4, 5
