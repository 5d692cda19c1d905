"""fb89 from Python: the paper's hidden-surface methods, a 1989 frame-buffer controller and its
command streams, with numpy arrays for images, face ids and commands, and tables for the
experiments.

    import fb89
    r = fb89.render("demo", method="zbuffer")
    r.image.shape, r.ids.shape, r.split
    fb89.experiment("fig3.1", ["A"], repeat=3).to_numpy()

The module is a thin layer over the libraries the fb89 command line uses: every call reads
its arguments and does its work as the matching command does, checks every keyword as the
command checks its option (the same limits, from the same code), and raises fb89.Error (or
one of its subclasses) with the command's message, naming the keyword; a value of the wrong
type is a TypeError naming it. A call that writes files writes them whole or not at all, as
the command does: on any failure every old file is left as it was. Long calls run without
the GIL, take a progress= callback, and stop on Ctrl-C. A keyword a call does not take is a
TypeError naming it, the call's keywords and the nearest one. The controller's cost profile
is profile=, as the commands' --profile (controller= is its old name, still taken).
docs/PYTHON.md is the tour.
"""
import difflib as _difflib
import functools as _functools
import inspect as _inspect
import json as _json
import os as _os
import tempfile as _tempfile
import weakref as _weakref

from . import _fb89
from ._fb89 import (  # noqa: F401
    COMMAND_DTYPE,
    EmulatorError,
    Error,
    FileError,
    OptionError,
    Radiosity,
    Render,
    SceneError,
    Stream,
    experiments,
    hosts,
    methods,
    profiles,
    scenes,
)
from ._table import Table

try:  # installed by cmake --install: the data and the 1989 hosts' parts are under the prefix
    from ._install import PREFIX_FROM_PACKAGE as _prefix
    _fb89._installed_at(_os.path.normpath(_os.path.join(_os.path.dirname(__file__), _prefix)))
except ImportError:  # the build tree's package: the source tree's data, the build's guests
    pass

__all__ = [
    "COMMAND_DTYPE", "Calibration", "Comparison", "Diff", "EmulatorError", "Error", "FileError",
    "OptionError", "Radiosity", "Render", "Replay", "Scene", "SceneError", "Stream", "Table",
    "Validation", "calibrate", "compare", "controller_validate", "diff", "experiment",
    "experiments", "host_validate", "hosts", "info", "load_scene", "methods", "model",
    "profiles", "radiosity", "render", "replay", "scenes", "sweep", "trim",
]

# Opcodes of COMMAND_DTYPE's "opcode" field by name (docs/PROTOCOL.md), from the commands'
# table: FRAME_BEGIN 1, FILL_RECT 2, DRAW_SPAN 3, MARKER 4, FRAME_END 5, and version 3's depth
# commands DEPTH_CLEAR 8, DEPTH_SPAN 9, FACE 10 (their depth in Stream.depth, a FACE's points
# in Stream.face_points). Each is also a name of this module: fb89.DRAW_SPAN.
OPCODES = dict(_fb89.OPCODES)
globals().update(OPCODES)

DEFAULT_PROFILE = "tms34010-50mhz"
DEFAULT_CONTROLLER = DEFAULT_PROFILE  # its old name


# ---- keywords as the commands take them ----

def _keywords(function):
    """Checks a call's keywords before it runs: one the function does not take is a TypeError
    naming it, the function's keywords, and the nearest of them ("did you mean")."""
    signature = _inspect.signature(function)
    known = [name for name, p in signature.parameters.items()
             if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)]

    @_functools.wraps(function)
    def checked(*args, **kwargs):
        for key in kwargs:
            if key not in known:
                raise TypeError(_unknown_keyword(function.__qualname__, key, known))
        return function(*args, **kwargs)
    return checked


def _unknown_keyword(where, key, known):
    near = _difflib.get_close_matches(key, known, n=1, cutoff=0.6)
    if key == "controller" and "profile" in known:
        near = ["profile"]
    hint = f"; did you mean '{near[0]}'?" if near else ""
    return (f"{where}() got an unknown keyword '{key}'{hint} "
            f"(its keywords: {', '.join(known)})")


def _profile(profile, controller):
    """profile=, the commands' --profile; controller= is its old name. Both is a TypeError."""
    if profile is not None and controller is not None:
        raise TypeError(f"profile={profile!r} and controller={controller!r} both name the "
                        "controller's cost profile (controller= is the old name of profile=): "
                        "give one")
    chosen = profile if profile is not None else controller
    return DEFAULT_PROFILE if chosen is None else chosen


# ---- arguments as the commands take them ----

def _scene_arg(scene, what="scene"):
    """A Scene, a bundled scene's name, a file, or a dict in the scene format -> a path."""
    if isinstance(scene, Scene):
        return scene.path
    if isinstance(scene, dict):
        return load_scene(scene).path
    if isinstance(scene, _os.PathLike):
        return _os.fspath(scene)
    if isinstance(scene, str):
        return scene
    raise TypeError(f"{what}: expected a scene name, a file, a dict or an fb89.Scene, "
                    f"got {type(scene).__name__} {scene!r:.40}")


def _scene_list(scenes_given):
    """None -> []; one scene or a list of them -> paths."""
    if scenes_given is None:
        return [], []
    if isinstance(scenes_given, (str, dict, Scene, _os.PathLike)):
        scenes_given = [scenes_given]
    loaded = [s if isinstance(s, Scene) else load_scene(s) if isinstance(s, dict) else s
              for s in scenes_given]
    return [_scene_arg(s) for s in loaded], loaded  # the loaded keep their files alive


def _path(p, what):
    if isinstance(p, Stream):
        if not p.path:
            raise OptionError(f"{what}: this stream was not read from a file: save() it first")
        return p.path
    if isinstance(p, (str, _os.PathLike)):
        return _os.fspath(p)
    raise TypeError(f"{what}: expected a path or an fb89.Stream, got {type(p).__name__} {p!r:.40}")


# ---- scenes ----

class Scene:
    """A scene fb89 has read: a bundled one by name, a file (.json, .tri), or a dict in the
    scene format (scenes/README.md, "The scene format") kept in a private file while the Scene lives.

    name, path: what `fb89 render` would call it and the file read
    width, height: the scene's own image size
    faces: the faces after loading (triangulated, degenerate ones dropped); notes says what
    loading changed
    """

    def __init__(self, info, owned_file=None):
        self.path = info["path"]
        self.name = info["name"]
        self.width = info["width"]
        self.height = info["height"]
        self.faces = info["faces"]
        self.face_ids = info["face_ids"]
        self.notes = list(info["notes"])
        if owned_file is not None:  # the file and the name it goes by go with the Scene
            self._finalizer = _weakref.finalize(self, _fb89._forget_scene_file, owned_file)

    def __repr__(self):
        return f"<fb89.Scene {self.name}: {self.faces} faces, {self.width}x{self.height}>"


@_keywords
def load_scene(scene, *, name="<dict scene>"):
    """Reads a scene: a bundled scene by name ("demo", "G"), a scene file (.json or .tri), or a
    dict in the scene format (so that a script can make scenes). Returns an fb89.Scene, which
    render(), experiment() and the rest take wherever they take a scene name. Raises
    fb89.SceneError naming the file and the field of anything wrong. A dict is kept in a
    private file while its Scene lives, and goes by `name` in errors, tables, stream headers
    and reprs."""
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, dict):
        if not isinstance(name, str) or not name:
            raise TypeError(f"name: expected a non-empty str, got {name!r}")
        fd, path = _tempfile.mkstemp(prefix="fb89_scene_", suffix=".json")
        try:
            with _os.fdopen(fd, "w") as f:
                _json.dump(scene, f)
            return Scene(_fb89._scene_info(path, name), owned_file=path)
        except BaseException:
            _fb89._forget_scene_file(path)
            raise
    return Scene(_fb89._scene_info(_scene_arg(scene), ""))


# ---- renders ----

@_keywords
def render(scene, *, method="zbuffer", size=None, host="native", profile=None, repeat=1,
           threshold=None, beam_threshold=None, reflections=None, buffer=None, controller=None):
    """Renders a scene with one method, as `fb89 render` does, and returns an fb89.Render:
    .image (H x W x 3 uint8, the controller's framebuffer), .ids (H x W int32 face ids, -1 for
    the background), .times, .counters, .controller_figures, .split, .pipeline, .period,
    .stream, and .timeline() (the frame through the pipeline as trace-event JSON).

    scene: a bundled scene's name ("demo", "G"), a file, a dict, or an fb89.Scene.
    method: zbuffer, scanline, warnock, hybrid, raytrace or beam (fb89.methods()).
    size: "WxH" or (W, H) (integers, 1 to 16384 each); None for the scene's own.
    host: "native" (timed here, in `repeat` interleaved rounds) or a 1989 host (fb89.hosts():
        the method's host code emulated once and priced; Ctrl-C stops it).
    profile: the controller's cost profile (fb89.profiles()), as --profile; controller= is its
        old name (giving both is a TypeError).
    repeat: frames rendered, 1 to 10000 (the hidden-surface time is their median).
    threshold, beam_threshold: the hybrids' thresholds: a number, "inf", "paper" or
        "calibrated" (the default: the one saved for this host by calibrate(save=True) or
        `fb89 calibrate`, else the paper's); refused for a method that does not read them.
    reflections: mirror bounces for raytrace, beam and mlrta, 0 to 16.
    buffer: the controller's command buffer for the pipeline in time, in bytes, or
        "unbounded" (render --buffer); None for the profile's.
    Raises fb89.SceneError, fb89.OptionError (naming the keyword), fb89.EmulatorError, and
    TypeError for a value of the wrong type."""
    keep = load_scene(scene) if isinstance(scene, dict) else scene
    return _fb89._render(_scene_arg(keep), method, size, host, _profile(profile, controller),
                         repeat, threshold, beam_threshold, reflections, buffer)


# ---- the experiments ----

@_keywords
def experiment(name, scenes=None, *, size=None, repeat=7, profile=None,
               threshold="calibrated", beam_threshold="calibrated", sizes=None,
               out_dir="out/masks", accel="bvh", patches=0, reference_rays=4, methods=None,
               host="native", jobs=1, results=None, progress=None, controller=None):
    """Re-runs one of the paper's experiments (fb89.experiments()), as `fb89 experiment NAME`
    does, and returns its fb89.Table (the CSV's columns and rows).

    scenes: scenes as render() takes them; None for the experiment's own.
    size: "WxH" or (W, H) for every scene; sizes: the fig4.* experiments' sizes.
    repeat: interleaved timing rounds (medians), 1 to 1000; one run each on a 1989 host.
    profile (or its old name controller): the controller's cost profile.
    threshold, beam_threshold: as render() takes them; out_dir: where fig4.7's masks go
        (written whole or not at all: a failed experiment leaves the old ones);
    accel: "bvh" or "grid" for the rays and the beams' queries; patches (0 to 100000),
        reference_rays (2 to 16): the radiosity experiments'.
    methods: split's methods by name (None: every one).
    host, jobs, results: a 1989 host, emulated runs at once (1 to 256), and a folder keeping
        each run.
    progress: None (a line on stderr when it is a terminal), True, False, or a callable
        progress(what, done, total, unit). Ctrl-C, or a callable that raises, stops the
        experiment between rounds (an emulated run within 50 ms) and is raised."""
    paths, _keep = _scene_list(scenes)
    parts = _fb89._experiment(
        name, paths, size=size, repeat=repeat, controller=_profile(profile, controller),
        threshold=threshold,
        beam_threshold=beam_threshold, sizes=sizes, out_dir=out_dir, accel=accel,
        patches=patches, reference_rays=reference_rays, methods=methods, host=host, jobs=jobs,
        results=results, progress=progress)
    return Table(**parts)


@_keywords
def sweep(what, scenes, *, start=0.001, stop=1.0, steps=13, window_test="area",
          depth_estimate="window", size=None, repeat=7, profile=None, host="native", jobs=1,
          results=None, progress=None, controller=None):
    """Sweeps the hybrid's Expr. 3.1 threshold (what="threshold"), as `fb89 sweep threshold`
    does: 0 (the pure Z-buffer), `steps` thresholds (1 to 200) from `start` to `stop` on a log
    scale, and inf (pure Warnock), on each scene. Returns an fb89.Table. window_test: "area"
    or "centres"; depth_estimate: "window" or "scene"; the rest as experiment() takes them."""
    if what != "threshold":
        raise OptionError(f"unknown sweep '{what}' (known: threshold)")
    paths, _keep = _scene_list(scenes)
    parts = _fb89._sweep(paths, start=start, stop=stop, steps=steps, window_test=window_test,
                         depth_estimate=depth_estimate, size=size, repeat=repeat,
                         controller=_profile(profile, controller), host=host, jobs=jobs,
                         results=results, progress=progress)
    return Table(**parts)


class Comparison:
    """What compare() found: table (an fb89.Table, the CSV `fb89 compare --csv` writes: one
    row a method), rows (the JSON --json writes), sheet (the contact sheet, H x W x 3 uint8),
    frames (each method's frame by name), thresholds (the line saying which thresholds ran)."""

    def __init__(self, parts):
        self.table = Table(columns=parts["columns"], rows=parts["rows"], text=parts["text"],
                           csv=parts["csv"])
        self.rows = list(parts["rows_json"])
        self.sheet = parts["sheet"]
        self.frames = dict(parts["frames"])
        self.thresholds = parts["thresholds"].strip()

    def __repr__(self):
        return f"<fb89.Comparison {len(self.rows)} methods: {', '.join(self.frames)}>"


@_keywords
def compare(scene, *, size=None, repeat=3, profile=None, threshold="calibrated",
            beam_threshold="calibrated", host="native", jobs=1, results=None, sheet=None,
            csv=None, json=None, progress=None, controller=None):
    """Every method on one scene, speed against accuracy, as `fb89 compare SCENE` does: each
    timed as the experiments time them (here, or on a 1989 host), its commands costed by the
    controller and its face ids counted against the Z-buffer's. Returns an fb89.Comparison.

    sheet, csv, json: files to write the contact sheet (PNG), the table (CSV) and the rows
    (JSON) to, as --sheet, --csv and --json do (None: not written; the command's default
    sheet is out/compare.png). They are written together or not at all: a failure in any
    leaves every old file as it was. The rest as experiment() takes them."""
    paths, _keep = _scene_list(scene)
    if len(paths) != 1:
        raise OptionError("scene: compare takes one scene")
    return Comparison(_fb89._compare(
        paths, size=size, repeat=repeat, controller=_profile(profile, controller),
        threshold=threshold, beam_threshold=beam_threshold, host=host, jobs=jobs,
        results=results, sheet=sheet,
        csv=csv, json=json, progress=progress))


class Calibration:
    """What calibrate() chose: chosen (the threshold), sweep (the timed sweep, an fb89.Table),
    total_ms and worst (per threshold: the scenes' total and the worst scene's ratio to the
    reference), reference_ms (the pure Z-buffer's or the ray tracer's total), choices and
    stable (each sweep's choice; whether the last two agreed), saved_to (the file, or None),
    warning (why a choice of 0 switches the hybrid off, or None), details (what is saved)."""

    def __init__(self, parts):
        self.chosen = parts["chosen"]
        self.sweep = Table(**parts["sweep"])
        self.total_ms = dict(parts["total_ms"])
        self.worst = dict(parts["worst"])
        self.reference_ms = parts["reference_ms"]
        self.choices = list(parts["choices"])
        self.stable = parts["stable"]
        self.saved_to = parts["saved_to"]
        self.warning = parts["warning"]
        self.details = parts["details"]

    def __repr__(self):
        return (f"<fb89.Calibration chosen {self.chosen:.6g}, "
                f"{'stable' if self.stable else 'not stable'}, "
                f"{'saved to ' + self.saved_to if self.saved_to else 'not saved'}>")


@_keywords
def calibrate(method="hybrid", scenes=None, *, start=0.0005, stop=2.0, steps=12, repeat=5,
              tolerance=0.03, host="native", jobs=1, results=None, save=False, progress=None):
    """The paper's calibration (§3), as `fb89 calibrate` does: the hybrid's Expr. 3.1 threshold
    (method="hybrid", on A-F by default; start, stop, steps: the ramp; tolerance: how much
    slower than the pure Z-buffer any scene may be, 0 to 100) or the beam-ray hybrid's Expr.
    2.7 threshold (method="beam", on G, H, I and cornell_mirror). Returns an fb89.Calibration.
    With save=True the choice is saved where threshold="calibrated" finds it (as the command
    does; it leaves the saved one alone by default). The rest as experiment() takes them."""
    paths, _keep = _scene_list(scenes)
    return Calibration(_fb89._calibrate(
        paths, method=method, start=start, stop=stop, steps=steps, repeat=repeat,
        tolerance=tolerance, host=host, jobs=jobs, results=results, save=save,
        progress=progress))


# ---- streams ----

class Replay:
    """What replay() gives: image (H x W x 3 uint8, the controller's framebuffer after the
    stream), checksum (the last frame's XXH64 as `fb89 replay` prints it: 16 hex digits), stats (the
    controller's figures per opcode and per frame) and, with buffer= or timeline=, pipelines:
    each complete frame through the pipeline in time (frame_ms, host_ms, host_stalled_ms,
    controller_idle_ms, buffer_high_water_bytes ...), else None."""

    def __init__(self, parts):
        self.image = parts["image"]
        self.checksum = _hex(parts["checksum"])
        self.stats = parts["stats"]
        self.pipelines = parts["pipelines"]

    def __repr__(self):
        return f"<fb89.Replay {self.image.shape[1]}x{self.image.shape[0]} {self.checksum}>"


def _hex(checksum):
    """A checksum as every command prints one: 16 hex digits."""
    return f"{checksum:016x}" if isinstance(checksum, int) else checksum


@_keywords
def replay(stream, *, profile=None, buffer=None, timeline=None, controller=None):
    """Replays a stream (an fb89.Stream or a stream file) into a controller with the given cost
    profile (profile=, as --profile; controller= is its old name), as `fb89 replay` does.
    Returns an fb89.Replay.

    buffer: as replay --buffer: each complete frame also through the pipeline in time with a
        command buffer of this many bytes, or "unbounded", from the stream's send times (a
        stream without them: every command ready at 0); in Replay.pipelines.
    timeline: as replay --timeline: a file to write the last complete frame through that
        pipeline to, as Chrome trace-event JSON (the profile's buffer unless buffer= says)."""
    if not isinstance(stream, Stream):
        stream = Stream.open(_path(stream, "stream"))
    profile = _profile(profile, controller)
    _fb89._check_profile(profile)
    return Replay(_fb89._replay(stream, profile, buffer, timeline))


@_keywords
def trim(stream, output, *, calls=None, frames=None, salvage=False):
    """Copies the commands in `calls` (a call set, e.g. "0-1000", "/span") and/or the frames in
    `frames` (e.g. "0-3,7") of a stream file into `output`, a stream that still replays, as
    `fb89 trim` does. Returns {'path', 'commands', 'frames', 'salvaged'} (salvaged: the
    error a damaged input ended with, kept up to it with salvage=True, else None). Raises
    fb89.OptionError when nothing matches and fb89.FileError for a damaged input or a file
    that cannot be read or written; then `output` is left as it was."""
    if calls is None and frames is None:
        raise OptionError("trim: give calls= and/or frames= to say what to keep")
    return _fb89._trim(_path(stream, "stream"), _path(output, "output"), calls, frames, salvage)


class Diff:
    """What diff() found: frames (one dict a frame: frame, size_a, size_b (None where only the
    other stream has it), differing and compared pixels), differing_frames, identical, and
    image_frame (the frame whose diff image was written, or None)."""

    def __init__(self, parts):
        self.frames = list(parts["frames"])
        self.differing_frames = parts["differing_frames"]
        self.image_frame = parts["image_frame"]
        self.identical = self.differing_frames == 0

    def __repr__(self):
        return (f"<fb89.Diff {len(self.frames)} frames, "
                f"{'identical' if self.identical else f'{self.differing_frames} differ'}>")


@_keywords
def diff(a, b, *, image=None):
    """Compares the frames two stream files produce, pixel by pixel, as `fb89 diff` does;
    with `image`, writes the first differing frame's diff image (differing pixels red over A
    dimmed). Returns an fb89.Diff. Raises fb89.FileError for a damaged or missing stream
    (the image is not written then)."""
    return Diff(_fb89._diff(_path(a, "a"), _path(b, "b"), image))


# ---- radiosity, the model, the validations, info ----

@_keywords
def radiosity(scene, *, ff="hybrid", patches=None, epsilon=None, link_rays=None, min_area=None,
              shaft_culling=False, max_links=None, hemicube_res=None, solver=None,
              tolerance=None, max_iterations=None, adaptive=None, adaptive_passes=None,
              exposure=None, size=None, profile=None, png=None, ids=None, ids_view=None,
              stream=None, stats=None, progress=None, controller=None):
    """The paper's §5 end to end, as `fb89 radiosity SCENE` does: the scene's faces cut into
    patches, intervisibility, form factors, the solution, and the patches drawn through the
    Z-buffer and the controller. Returns an fb89.Radiosity: .image (H x W x 3 uint8), .ids
    (H x W int32 patch ids, -1 for the background), .counts (patches, iterations, residual,
    the hierarchy's counts, the counted operations), .times, .stats (all --stats writes),
    .summary (what the command prints), .notes, .stream.

    ff: flux, hybrid, disk, exact, hemicube or hierarchical (the command's --ff).
    The hierarchy's (ff="hierarchical" only): epsilon, link_rays, min_area, shaft_culling,
        max_links. hemicube_res: ff="hemicube" only. solver ("gauss-seidel" or
        "progressive"), adaptive and adaptive_passes: not with ff="hierarchical".
    patches, tolerance, max_iterations, exposure, size: as the command's options; None (the
        default) is the command's default. An option the chosen ff does not read is refused,
        as the command refuses it; every number is held to the option's range.
    profile (or its old name controller): the controller's cost profile.
    png, ids, ids_view, stream, stats: files to write as --png ... --stats do, together or not
        at all."""
    keep = load_scene(scene) if isinstance(scene, dict) else scene
    return _fb89._radiosity(
        _scene_arg(keep), ff=ff, patches=patches, epsilon=epsilon, link_rays=link_rays,
        min_area=min_area, shaft_culling=shaft_culling, max_links=max_links,
        hemicube_res=hemicube_res, solver=solver, tolerance=tolerance,
        max_iterations=max_iterations, adaptive=adaptive, adaptive_passes=adaptive_passes,
        exposure=exposure, size=size, profile=_profile(profile, controller), png=png, ids=ids,
        ids_view=ids_view, stream=stream, stats=stats, progress=progress)


@_keywords
def model(*, es=None, fv=None, d=1, fw=None, ew=None, faces=None):
    """Tabulates the paper's analytic model, as `fb89 model` does: with es and fv, the window
    samples of the ideal scene (Eqs. 2.1-2.4); with fw and ew (and faces for Expr. 2.7), the
    cost per pixel of the cheapest window derived from a window (Exprs. 2.5-2.7, 3.1); d is
    the depth complexity. Each takes a number, a list of numbers, or the command's text
    ("16,32,64", "16..1024*2", "1..10+0.5"). Returns an fb89.Table (the CSV --csv writes;
    str() the table the command prints), or a tuple of two (samples, window costs) when both
    are asked."""
    tables = [Table(columns=t["columns"], rows=t["rows"], text=t["text"], csv=t["csv"])
              for t in _fb89._model(es=es, fv=fv, d=d, fw=fw, ew=ew, faces=faces)]
    return tables[0] if len(tables) == 1 else tuple(tables)


class Validation(Table):
    """What host_validate() and controller_validate() found: an fb89.Table of the checks, the
    CSV the command's --csv writes (one row a check; str() is the text the command prints),
    with all_pass (whether every check passed: the command's --check exits 1 when not),
    listing (controller_validate(listing=True): the command loop with each instruction's
    cycles, else None), text (what the command prints) and table (itself)."""

    def __init__(self, parts):
        import csv as _csv
        lines = list(_csv.reader(parts["csv"].splitlines()))
        super().__init__(columns=lines[0], rows=lines[1:], text=parts["text"], csv=parts["csv"])
        self.text = parts["text"]
        self.all_pass = parts["all_pass"]
        self.listing = parts["listing"] or None

    @property
    def table(self):
        return self

    def __repr__(self):
        return (f"<fb89.Validation {len(self.rows)} checks, "
                f"{'all pass' if self.all_pass else 'some missed'}: {', '.join(self.columns)}>")


@_keywords
def host_validate(*, profile=None, classes=None, progress=None):
    """The modelled 1989 hosts against published figures of the period, as `fb89
    host-validate` does: each validation kernel run on the emulated instruction sets, priced
    by each host profile (profile: one name or file, a list of them, or None for every one a
    figure names). classes: also the N instruction classes that take most of each kernel's
    modelled time (in .text). Returns an fb89.Validation."""
    profiles = [profile] if isinstance(profile, (str, _os.PathLike)) else profile
    if profiles is not None:
        profiles = [_os.fspath(p) if isinstance(p, _os.PathLike) else p for p in profiles]
    return Validation(_fb89._host_validate(profiles=profiles, classes=classes,
                                           progress=progress))


@_keywords
def controller_validate(*, profile=None, listing=False, controller=None):
    """The controller's cost model beside TI's data sheet, as `fb89 controller-validate` does
    (profile: one with a command-loop listing). listing=True also gives the command loop with
    each instruction's cycles. Returns an fb89.Validation."""
    return Validation(_fb89._controller_validate(profile=_profile(profile, controller),
                                                 listing=listing))


@_keywords
def info(stream, *, profile=None, controller=None):
    """What a stream holds, as `fb89 info --json` reports it, as a dict: the header (version,
    properties), whether it ends in a frame index, the commands by opcode, and per frame
    ("frames") the commands by opcode, pixels, bus bytes (modelled under `profile`), file bytes
    and checksum (16 hex digits, as the command prints it); a timed stream's send times. A
    truncated or corrupt stream gives its complete frames and an "error" (message, offset,
    command)."""
    return _fb89._info(_path(stream, "stream"), _profile(profile, controller))


def _checked_method(method, where):
    """A compiled method with its keywords checked as _keywords checks a function's."""
    @_functools.wraps(method)
    def checked(*args, **kwargs):
        try:
            return method(*args, **kwargs)
        except TypeError as e:
            if "incompatible function arguments" not in str(e) or not kwargs:
                raise
            names = _pybind_keywords(method)
            for key in kwargs:
                if names and key not in names:
                    raise TypeError(_unknown_keyword(where, key, names)) from None
            raise
    return checked


def _pybind_keywords(method):
    """The keyword names of a pybind11 function, from its docstring's signature."""
    import re as _re
    first = (method.__doc__ or "").splitlines()[0] if method.__doc__ else ""
    return [n for n in _re.findall(r"(\w+): ", first.split("->")[0]) if n != "self"]


Stream.open = staticmethod(_checked_method(Stream.open, "Stream.open"))
Stream.save = _checked_method(Stream.save, "Stream.save")
Render.save_timeline = _checked_method(Render.save_timeline, "Render.save_timeline")
