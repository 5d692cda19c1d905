# Type stubs for the fb89 module (its compiled part is fb89._fb89).
import os
from typing import Any, Callable, Iterator, Sequence

import numpy as np
import numpy.typing as npt

COMMAND_DTYPE: np.dtype
FRAME_BEGIN: int
FILL_RECT: int
DRAW_SPAN: int
MARKER: int
FRAME_END: int
DEFAULT_PROFILE: str
DEFAULT_CONTROLLER: str

class Error(Exception): ...
class SceneError(Error, ValueError): ...
class OptionError(Error, ValueError): ...
class FileError(Error, OSError): ...
class EmulatorError(Error, RuntimeError): ...

Progress = None | bool | Callable[[str, int, int, str], object]
Size = None | str | tuple[int, int]
Threshold = None | str | float
Buffer = None | int | str  # bytes, or "unbounded"
PathLike = str | os.PathLike[str]

class Scene:
    path: str
    name: str
    width: int
    height: int
    faces: int
    face_ids: int
    notes: list[str]

SceneLike = str | os.PathLike[str] | dict[str, Any] | Scene

class Stream:
    path: str
    version: int
    header: dict[str, str]
    def __init__(self, commands: npt.NDArray[np.void], header: dict[str, str] | None = ...,
                 markers: Sequence[tuple[int, str]] | None = ...) -> None: ...
    @staticmethod
    def open(path: PathLike, calls: str | None = ...) -> Stream: ...
    @property
    def commands(self) -> npt.NDArray[np.void]: ...
    @property
    def numbers(self) -> npt.NDArray[np.uint64] | None: ...
    @property
    def markers(self) -> list[tuple[int, str]]: ...
    @property
    def frames(self) -> int: ...
    def __len__(self) -> int: ...
    @property
    def send_times(self) -> npt.NDArray[np.int64] | None: ...
    @property
    def host_ends(self) -> list[tuple[int, int]]: ...
    def save(self, path: PathLike) -> None: ...

class Render:
    scene: str
    method: str
    host: str
    profile: str
    controller: str
    stream: Stream
    @property
    def image(self) -> npt.NDArray[np.uint8]: ...
    @property
    def ids(self) -> npt.NDArray[np.int32]: ...
    @property
    def times(self) -> dict[str, Any]: ...
    @property
    def counters(self) -> dict[str, int]: ...
    @property
    def controller_figures(self) -> dict[str, Any]: ...
    @property
    def split(self) -> dict[str, Any]: ...
    @property
    def period(self) -> dict[str, Any] | None: ...
    @property
    def pipeline(self) -> dict[str, Any] | None: ...
    @property
    def commands(self) -> npt.NDArray[np.void]: ...
    def timeline(self) -> dict[str, Any]: ...
    def save_timeline(self, path: PathLike) -> None: ...

class Table:
    columns: list[str]
    rows: list[tuple[str, ...]]
    def __init__(self, columns: Sequence[str], rows: Sequence[Sequence[str]], text: str = ...,
                 csv: str = ...) -> None: ...
    def __len__(self) -> int: ...
    def __iter__(self) -> Iterator[dict[str, Any]]: ...
    def __getitem__(self, column: str) -> npt.NDArray[Any]: ...
    def to_numpy(self) -> npt.NDArray[np.void]: ...
    def to_pandas(self) -> Any: ...
    def csv(self) -> str: ...

class Calibration:
    chosen: float
    sweep: Table
    total_ms: dict[float, float]
    worst: dict[float, float]
    reference_ms: float
    choices: list[float]
    stable: bool
    saved_to: str | None
    warning: str | None
    details: dict[str, Any]

class Comparison:
    table: Table
    rows: list[dict[str, Any]]
    sheet: npt.NDArray[np.uint8]
    frames: dict[str, npt.NDArray[np.uint8]]
    thresholds: str

class Replay:
    image: npt.NDArray[np.uint8]
    checksum: str  # 16 hex digits, as fb89 replay prints it
    stats: dict[str, Any]
    pipelines: list[dict[str, Any]] | None

class Radiosity:
    scene: str
    ff: str
    profile: str
    summary: str
    controller_summary: str
    notes: list[str]
    stream: Stream
    @property
    def image(self) -> npt.NDArray[np.uint8]: ...
    @property
    def ids(self) -> npt.NDArray[np.int32]: ...
    @property
    def stats(self) -> dict[str, Any]: ...
    @property
    def counts(self) -> dict[str, Any]: ...
    @property
    def times(self) -> dict[str, Any]: ...
    @property
    def controller_figures(self) -> dict[str, Any]: ...

class Validation(Table):
    text: str
    all_pass: bool
    listing: str | None
    @property
    def table(self) -> Table: ...

class Diff:
    frames: list[dict[str, Any]]
    differing_frames: int
    image_frame: int | None
    identical: bool

def scenes() -> list[str]: ...
def methods() -> list[str]: ...
def hosts() -> list[str]: ...
def profiles() -> list[str]: ...
def experiments() -> list[str]: ...
def load_scene(scene: SceneLike, *, name: str = ...) -> Scene: ...
def render(scene: SceneLike, *, method: str = ..., size: Size = ..., host: str = ...,
           profile: str | None = ..., repeat: int = ..., threshold: Threshold = ...,
           beam_threshold: Threshold = ..., reflections: int | None = ...,
           buffer: Buffer = ..., controller: str | None = ...) -> Render: ...
def experiment(name: str, scenes: SceneLike | Sequence[SceneLike] | None = ..., *,
               size: Size = ..., repeat: int = ..., profile: str | None = ...,
               threshold: Threshold = ..., beam_threshold: Threshold = ...,
               sizes: Sequence[Size] | None = ..., out_dir: str | os.PathLike[str] = ...,
               accel: str = ..., patches: int = ..., reference_rays: int = ...,
               methods: Sequence[str] | None = ...,
               host: str = ..., jobs: int = ..., results: str | os.PathLike[str] | None = ...,
               progress: Progress = ..., controller: str | None = ...) -> Table: ...
def sweep(what: str, scenes: SceneLike | Sequence[SceneLike], *, start: float = ...,
          stop: float = ..., steps: int = ..., window_test: str = ...,
          depth_estimate: str = ..., size: Size = ..., repeat: int = ...,
          profile: str | None = ..., host: str = ..., jobs: int = ...,
          results: str | os.PathLike[str] | None = ..., progress: Progress = ...,
          controller: str | None = ...) -> Table: ...
def compare(scene: SceneLike, *, size: Size = ..., repeat: int = ..., profile: str | None = ...,
            threshold: Threshold = ..., beam_threshold: Threshold = ..., host: str = ...,
            jobs: int = ..., results: PathLike | None = ..., sheet: PathLike | None = ...,
            csv: PathLike | None = ..., json: PathLike | None = ...,
            progress: Progress = ..., controller: str | None = ...) -> Comparison: ...
def calibrate(method: str = ..., scenes: SceneLike | Sequence[SceneLike] | None = ..., *,
              start: float = ..., stop: float = ..., steps: int = ..., repeat: int = ...,
              tolerance: float = ..., host: str = ..., jobs: int = ...,
              results: str | os.PathLike[str] | None = ..., save: bool = ...,
              progress: Progress = ...) -> Calibration: ...
def replay(stream: Stream | str | os.PathLike[str], *, profile: str | None = ...,
           buffer: Buffer = ..., timeline: PathLike | None = ...,
           controller: str | None = ...) -> Replay: ...
def trim(stream: Stream | str | os.PathLike[str], output: str | os.PathLike[str], *,
         calls: str | None = ..., frames: str | None = ..., salvage: bool = ...) -> dict[str, Any]: ...
def diff(a: Stream | str | os.PathLike[str], b: Stream | str | os.PathLike[str], *,
         image: str | os.PathLike[str] | None = ...) -> Diff: ...
def radiosity(scene: SceneLike, *, ff: str = ..., patches: int | None = ...,
              epsilon: float | None = ..., link_rays: int | None = ...,
              min_area: float | None = ..., shaft_culling: bool = ...,
              max_links: int | None = ..., hemicube_res: int | None = ...,
              solver: str | None = ..., tolerance: float | None = ...,
              max_iterations: int | None = ..., adaptive: float | None = ...,
              adaptive_passes: int | None = ..., exposure: float | None = ..., size: Size = ...,
              profile: str | None = ..., png: PathLike | None = ..., ids: PathLike | None = ...,
              ids_view: PathLike | None = ..., stream: PathLike | None = ...,
              stats: PathLike | None = ..., progress: Progress = ...,
              controller: str | None = ...) -> Radiosity: ...
ModelValues = None | float | str | Sequence[float | str]
def model(*, es: ModelValues = ..., fv: ModelValues = ..., d: ModelValues = ...,
          fw: ModelValues = ..., ew: ModelValues = ...,
          faces: ModelValues = ...) -> Table | tuple[Table, Table]: ...
def host_validate(*, profile: PathLike | Sequence[PathLike] | None = ...,
                  classes: int | None = ..., progress: Progress = ...) -> Validation: ...
def controller_validate(*, profile: str | None = ..., listing: bool = ...,
                        controller: str | None = ...) -> Validation: ...
def info(stream: Stream | str | os.PathLike[str], *, profile: str | None = ...,
         controller: str | None = ...) -> dict[str, Any]: ...
