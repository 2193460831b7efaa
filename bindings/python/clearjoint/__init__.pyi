# SPDX-License-Identifier: BSD-3-Clause
# Type stubs of the clearjoint package for editors and type checkers; the docstrings are in the
# package (help(clearjoint.detect)) and docs/python.md.
import enum
import os
from dataclasses import dataclass
from typing import (Any, Callable, Dict, Iterator, List, Mapping, Optional, Sequence, Tuple, Union,
                    overload)

import numpy as np
import numpy.typing as npt

__version__: str
MAX_CONTACTS: int

_Vector = Union[Sequence[float], npt.NDArray[np.float64]]  # shape (3,)
_Vectors = Union[Sequence[Sequence[float]], npt.NDArray[np.float64]]  # shape (3,) or (N, 3)
_Scalars = Union[float, Sequence[float], npt.NDArray[np.float64]]  # shape () or (N,)

class SolverError(RuntimeError): ...

# The enums: the library's enum tables, written by scripts/projections (cmake --build build
# --target projections): edit the tables.
# BEGIN GENERATED enums
class Certainty(enum.IntEnum):
    exact = 0
    certified = 1
    uncertain = 2

class CertificateReason(enum.IntEnum):
    none = 0
    not_decided = 1
    certificate_switched_off = 2
    plane_filter_undecided = 3
    plane_filter_undecided_exact_fallback_off = 4
    plane_results_not_representable = 5
    subdivision_budget_exhausted = 6
    more_than_four_roots = 7
    interval_proof_failed_near_multiple_root = 8
    coefficient_overflow = 9
    cylinder_points_not_representable = 10
    exact_root_isolation_budget_exhausted = 11
    exact_coefficients_too_large = 12
    exact_intermediate_beyond_double_range = 13
    contact_not_representable_in_world = 14
    axes_parallel_within_tolerance = 15
    beyond_model_undecided = 16
    edge_sides_undecided = 17

class ContactScenario(enum.IntEnum):
    none = 0
    single_radial = 1
    single_axial = 2
    radial_at_both_bases = 3
    axial_at_both_bases = 4
    radial_and_axial_same_base = 5
    radial_and_axial_opposite_bases = 6
    two_radial_one_axial = 7
    one_radial_two_axial = 8
    all_four = 9
    line = 10
    face = 11
    line_and_face = 12
    beyond_model = 13

class ContactType(enum.IntEnum):
    radial = 0
    axial = 1

class ContactBase(enum.IntEnum):
    a = 0
    b = 1
    mid = 2

class CirclePlaneTopology(enum.IntEnum):
    disjoint = 0
    tangent = 1
    two_crossings = 2
    circle_in_plane = 3

class CircleCylinderTopology(enum.IntEnum):
    inside = 0
    outside = 1
    crossing = 2
    on_surface = 3

class PinInHoleScenario(enum.IntEnum):
    none = 0
    one_edge = 1
    both_edges_opposite = 2
    both_edges_same_side = 3
    line = 4
    one_stop = 5
    both_stops = 6
    face = 7
    edges_and_stops = 8
    line_and_face = 9
    beyond_model = 10
# END GENERATED enums

def certificate_reason_text(reason: Union[CertificateReason, int]) -> str: ...
def scenario_label(scenario: Union[ContactScenario, PinInHoleScenario, int]) -> str: ...

class JointDimensions:
    def __init__(self, *, bearing_radius: float, bearing_length: float, journal_radius: float,
                 journal_length: float) -> None: ...
    @property
    def bearing_radius(self) -> float: ...
    @property
    def bearing_length(self) -> float: ...
    @property
    def journal_radius(self) -> float: ...
    @property
    def journal_length(self) -> float: ...
    @property
    def radial_clearance(self) -> float: ...
    @property
    def axial_clearance(self) -> float: ...

class PinInHoleDimensions:
    def __init__(self, *, hole_radius: float, hole_length: float, pin_radius: float,
                 stops: Sequence[Tuple[float, float]] = ()) -> None: ...
    @property
    def hole_radius(self) -> float: ...
    @property
    def hole_length(self) -> float: ...
    @property
    def pin_radius(self) -> float: ...
    @property
    def stops(self) -> Tuple[Tuple[float, float], ...]: ...
    @property
    def radial_clearance(self) -> float: ...
    @property
    def axial_clearance(self) -> float: ...

# The result classes: the library's result field lists, written by scripts/projections, with the
# attributes that are not fields (its PY_EXTRAS): edit the field lists.
# BEGIN GENERATED results
class Certificate:
    @property
    def level(self) -> Certainty: ...
    @property
    def reason(self) -> CertificateReason: ...
    @property
    def reason_text(self) -> str: ...
    def as_dict(self) -> Dict[str, Any]: ...

class RimCrossing:
    @property
    def angle(self) -> float: ...
    @property
    def angle_error(self) -> float: ...
    @property
    def point(self) -> npt.NDArray[np.float64]: ...
    @property
    def point_error(self) -> float: ...
    @property
    def multiplicity(self) -> int: ...
    def as_dict(self) -> Dict[str, Any]: ...

class RimArc:
    @property
    def begin(self) -> float: ...
    @property
    def end(self) -> float: ...
    @property
    def full(self) -> bool: ...
    @property
    def middle(self) -> float: ...
    @property
    def sweep(self) -> float: ...
    def as_dict(self) -> Dict[str, Any]: ...

class Contact:
    @property
    def type(self) -> ContactType: ...
    @property
    def base(self) -> ContactBase: ...
    @property
    def depth(self) -> float: ...
    @property
    def depth_error(self) -> float: ...
    @property
    def point_journal(self) -> npt.NDArray[np.float64]: ...
    @property
    def point_bearing(self) -> npt.NDArray[np.float64]: ...
    @property
    def point_journal_error(self) -> float: ...
    @property
    def point_bearing_error(self) -> float: ...
    @property
    def normal(self) -> npt.NDArray[np.float64]: ...
    @property
    def crossings(self) -> List[RimCrossing]: ...
    @property
    def certificate(self) -> Certificate: ...
    def as_dict(self) -> Dict[str, Any]: ...

class JointContacts:
    @property
    def scenario(self) -> ContactScenario: ...
    @property
    def aligned(self) -> bool: ...
    @property
    def certificate(self) -> Certificate: ...
    @property
    def contacts(self) -> List[Contact]: ...
    @property
    def contact_count(self) -> int: ...
    def as_dict(self) -> Dict[str, Any]: ...

class CirclePlaneIntersection:
    @property
    def topology(self) -> CirclePlaneTopology: ...
    @property
    def side(self) -> int: ...
    @property
    def crossings(self) -> List[RimCrossing]: ...
    @property
    def penetration(self) -> Optional[RimArc]: ...
    @property
    def max_signed_distance(self) -> float: ...
    @property
    def max_signed_distance_error(self) -> float: ...
    @property
    def certificate(self) -> Certificate: ...
    def as_dict(self) -> Dict[str, Any]: ...

class CircleCylinderIntersection:
    @property
    def topology(self) -> CircleCylinderTopology: ...
    @property
    def crossings(self) -> List[RimCrossing]: ...
    @property
    def penetration_arcs(self) -> List[RimArc]: ...
    @property
    def certificate(self) -> Certificate: ...
    @property
    def root_count(self) -> int: ...
    def as_dict(self) -> Dict[str, Any]: ...

class PinInHoleContacts:
    @property
    def scenario(self) -> PinInHoleScenario: ...
    @property
    def aligned(self) -> bool: ...
    @property
    def certificate(self) -> Certificate: ...
    @property
    def contacts(self) -> List[Contact]: ...
    @property
    def contact_count(self) -> int: ...
    def as_dict(self) -> Dict[str, Any]: ...
# END GENERATED results

class ArrayResult:
    def fields(self) -> Tuple[str, ...]: ...
    def as_dict(self) -> Dict[str, npt.NDArray[Any]]: ...
    def __len__(self) -> int: ...

class DetectionBatch(ArrayResult):
    scenario: npt.NDArray[np.int8]            # (N,)
    aligned: npt.NDArray[np.bool_]            # (N,)
    certificate: npt.NDArray[np.int8]         # (N,)
    certificate_reason: npt.NDArray[np.int8]  # (N,)
    contact_count: npt.NDArray[np.int8]       # (N,)
    contact_start: npt.NDArray[np.int64]      # (N + 1,)
    contact_pose: npt.NDArray[np.int64]       # (M,)
    contact_type: npt.NDArray[np.int8]        # (M,)
    contact_base: npt.NDArray[np.int8]        # (M,)
    depth: npt.NDArray[np.float64]            # (M,)
    depth_error: npt.NDArray[np.float64]      # (M,)
    point_journal: npt.NDArray[np.float64]    # (M, 3)
    point_journal_error: npt.NDArray[np.float64]  # (M,)
    point_bearing: npt.NDArray[np.float64]    # (M, 3)
    point_bearing_error: npt.NDArray[np.float64]  # (M,)
    normal: npt.NDArray[np.float64]           # (M, 3)
    crossing_count: npt.NDArray[np.int8]      # (M,)
    crossing_angle: npt.NDArray[np.float64]   # (M, 2)
    crossing_angle_error: npt.NDArray[np.float64]  # (M, 2)
    crossing_point: npt.NDArray[np.float64]   # (M, 2, 3)
    crossing_point_error: npt.NDArray[np.float64]  # (M, 2)
    crossing_multiplicity: npt.NDArray[np.int8]    # (M, 2)
    contact_certificate: npt.NDArray[np.int8]  # (M,)
    contact_certificate_reason: npt.NDArray[np.int8]  # (M,)
    def scenarios(self) -> List[ContactScenario]: ...
    def slot(self) -> npt.NDArray[np.int64]: ...
    def padded(self, field: str) -> npt.NDArray[Any]: ...
    def __getitem__(self, pose: int) -> JointContacts: ...
    def __iter__(self) -> Iterator[JointContacts]: ...
    def poses(self) -> Any: ...     # pandas.DataFrame, or Dict[str, NDArray] without pandas
    def contacts(self) -> Any: ...  # pandas.DataFrame, or Dict[str, NDArray] without pandas

class PinInHoleBatch(ArrayResult):
    scenario: npt.NDArray[np.int8]            # (N,) PinInHoleScenario codes
    aligned: npt.NDArray[np.bool_]            # (N,)
    certificate: npt.NDArray[np.int8]         # (N,)
    certificate_reason: npt.NDArray[np.int8]  # (N,)
    contact_count: npt.NDArray[np.int8]       # (N,)
    contact_start: npt.NDArray[np.int64]      # (N + 1,)
    contact_pose: npt.NDArray[np.int64]       # (M,)
    contact_type: npt.NDArray[np.int8]        # (M,)
    contact_base: npt.NDArray[np.int8]        # (M,)
    depth: npt.NDArray[np.float64]            # (M,)
    depth_error: npt.NDArray[np.float64]      # (M,)
    point_journal: npt.NDArray[np.float64]    # (M, 3) on the pin
    point_journal_error: npt.NDArray[np.float64]  # (M,)
    point_bearing: npt.NDArray[np.float64]    # (M, 3) on the link
    point_bearing_error: npt.NDArray[np.float64]  # (M,)
    normal: npt.NDArray[np.float64]           # (M, 3)
    crossing_count: npt.NDArray[np.int8]      # (M,)
    crossing_angle: npt.NDArray[np.float64]   # (M, 2)
    crossing_angle_error: npt.NDArray[np.float64]  # (M, 2)
    crossing_point: npt.NDArray[np.float64]   # (M, 2, 3)
    crossing_point_error: npt.NDArray[np.float64]  # (M, 2)
    crossing_multiplicity: npt.NDArray[np.int8]    # (M, 2)
    contact_certificate: npt.NDArray[np.int8]  # (M,)
    contact_certificate_reason: npt.NDArray[np.int8]  # (M,)
    def scenarios(self) -> List[PinInHoleScenario]: ...
    def slot(self) -> npt.NDArray[np.int64]: ...
    def padded(self, field: str) -> npt.NDArray[Any]: ...
    def __getitem__(self, pose: int) -> PinInHoleContacts: ...
    def __iter__(self) -> Iterator[PinInHoleContacts]: ...
    def poses(self) -> Any: ...     # pandas.DataFrame, or Dict[str, NDArray] without pandas
    def contacts(self) -> Any: ...  # pandas.DataFrame, or Dict[str, NDArray] without pandas

class CirclePlaneBatch(ArrayResult):
    topology: npt.NDArray[np.int8]
    side: npt.NDArray[np.int8]
    crossing_count: npt.NDArray[np.int8]
    crossing_angle: npt.NDArray[np.float64]
    crossing_angle_error: npt.NDArray[np.float64]
    crossing_point: npt.NDArray[np.float64]
    crossing_point_error: npt.NDArray[np.float64]
    crossing_multiplicity: npt.NDArray[np.int8]
    has_penetration: npt.NDArray[np.bool_]
    penetration_begin: npt.NDArray[np.float64]
    penetration_end: npt.NDArray[np.float64]
    penetration_full: npt.NDArray[np.bool_]
    max_signed_distance: npt.NDArray[np.float64]
    max_signed_distance_error: npt.NDArray[np.float64]
    certificate: npt.NDArray[np.int8]
    certificate_reason: npt.NDArray[np.int8]

class CircleCylinderBatch(ArrayResult):
    topology: npt.NDArray[np.int8]
    crossing_count: npt.NDArray[np.int8]
    crossing_angle: npt.NDArray[np.float64]
    crossing_angle_error: npt.NDArray[np.float64]
    crossing_point: npt.NDArray[np.float64]
    crossing_point_error: npt.NDArray[np.float64]
    crossing_multiplicity: npt.NDArray[np.int8]
    arc_count: npt.NDArray[np.int8]
    arc_begin: npt.NDArray[np.float64]
    arc_end: npt.NDArray[np.float64]
    arc_full: npt.NDArray[np.bool_]
    certificate: npt.NDArray[np.int8]
    certificate_reason: npt.NDArray[np.int8]

@overload
def detect(dims: JointDimensions, bearing_center: _Vector, bearing_axis: _Vector,
           journal_center: _Vector, journal_axis: _Vector, *, certify: bool = ...,
           exact_fallback: bool = ..., parallel_angle_tolerance: float = ...,
           threads: Optional[int] = ...) -> JointContacts: ...
@overload
def detect(dims: JointDimensions, bearing_center: _Vectors, bearing_axis: _Vectors,
           journal_center: _Vectors, journal_axis: _Vectors, *, certify: bool = ...,
           exact_fallback: bool = ..., parallel_angle_tolerance: float = ...,
           threads: Optional[int] = ...) -> Union[JointContacts, DetectionBatch]: ...
@overload
def detect_pin_in_hole(dims: PinInHoleDimensions, hole_center: _Vector, hole_axis: _Vector,
                       pin_center: _Vector, pin_axis: _Vector, *, certify: bool = ...,
                       exact_fallback: bool = ..., parallel_angle_tolerance: float = ...,
                       threads: Optional[int] = ...) -> PinInHoleContacts: ...
@overload
def detect_pin_in_hole(dims: PinInHoleDimensions, hole_center: _Vectors, hole_axis: _Vectors,
                       pin_center: _Vectors, pin_axis: _Vectors, *, certify: bool = ...,
                       exact_fallback: bool = ..., parallel_angle_tolerance: float = ...,
                       threads: Optional[int] = ...) -> Union[PinInHoleContacts, PinInHoleBatch]: ...
def intersect_circle_plane(circle_center: _Vectors, circle_normal: _Vectors, circle_radius: _Scalars,
                           plane_point: _Vectors, plane_normal: _Vectors, *, certify: bool = ...,
                           exact_fallback: bool = ..., threads: Optional[int] = ...
                           ) -> Union[CirclePlaneIntersection, CirclePlaneBatch]: ...
def intersect_circle_cylinder(circle_center: _Vectors, circle_normal: _Vectors,
                              circle_radius: _Scalars, cylinder_point: _Vectors,
                              cylinder_axis: _Vectors, cylinder_radius: _Scalars, *,
                              certify: bool = ..., exact_fallback: bool = ...,
                              threads: Optional[int] = ...
                              ) -> Union[CircleCylinderIntersection, CircleCylinderBatch]: ...

@dataclass(frozen=True)
class SimulationResult:
    tables: Dict[str, Dict[str, npt.NDArray[np.float64]]]
    summary: Dict[str, Any]
    folder: Optional[str]
    def __getitem__(self, table: str) -> Dict[str, npt.NDArray[np.float64]]: ...

def simulate(model: Union[str, os.PathLike[str], Mapping[str, Any]], *,
             progress: Union[bool, None, Callable[[float], None]] = ...,
             allow_large: bool = ...,
             report_step: Optional[float] = ...,
             decimation: Optional[int] = ...,
             out: Union[None, str, os.PathLike[str]] = ...,
             format: str = ...,
             force: bool = ...,
             engine: str = ...,
             overrides: Optional[Mapping[str, Any]] = ...,
             write_fclib: Union[None, str, os.PathLike[str]] = ...,
             fclib_count: Optional[int] = ...) -> SimulationResult: ...

def read_run(folder: Union[str, os.PathLike[str]]) -> SimulationResult: ...

class Simulator:
    def __init__(self, model: Union[str, os.PathLike[str], Mapping[str, Any]]) -> None: ...
    @property
    def time(self) -> float: ...
    @property
    def end_time(self) -> float: ...
    @property
    def finished(self) -> bool: ...
    @property
    def state(self) -> npt.NDArray[np.float64]: ...
    def set_state(self, state: Any) -> None: ...
    def body_state(self, body: str) -> Dict[str, npt.NDArray[np.float64]]: ...
    def apply_load(self, body: str, force: Any = ..., moment: Any = ...) -> None: ...
    def clear_loads(self) -> None: ...
    def step(self) -> None: ...
    def advance_to(self, t: float) -> None: ...
    def joint_state(self, name: str) -> Dict[str, Any]: ...
    def take_impacts(self) -> List[Dict[str, Any]]: ...
    def statistics(self) -> Dict[str, int]: ...

_Fields = Mapping[str, Any]

class Model:
    def __init__(self, name: Optional[str] = ..., *, gravity: Optional[_Vector] = ...,
                 notes: Optional[str] = ..., comment: Optional[str] = ...) -> None: ...
    name: Optional[str]
    gravity: Optional[List[float]]
    notes: Optional[str]
    comment: Optional[str]
    def add_body(self, name: str, *, mass: float, inertia: _Vector, position: _Vector,
                 euler_parameters: Optional[Sequence[float]] = ..., velocity: Optional[_Vector] = ...,
                 angular_velocity: Optional[_Vector] = ..., comment: Optional[str] = ...,
                 notes: Optional[str] = ...) -> str: ...
    def add_joint(self, name: str, type: str, body_i: str, body_j: str, *,
                  point_i: Optional[_Vector] = ..., point_j: Optional[_Vector] = ...,
                  axis_i: Optional[_Vector] = ..., axis_j: Optional[_Vector] = ...,
                  angle_rate: Optional[float] = ..., angle_acceleration: Optional[float] = ...,
                  comment: Optional[str] = ..., notes: Optional[str] = ...) -> str: ...
    def add_spherical(self, name: str, body_i: str, body_j: str, *, point_i: Optional[_Vector] = ...,
                      point_j: Optional[_Vector] = ..., comment: Optional[str] = ...,
                      notes: Optional[str] = ...) -> str: ...
    def add_revolute(self, name: str, body_i: str, body_j: str, *, point_i: Optional[_Vector] = ...,
                     point_j: Optional[_Vector] = ..., axis_i: Optional[_Vector] = ...,
                     axis_j: Optional[_Vector] = ..., comment: Optional[str] = ...,
                     notes: Optional[str] = ...) -> str: ...
    def add_universal(self, name: str, body_i: str, body_j: str, *, point_i: Optional[_Vector] = ...,
                      point_j: Optional[_Vector] = ..., axis_i: Optional[_Vector] = ...,
                      axis_j: Optional[_Vector] = ..., comment: Optional[str] = ...,
                      notes: Optional[str] = ...) -> str: ...
    def add_cylindrical(self, name: str, body_i: str, body_j: str, *,
                        point_i: Optional[_Vector] = ..., point_j: Optional[_Vector] = ...,
                        axis_i: Optional[_Vector] = ..., axis_j: Optional[_Vector] = ...,
                        comment: Optional[str] = ..., notes: Optional[str] = ...) -> str: ...
    def add_translational(self, name: str, body_i: str, body_j: str, *,
                          point_i: Optional[_Vector] = ..., point_j: Optional[_Vector] = ...,
                          axis_i: Optional[_Vector] = ..., axis_j: Optional[_Vector] = ...,
                          comment: Optional[str] = ..., notes: Optional[str] = ...) -> str: ...
    def add_fixed(self, name: str, body_i: str, body_j: str, *, point_i: Optional[_Vector] = ...,
                  point_j: Optional[_Vector] = ..., comment: Optional[str] = ...,
                  notes: Optional[str] = ...) -> str: ...
    def add_angle_driver(self, name: str, body_i: str, body_j: str, *, axis_i: Optional[_Vector] = ...,
                         angle_rate: Optional[float] = ..., angle_acceleration: Optional[float] = ...,
                         comment: Optional[str] = ..., notes: Optional[str] = ...) -> str: ...
    def add_point_load(self, name: str, body: str, *, point: Optional[_Vector] = ...,
                       force: Optional[_Vector] = ..., moment: Optional[_Vector] = ...,
                       comment: Optional[str] = ..., notes: Optional[str] = ...) -> str: ...
    def add_spring_damper(self, name: str, body_i: str, body_j: str, *, stiffness: float,
                          free_length: float, damping: Optional[float] = ...,
                          point_i: Optional[_Vector] = ..., point_j: Optional[_Vector] = ...,
                          comment: Optional[str] = ..., notes: Optional[str] = ...) -> str: ...
    def add_clearance_revolute(self, name: str, *, normal_force: _Fields,
                               bearing: Optional[_Fields] = ..., journal: Optional[_Fields] = ...,
                               geometry: Optional[str] = ..., hole: Optional[_Fields] = ...,
                               pin: Optional[_Fields] = ..., friction: Optional[_Fields] = ...,
                               detection: Optional[_Fields] = ..., lubrication: Optional[_Fields] = ...,
                               comment: Optional[str] = ..., notes: Optional[str] = ...) -> str: ...
    def set_initial_conditions(self, *, hold_positions: Optional[Sequence[_Fields]] = ...,
                               hold_velocities: Optional[Sequence[_Fields]] = ...,
                               comment: Optional[str] = ..., notes: Optional[str] = ...) -> None: ...
    def hold_position(self, body: str, components: Sequence[str] = ..., *,
                      comment: Optional[str] = ..., notes: Optional[str] = ...) -> None: ...
    def hold_velocity(self, body: str, component: str, value: float, *,
                      comment: Optional[str] = ..., notes: Optional[str] = ...) -> None: ...
    def set_solver(self, *, start_time: Optional[float] = ..., end_time: Optional[float] = ...,
                   report_step: Optional[float] = ..., relative_tolerance: Optional[float] = ...,
                   absolute_tolerance: Optional[float] = ..., initial_step: Optional[float] = ...,
                   minimum_step: Optional[float] = ..., max_steps: Optional[int] = ...,
                   baumgarte_alpha: Optional[float] = ..., baumgarte_beta: Optional[float] = ...,
                   comment: Optional[str] = ..., notes: Optional[str] = ...) -> None: ...
    def set_output(self, *, bodies: Optional[Sequence[str]] = ...,
                   force_elements: Optional[Sequence[str]] = ..., decimation: Optional[int] = ...,
                   comment: Optional[str] = ..., notes: Optional[str] = ...) -> None: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def to_json(self, *, indent: Optional[int] = ...) -> str: ...
    def validate(self) -> None: ...
    def save(self, path: Union[str, os.PathLike[str]], *, validate: bool = ...) -> None: ...
    @classmethod
    def from_dict(cls, data: Mapping[str, Any], *, validate: bool = ...) -> Model: ...
    @classmethod
    def load(cls, path: Union[str, os.PathLike[str]], *, validate: bool = ...) -> Model: ...
