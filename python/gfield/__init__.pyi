# Typed stubs of the package gfield (the extension gfield._gfield and print_progress). Array
# shapes in the docstrings: R rays, V vertices, F triangles, n texels per side, N samples per side,
# K layers, S = 6 N^2 samples. docs/python.md.
import os
from typing import Callable, Literal, TypedDict

import numpy as np
import numpy.typing as npt

__version__: str

_Path = str | os.PathLike[str]
_Progress = Callable[[str, float], object] | None
_Floats = npt.ArrayLike

class Error(Exception):
    """Bad input or a failed command, with the CLI's one-line message."""

class GfieldWarning(UserWarning):
    """What gfield went on past (a missing texture, ...)."""

class Hits(TypedDict):
    """GeometryField.lookup's answer for R rays."""

    hit: npt.NDArray[np.bool_]  # (R,)
    t: npt.NDArray[np.float32]  # (R,), along the unnormalised direction
    distance: npt.NDArray[np.float32]  # (R,), t * |direction|
    position: npt.NDArray[np.float32]  # (R, 3), mesh coordinates
    normal: npt.NDArray[np.float32]  # (R, 3), unit
    uv: npt.NDArray[np.float32]  # (R, 2), geometry-image uv; (-1, -1) for a miss

class ExactHits(TypedDict):
    """Mesh.intersect's answer for R rays."""

    hit: npt.NDArray[np.bool_]  # (R,)
    t: npt.NDArray[np.float32]  # (R,)
    position: npt.NDArray[np.float32]  # (R, 3)
    normal: npt.NDArray[np.float32]  # (R, 3), unit geometric normal
    triangle: npt.NDArray[np.int32]  # (R,), -1 for a miss
    barycentric: npt.NDArray[np.float32]  # (R, 2), Embree's u, v

class Comparison(TypedDict):
    """compare's answer (gfield compare --json)."""

    pixels: int
    psnr_db: float  # inf for equal pictures
    ssim: float
    mse: float
    max_abs_error: float
    mean_abs_error: float

class Mesh:
    """A triangle mesh as its file stores it (load_mesh)."""

    @property
    def vertices(self) -> npt.NDArray[np.float64]:
        """(V, 3) vertex positions."""
    @property
    def faces(self) -> npt.NDArray[np.int32]:
        """(F, 3) vertex indices per triangle."""
    @property
    def uvs(self) -> npt.NDArray[np.float32] | None:
        """(F, 3, 2) corner texture coordinates, or None."""
    @property
    def colors(self) -> npt.NDArray[np.float32] | None:
        """(V, 3) linear RGB vertex colours, or None."""
    @property
    def warnings(self) -> list[str]: ...
    def intersect(
        self, origins: _Floats, directions: _Floats, t_min: float | _Floats = 0.0
    ) -> ExactHits:
        """Exact first hits (Embree) of R rays: origins, directions (R, 3); t_min scalar or (R,)."""

class GeometryImage:
    """A geometry image (NAME.gimage.exr): texel (i, j) is [j, i] of the arrays."""

    @staticmethod
    def load(path: _Path) -> GeometryImage: ...
    @property
    def size(self) -> int:
        """n, texels per side."""
    @property
    def box(self) -> npt.NDArray[np.float32]:
        """(2, 3): min and max corners."""
    @property
    def source(self) -> str: ...
    @property
    def build_id(self) -> str: ...
    @property
    def ray_offset(self) -> float: ...
    @property
    def positions(self) -> npt.NDArray[np.float32]:
        """(n, n, 3) surface positions."""
    @property
    def normals(self) -> npt.NDArray[np.float32]:
        """(n, n, 3) unit normals."""
    @property
    def coverage(self) -> npt.NDArray[np.float32]:
        """(n, n): 1 on the surface, 0 in padding."""
    @property
    def albedo(self) -> npt.NDArray[np.float32] | None:
        """(n, n, 3) linear RGB base colour, or None."""

class GeometryField:
    """A geometry field (NAME.gfield.exr) with the geometry image it indexes."""

    @staticmethod
    def load(
        path: _Path, image: GeometryImage | _Path | None = None, *, mesh: _Path | None = None
    ) -> GeometryField: ...
    @property
    def samples_per_side(self) -> int:
        """N."""
    @property
    def layers(self) -> int:
        """K, the hits a lookup reads per line (format 3: the most a line holds, at most 8)."""
    @property
    def box(self) -> npt.NDArray[np.float32]:
        """(2, 3): min and max corners."""
    @property
    def source(self) -> str: ...
    @property
    def build_id(self) -> str: ...
    @property
    def image(self) -> GeometryImage | None: ...
    @property
    def nearest(self) -> npt.NDArray[np.float32]:
        """(S, 5 N^2, 2): nearest[entry sample, column] = uv of the hit nearest the entry; -1 miss."""
    def line_hits(self, entry: int, exit: int) -> npt.NDArray[np.float32]:
        """(k, 2): every hit of the line from sample entry towards sample exit, in order."""
    def table(self, layers: int = 4) -> npt.NDArray[np.float32]:
        """(K, S, S, 2), computed: table[layer, entry, exit] = uv; -1 fewer hits, -2 no ray."""
    def lookup(
        self,
        origins: _Floats,
        directions: _Floats,
        t_min: float | _Floats = 0.0,
        mode: Literal["nearest", "linear", "refined"] = "refined",
    ) -> Hits:
        """First hits beyond t_min of R rays: origins, directions (R, 3); t_min scalar or (R,)."""

def load_mesh(path: _Path, *, mesh: str = "", allow_outside_paths: bool = False) -> Mesh: ...
def info(path: _Path, *, mesh: str = "", allow_outside_paths: bool = False) -> dict[str, object]:
    """The dict of `gfield info --json`."""

def build(
    mesh_path: _Path,
    out: _Path,
    *,
    mesh: str = "",
    size: int | Literal["auto"] = "auto",
    max_image_error: float = 0.005,
    proxy_above: int = 200000,
    samples: int = 24,
    format: Literal[3, 2] = 3,
    layers: int | Literal["auto"] = "auto",
    precision: Literal["half", "float"] = "half",
    verify_rays: int = 10000,
    method: Literal["auto", "orbifold", "square"] = "auto",
    components: Literal["all", "largest"] = "all",
    allow_outside_paths: bool = False,
    threads: int = 0,
    progress: _Progress = None,
) -> dict[str, object]:
    """gfield build MESH -o OUT; returns the report (NAME.report.json)."""

def render(
    scene_path: _Path,
    size: tuple[int, int] | None = None,
    spp: int = 8,
    depth: int = 10,
    *,
    dielectric: Literal["full", "refract-only", "tir-only"] = "full",
    seed: int = 1,
    strata_centres: bool = False,
    camera: str | None = None,
    allow_outside_paths: bool = False,
    progress: _Progress = None,
) -> npt.NDArray[np.float32]:
    """The reference tracer's (h, w, 3) linear RGB picture of a scene."""

def compare(
    a: _Floats | _Path, b: _Floats | _Path, *, mask: _Floats | _Path | None = None
) -> Comparison:
    """PSNR and SSIM of two (h, w, 3) pictures or image files."""

def load_scene(path: _Path, *, allow_outside_paths: bool = False) -> dict[str, object]:
    """A scene file as a dict."""

def print_progress(stage: str, done: float) -> None:
    """A progress callback printing a bar per stage on stderr."""
