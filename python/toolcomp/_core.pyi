"""Type stub of toolcomp._core (the compiled core). Users import these names from toolcomp."""
from __future__ import annotations

import enum
import os
from typing import Any, Callable, Dict, Iterator, List, Mapping, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str
RAPID: int
LINE: int
ARC_CW: int
ARC_CCW: int

_PathLike = Union[str, os.PathLike]
_Vec3 = Union[Sequence[float], npt.NDArray[np.float64]]

class Diagnostic:
    """A message from the engine: stable code, severity ('info', 'warning', 'error'), text and
    1-based line and column (0 = unknown)."""
    def __init__(self, code: str, severity: str, message: str, line: int = 0, column: int = 0) -> None: ...
    @property
    def code(self) -> str: ...
    @property
    def severity(self) -> str: ...  # "error" | "warning" | "info"
    @property
    def message(self) -> str: ...
    @property
    def line(self) -> int: ...
    @property
    def column(self) -> int: ...
    @property
    def file(self) -> str: ...  # the called file the line is in; "" = the main program

class CuttingEdge:
    """One cutting edge (D number) of a tool. Lengths in mm, angles in degrees."""
    def __init__(self, *, number: int = 1, length: _Vec3 = ..., radius: float = 0.0,
                 corner_radius: float = 0.0, rotary: _Vec3 = ..., uvw: _Vec3 = ...,
                 length_wear: _Vec3 = ..., radius_wear: float = 0.0, corner_radius_wear: float = 0.0,
                 orientation: int = 0, front_angle: float = 0.0, back_angle: float = 0.0) -> None: ...
    number: int
    length: npt.NDArray[np.float64]
    rotary: npt.NDArray[np.float64]
    uvw: npt.NDArray[np.float64]
    length_wear: npt.NDArray[np.float64]
    radius: float
    corner_radius: float
    radius_wear: float
    corner_radius_wear: float
    orientation: int
    front_angle: float
    back_angle: float
    @property
    def effective_length(self) -> npt.NDArray[np.float64]: ...
    @property
    def effective_radius(self) -> float: ...
    @property
    def effective_corner_radius(self) -> float: ...
    @property
    def shape(self) -> str: ...  # "end_mill" | "toroid" | "ball"

class Tool:
    """A tool with one or more cutting edges (values, not references into a table)."""
    def __init__(self, number: int, *, pocket: int = 0, name: str = "", comment: str = "",
                 edges: Optional[Sequence[CuttingEdge]] = None) -> None: ...
    number: int
    pocket: int
    name: str
    comment: str
    @property
    def edges(self) -> Tuple[CuttingEdge, ...]: ...
    def edge(self, d: int = 1) -> CuttingEdge: ...
    def has_edge(self, d: int) -> bool: ...
    def set_edge(self, edge: CuttingEdge) -> None: ...

class ToolTable:
    """Tool table (LinuxCNC .tbl, CSV, JSON, Heidenhain TOOL.T); tools stored in mm and degrees."""
    def __init__(self, units: str = "mm") -> None: ...
    @staticmethod
    def read(path: _PathLike, format: Optional[str] = None, units: str = "mm", *,
             max_bytes: int = 268435456) -> ToolTable: ...
    @staticmethod
    def parse(text: str, format: str, units: str = "mm") -> ToolTable: ...
    def write(self, path: _PathLike, format: Optional[str] = None) -> None: ...
    def dumps(self, format: Optional[str] = None) -> str: ...
    units: str
    @property
    def format(self) -> Optional[str]: ...
    @property
    def tools(self) -> Tuple[Tool, ...]: ...
    @property
    def numbers(self) -> Tuple[int, ...]: ...
    def get(self, number: int) -> Optional[Tool]: ...
    def set(self, tool: Tool) -> None: ...
    def remove(self, number: int) -> bool: ...
    def __getitem__(self, number: int) -> Tool: ...
    def __contains__(self, number: int) -> bool: ...
    def __len__(self) -> int: ...
    def __iter__(self) -> Iterator[Tool]: ...
    # added by toolcomp/__init__.py (toolcomp.table_frames; pandas imported on use)
    def to_pandas(self) -> Any: ...
    @staticmethod
    def from_pandas(df: Any, base: Optional[ToolTable] = None, units: str = "mm") -> ToolTable: ...
    def diff(self, other: ToolTable, tol: float = 0.0) -> List[Any]: ...

class Program:
    """A parsed part program (blocks of words) in one dialect; create it with Program.read or Program.parse."""
    @staticmethod
    def read(path: _PathLike, dialect: Optional[str] = None, strict: bool = True, *,
             max_bytes: int = 2147483648, max_line_length: int = 1048576) -> Program: ...
    @staticmethod
    def check_file(path: _PathLike, dialect: Optional[str] = None, *, max_line_length: int = 1048576) -> int: ...
    @staticmethod
    def parse(text: str, dialect: str = "linuxcnc", name: str = "<string>", strict: bool = True, *,
              max_line_length: int = 1048576) -> Program: ...
    @property
    def syntax_error(self) -> Optional[Diagnostic]: ...
    @property
    def name(self) -> str: ...
    @property
    def dialect(self) -> str: ...
    @property
    def word_count(self) -> int: ...
    def __len__(self) -> int: ...

class Path:
    """N segments as read-only numpy views (millimetres, degrees, program coordinates)."""
    def __len__(self) -> int: ...
    @property
    def kind(self) -> npt.NDArray[np.uint8]: ...
    @property
    def start(self) -> npt.NDArray[np.float64]: ...
    @property
    def end(self) -> npt.NDArray[np.float64]: ...
    @property
    def center(self) -> npt.NDArray[np.float64]: ...
    @property
    def nbytes(self) -> int: ...
    @property
    def abc(self) -> npt.NDArray[np.float64]: ...
    @property
    def line(self) -> npt.NDArray[np.int32]: ...
    @property
    def tool(self) -> npt.NDArray[np.int32]: ...
    @property
    def feed(self) -> npt.NDArray[np.float64]: ...
    @property
    def side(self) -> npt.NDArray[np.int8]: ...
    @property
    def generated(self) -> npt.NDArray[np.bool_]: ...
    @property
    def tool_offset(self) -> npt.NDArray[np.float64]: ...
    @property
    def plane(self) -> npt.NDArray[np.uint8]: ...
    @property
    def turns(self) -> npt.NDArray[np.int32]: ...
    @property
    def normal(self) -> npt.NDArray[np.float64]: ...
    @property
    def tool_axis(self) -> npt.NDArray[np.float64]: ...
    @property
    def file(self) -> npt.NDArray[np.int32]: ...
    @property
    def files(self) -> list[str]: ...
    def contact_points(self, r: float, r2: float) -> npt.NDArray[np.float64]: ...
    def sample(self, tolerance: float = 0.01) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
    def length(self, include_rapids: bool = True) -> float: ...
    @property
    def work_offset(self) -> npt.NDArray[np.float64]: ...
    @property
    def work_rotation(self) -> npt.NDArray[np.float64]: ...
    @property
    def machine_end(self) -> npt.NDArray[np.float64]: ...
    @property
    def duration(self) -> npt.NDArray[np.float64]: ...
    @property
    def tool_changes(self) -> int: ...

class LengthAxes(enum.Enum):
    """Which axes a tool length offset (G43 H) acts on."""
    all = 0
    z_only = 1
    plane_normal = 2

class EntryStyle(enum.Enum):
    """How a control finishes the activation block of radius compensation."""
    perpendicular_to_entry = 0
    perpendicular_to_next = 1
    around_start_when_behind = 2

class ExitStyle(enum.Enum):
    """How the compensated path leaves the contour when compensation is cancelled."""
    perpendicular_to_last = 0
    corner_with_exit = 1
    around_end_when_behind = 2

class OutsideCorner(enum.Enum):
    """What fills the gap at an outside corner of the compensated path."""
    arc = 0
    intersection = 1
    extension = 2

class GougeReaction(enum.Enum):
    """What the control does when the compensated tool cannot reach part of the contour."""
    error = 0
    skip = 1
    report = 2

class NonPlaneReaction(enum.Enum):
    """What happens when too many blocks without motion in the plane follow each other while compensating."""
    error = 0
    overcut = 1

class TipConvention(enum.Enum):
    """Numbering of lathe tool tip directions (orientation 0..9)."""
    linuxcnc = 0
    fanuc = 1

class MachineKind(enum.Enum):
    """The kind of machine of a ControlProfile: mill or lathe."""
    mill = 0
    lathe = 1

class RadiusRules:
    """How a control applies cutter radius compensation."""
    yz_plane: bool
    entry: EntryStyle
    entry_arc: bool
    exit: ExitStyle
    tip_convention: TipConvention
    extension_min_length: float
    ct_radius_on_contour: bool
    lct_tangency_tool_space: bool
    exit_direction_words: bool
    offset_change_reenters: bool
    exit_must_be_straight: bool
    entry_length_check: bool
    outside_corner: OutsideCorner
    corner_limit: float
    disc: float
    side_change: bool
    corner_tolerance: float
    arc_sweep_tolerance: Tuple[float, float]
    count_blocks_without_motion: bool
    max_non_plane_moves: int
    non_plane_reaction: NonPlaneReaction
    lookahead: int
    gouge: GougeReaction
    overcut_neighbours: int
    overcut_tolerance: float

class ControlProfile:
    """How a particular control behaves, as plain data; adjust fields and pass as run(..., profile=...)."""
    def __init__(self, dialect: str = "linuxcnc", kind: Optional[str] = None, machine: Optional[str] = None) -> None: ...
    @property
    def kind(self) -> MachineKind: ...
    @property
    def machine(self) -> MachineKind: ...
    x_diameter: bool
    incremental_uw: bool
    t_offsets: bool
    g_code_system_a: bool
    modal_offset_numbers: bool
    t_format: int
    wear_sign: float
    tool_length_const: int
    tool_length_type: int
    tool_parameter_def_mask: int
    name: str
    startup_inch: bool
    integer_word_slack: bool
    linuxcnc_g_numbers: bool
    last_g_code_wins: bool
    max_m_code: int
    fixed_m_codes: List[int]
    negative_l_refused: bool
    dwell_negative_p: bool
    dwell_x_seconds: bool
    arc_turns_word: bool
    c_word_is_chamfer: bool
    fanuc_g10: bool
    g10_tool_table: bool
    numbered_subprograms: bool
    modal_state_codes: bool
    spindle_sync_motion: bool
    splines: bool
    profile_cycles: bool
    spindle_orient: bool
    restore_feed_speed_always: bool
    tool_change_stops_spindle: bool
    startup_motion: int
    cycles_own_group: bool
    g53_rapid: bool
    g84_axes_warning: bool
    motion_beside_data_axes: bool
    startup_retract_initial: bool
    d_word_alone: bool
    turning_cycles: bool
    turning_escape: float
    roughing_nose_allowance: bool
    pattern_return_shifted: bool
    thread_chamfer: float
    thread_chamfer_angle: float
    thread_finish_allowance: float
    thread_min_cut: float
    g52_offset: bool
    macro_calls: bool
    m98_subprograms: bool
    ttrc_check_codes: bool
    program_end_required: bool
    errors_at_outermost_call: bool
    abort_comment: bool
    call_depth_message: str
    startup_plane: int
    startup_feed_per_rev: bool
    block_limit: int
    call_depth_limit: int
    cutting_edge_default: int
    m89_modal_cycle_call: bool
    no_motion_limit: int
    last_comment_only: bool
    feed_mode_clears_feed: bool
    tool_change_after_block: bool
    bare_motion_codes: bool
    inverse_time_min_rate: float
    g96_needs_s: bool
    arc_spiral_abs: tuple[float, float]
    arc_spiral_rel: float
    arc_spiral_hard_factor: float
    arc_min_radius: tuple[float, float]
    length_axes: LengthAxes
    length_subtract_word: bool
    radius: RadiusRules

class Result:
    """The outcome of run(): programmed and compensated paths (mm), diagnostics and block count."""
    @property
    def ok(self) -> bool: ...
    @property
    def diagnostics(self) -> list[Diagnostic]: ...
    @property
    def nominal(self) -> Path: ...
    @property
    def path(self) -> Path: ...
    @property
    def blocks(self) -> int: ...
    @property
    def tools(self) -> ToolTable | None: ...
    @property
    def parameters(self) -> dict[int, float]: ...
    @property
    def blank(self) -> Optional[Tuple[Tuple[float, float, float], Tuple[float, float, float]]]: ...
    @property
    def cycle_time(self) -> float: ...
    @property
    def dwell_time(self) -> float: ...
    def plot(self, ax: object = None, plane: str = "xy", show_nominal: bool = True, tolerance: Optional[float] = None,
             title: Optional[str] = None, legend: bool = True, color_by: str = "tool") -> object: ...

def compensate_3d(points: npt.ArrayLike, normals: npt.ArrayLike, tool_axes: Optional[npt.ArrayLike] = None, *,
                  R: float, R2: float, DR: float = 0.0, DR2: float = 0.0,
                  out: Optional[npt.NDArray[np.float64]] = None) -> npt.NDArray[np.float64]: ...

def run(program: Program, tools: Optional[ToolTable] = None, strict: bool = True,
        block_delete: bool = False, profile: Optional[ControlProfile] = None,
        progress: Optional[Callable[[int], None]] = None, progress_every: int = 65536,
        search_path: Sequence[str] = (), parameters: Mapping[int, float] = ...,
        max_segments: int = 20000000, threads: bool = True, follow_links: bool = False,
        max_bytes: int = 2147483648, max_line_length: int = 1048576,
        machine: Optional[Machine] = None,
        probes: Sequence[Optional[Sequence[float]]] = (),
        start: Optional[Tuple[float, float, float]] = None) -> Result: ...

class PathStream:
    """Iterator over a run's compensated path in chunks; see toolcomp.iter_run."""
    def __iter__(self) -> "PathStream": ...
    def __next__(self) -> Path: ...
    def close(self) -> None: ...
    def __enter__(self) -> "PathStream": ...
    def __exit__(self, *args: object) -> None: ...
    @property
    def diagnostics(self) -> list[Diagnostic]: ...
    @property
    def blocks(self) -> int: ...
    @property
    def files(self) -> list[str]: ...
    @property
    def dialect(self) -> str: ...
    @property
    def blocks_read(self) -> int: ...
    @property
    def programmed_segments(self) -> int: ...

def iter_run_file(path: str, dialect: Optional[str], tools: Optional[ToolTable], *, strict: bool,
                  block_delete: bool, profile: Optional[ControlProfile], search_path: Sequence[str],
                  parameters: Mapping[int, float], chunk: int, piece_bytes: int, max_bytes: int,
                  max_line_length: int, follow_links: bool = False, machine: Optional[Machine] = None,
                  start: Optional[Tuple[float, float, float]] = None) -> PathStream: ...

def iter_run_program(program: Program, tools: Optional[ToolTable], *, strict: bool, block_delete: bool,
                     profile: Optional[ControlProfile], search_path: Sequence[str],
                     parameters: Mapping[int, float], chunk: int, max_bytes: int = 2147483648,
                     max_line_length: int = 1048576, follow_links: bool = False,
                     machine: Optional[Machine] = None,
                     start: Optional[Tuple[float, float, float]] = None) -> PathStream: ...

def run_file(path: str, dialect: Optional[str], tools: Optional[ToolTable], *, strict: bool, block_delete: bool,
             profile: Optional[ControlProfile], progress: Optional[Callable[[int], None]], progress_every: int,
             search_path: Sequence[str], parameters: Mapping[int, float], max_segments: int, max_bytes: int,
             max_line_length: int, threads: bool = True, follow_links: bool = False,
             machine: Optional[Machine] = None, probes: Sequence[Optional[Sequence[float]]] = (),
             start: Optional[Tuple[float, float, float]] = None) -> Result: ...

_Plane = Union[int, str]  # 17, 18, 19 or "G17", "G18", "G19"
_EdgeMap = dict[Tuple[int, int], "sinumerik.Edge"]

class sinumerik:
    """Submodule toolcomp._core.sinumerik (re-exported as toolcomp.sinumerik); a namespace here."""

    GETTCOR_OK: int
    GETTCOR_NO_ENV_MEMORY: int
    GETTCOR_ENV_MISSING: int
    GETTCOR_BAD_COMP: int
    GETTCOR_BAD_T: int
    GETTCOR_BAD_D: int
    GETTCOR_BAD_DL: int
    GETTCOR_NO_MEMORY_MODULE: int
    GETTCOR_MISSING_OPTION: int
    GETTCOR_BAD_COORD: int

    class Edge:
        def __init__(self, dp: Optional[Mapping[int, float]] = None, *, dl: int = 1) -> None: ...
        dp: npt.NDArray[np.float64]   # (25,) writable view, dp[i] = $TC_DP(i+1)
        ecp: npt.NDArray[np.float64]
        scp: npt.NDArray[np.float64]
        dl: int
        def get_dp(self, n: int) -> float: ...
        def set_dp(self, n: int, value: float) -> None: ...
        def get_ecp(self, n: int) -> float: ...
        def get_scp(self, n: int) -> float: ...
        @property
        def tool_type(self) -> int: ...
        @property
        def cutting_edge_position(self) -> float: ...
        def length(self, i: int, wear_sign: float = 1.0) -> float: ...
        def radius(self, offn: float = 0.0, *, wear_sign: float = 1.0) -> float: ...

    class LengthSettings:
        def __init__(self, *, tool_length_const: int = 0, tool_length_type: int = 0,
                     wear_sign_inverted: bool = False) -> None: ...
        tool_length_const: int
        tool_length_type: int
        wear_sign_inverted: bool
        @property
        def wear_sign(self) -> float: ...

    class GettcorSettings:
        def __init__(self, *, plane: _Plane = 17, lengths: Optional[sinumerik.LengthSettings] = None,
                     parameter_def_mask: int = 0, transverse_axis: int = 0, tool_env_memory: int = 0) -> None: ...
        @property
        def plane(self) -> int: ...
        @plane.setter
        def plane(self, value: _Plane) -> None: ...
        lengths: sinumerik.LengthSettings
        geometry_diameter: bool
        wear_diameter: bool
        transverse_axis: int
        tool_env_memory: int
        def set_parameter_def_mask(self, mask: int) -> None: ...

    class Toolholder:
        def __init__(self, kinematic_type: str = "T", *, l1: _Vec3 = ..., l2: _Vec3 = ..., l3: _Vec3 = ...,
                     l4: _Vec3 = ..., v1: _Vec3 = ..., v2: _Vec3 = ..., alpha1: float = 0.0, alpha2: float = 0.0,
                     offset1: float = 0.0, offset2: float = 0.0, name: str = "") -> None: ...
        l1: npt.NDArray[np.float64]
        l2: npt.NDArray[np.float64]
        l3: npt.NDArray[np.float64]
        l4: npt.NDArray[np.float64]
        v1: npt.NDArray[np.float64]
        v2: npt.NDArray[np.float64]
        alpha1: float
        alpha2: float
        axis1: str
        axis2: str
        kinematic_type: str  # "T" | "P" | "M"
        offset1: float
        offset2: float
        hirth: list[float]
        limits: list[float]
        name: str
        user: list[float]
        @property
        def angle1(self) -> float: ...
        @property
        def angle2(self) -> float: ...
        @overload
        def set_carr(self, n: int, value: str) -> None: ...
        @overload
        def set_carr(self, n: int, value: float) -> None: ...
        def resulting_tool_length(self, tool_length: _Vec3) -> npt.NDArray[np.float64]: ...
        def table_zero_offset(self) -> npt.NDArray[np.float64]: ...

    class Trafo5:
        def __init__(self, type: int = 24, *, base_tool: _Vec3 = ..., joint_offset: _Vec3 = ...,
                     joint_offset_part: _Vec3 = ..., part_offset: _Vec3 = ..., axis1: _Vec3 = ...,
                     axis2: _Vec3 = ...) -> None: ...
        type: int
        base_tool: npt.NDArray[np.float64]
        joint_offset: npt.NDArray[np.float64]
        joint_offset_part: npt.NDArray[np.float64]
        part_offset: npt.NDArray[np.float64]
        axis1: npt.NDArray[np.float64]
        axis2: npt.NDArray[np.float64]
        def to_toolholder(self, a1: float = 0.0, a2: float = 0.0) -> sinumerik.Toolholder: ...
        def tool_length(self, a1: float, a2: float, tool_length: _Vec3) -> npt.NDArray[np.float64]: ...

    @staticmethod
    def is_turning_type(tool_type: int) -> bool: ...
    @staticmethod
    def length_axes(tool_type: int, plane: _Plane,
                    settings: Optional[sinumerik.LengthSettings] = None) -> Tuple[int, int, int]: ...
    @staticmethod
    def lentoax(tool_type: int, plane: _Plane, settings: Optional[sinumerik.LengthSettings] = None,
                coord: str = "W") -> Tuple[int, Tuple[int, int, int], npt.NDArray[np.float64]]: ...
    @staticmethod
    def place_lengths(lengths: _Vec3, tool_type: int, plane: _Plane,
                      settings: Optional[sinumerik.LengthSettings] = None) -> npt.NDArray[np.float64]: ...
    @staticmethod
    def tool_length(edge: sinumerik.Edge, plane: _Plane = 17,
                    settings: Optional[sinumerik.LengthSettings] = None) -> npt.NDArray[np.float64]: ...
    @staticmethod
    def parse_tool_data(text: str, *, max_t: int = 32000, max_d: int = 32000) -> _EdgeMap: ...
    @staticmethod
    def read_tool_data(path: _PathLike, *, max_t: int = 32000, max_d: int = 32000) -> _EdgeMap: ...
    @staticmethod
    def format_tool_data(edges: Mapping[Tuple[int, int], sinumerik.Edge]) -> str: ...
    @overload
    @staticmethod
    def gettcor(edge: sinumerik.Edge, comp: str = "GW", settings: Optional[sinumerik.GettcorSettings] = None, *,
                plane: Optional[_Plane] = None, stat: str = "", dl: int = -1
                ) -> Tuple[int, npt.NDArray[np.float64]]: ...
    @overload
    @staticmethod
    def gettcor(edges: Mapping[Tuple[int, int], sinumerik.Edge], t: int, d: int, comp: str = "GW",
                settings: Optional[sinumerik.GettcorSettings] = None, *, plane: Optional[_Plane] = None,
                stat: str = "", dl: int = -1) -> Tuple[int, npt.NDArray[np.float64]]: ...
    @staticmethod
    def settcor(edge: sinumerik.Edge, corval: _Vec3, comp: str, corcomp: int = 0, cormode: int = 0, geoax: int = 0,
                plane: _Plane = 17, settings: Optional[sinumerik.LengthSettings] = None) -> int: ...
    SETTCOR_BAD_CORCOMP: int
    SETTCOR_BAD_CORMODE: int
    SETTCOR_BAD_GEOAX: int
    SETTCOR_NO_RADIUS: int
    @staticmethod
    def rotate_about_axis(v: _Vec3, axis: _Vec3, angle_deg: float) -> npt.NDArray[np.float64]: ...

class MachineCode:
    """A builder M code: what it does for the path, its name, the words it reads, the program it runs."""
    def __init__(self, action: str, name: str = "", words: str = "", program: str = "",
                 argspec: str = "") -> None: ...
    action: str
    name: str
    words: str
    program: str
    argspec: str

class Machine:
    """A machine: a control (its ControlProfile) plus what its builder configured."""
    def __init__(self, control: str = "linuxcnc", kind: str = "mill", name: Optional[str] = None) -> None: ...
    name: str
    @property
    def control(self) -> str: ...
    @property
    def kind(self) -> MachineKind: ...
    profile: ControlProfile
    m_codes: Dict[int, MachineCode]
    g_codes: Dict[float, MachineCode]
    cycles: Dict[int, MachineCode]
    machine_data: Dict[str, float]
    work_origin: Tuple[float, float, float]
    g28: Tuple[float, float, float]
    g30: Tuple[float, float, float]
    start: Tuple[float, float, float]
    m92: Tuple[float, float, float]
    tool_change: Sequence[Optional[float]]
    travel: Sequence[Tuple[float, float]]
    travel_limit_warning: bool
    rapid_rate: Tuple[float, float, float]
    max_feed: Tuple[float, float, float]
    tool_change_time: float
    spindles: int
    def check(self) -> None: ...
    # from toolcomp.machine
    @staticmethod
    def read(path: Any) -> "Machine": ...
    @staticmethod
    def parse(text: str, path: Optional[str] = None) -> "Machine": ...
    @staticmethod
    def preset(name: str) -> "Machine": ...
    @staticmethod
    def presets() -> List[str]: ...
    def write(self, path: Any) -> None: ...
    def dumps(self) -> str: ...

def dialect_table() -> List[Dict[str, Any]]: ...
def dialect_of_file(path: str, dialect: Optional[str] = None) -> str: ...
def diagnostic_codes() -> List[Dict[str, str]]: ...
