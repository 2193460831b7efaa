# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.detect and the kernel queries, on one pose or on NumPy batches."""
from __future__ import annotations

import operator
from collections.abc import Mapping
from typing import Any, Dict, Iterator, Optional, Union

import numpy as np

from . import _core
from ._arrays import ArrayResult
from ._core import (CircleCylinderIntersection, CirclePlaneIntersection, JointContacts,
                    JointDimensions, PinInHoleContacts, PinInHoleDimensions)
from ._enums import ContactScenario, PinInHoleScenario

#: Room for contacts per pose: two radial per rim (beyond the model a rim may have two
#: penetration arcs) plus two axial; C++ ``clearjoint::geometry::kMaxContacts``.
MAX_CONTACTS = 6

ArrayLike = Any

#: DetectionBatch fields with one row per pose, in the order of ``poses()``.
_POSE_FIELDS = ("scenario", "aligned", "certificate", "certificate_reason", "contact_count")
#: Contact fields whose last axis is a vector (x, y, z) in ``contacts()``'s column names.
_VECTOR_FIELDS = ("point_journal", "point_bearing", "normal", "crossing_point")


def _table(columns: Dict[str, np.ndarray]) -> Any:
    """A pandas DataFrame of the columns when pandas can be imported, else the dict itself."""
    try:
        import pandas
    except ImportError:
        return columns
    return pandas.DataFrame(columns)


class _ContactBatch(ArrayResult):
    """What DetectionBatch and PinInHoleBatch share: the packed arrays of a joint whose answer is
    a list of :class:`Contact` (the layout of ``bindings/python/src/packed_contacts.hpp``)."""

    _rows_field = "scenario"
    #: The class of one pose's answer, rebuilt by ``batch[n]``.
    _answer: Any = JointContacts
    #: The scenario enum of ``scenarios()``.
    _scenario_enum: Any = ContactScenario

    def __getitem__(self, pose: int) -> JointContacts:
        """Pose ``pose``'s contacts, as :func:`detect` gives them for that pose alone."""
        try:
            n = operator.index(pose)
        except TypeError:
            raise TypeError(f"{type(self).__name__} index {pose!r}: must be an integer (a pose "
                            f"number); poses() and contacts() give tables to filter") from None
        count = len(self)
        if not -count <= n < count:
            raise IndexError(f"pose {n} out of range for a batch of {count} poses")
        n %= count
        contacts = [self._contact_dict(k)
                    for k in range(self.contact_start[n], self.contact_start[n + 1])]
        return self._answer._from_dict({
            "scenario": int(self.scenario[n]), "aligned": bool(self.aligned[n]),
            "certificate": int(self.certificate[n]),
            "certificate_reason": int(self.certificate_reason[n]),
            "contact_count": len(contacts), "contacts": contacts})

    def __iter__(self) -> Iterator[JointContacts]:
        return (self[n] for n in range(len(self)))

    def _contact_dict(self, k: int) -> Dict[str, Any]:
        """Contact row k in the form of :meth:`Contact.as_dict` (floats keep their bits)."""
        crossings = [{"angle": float(self.crossing_angle[k, x]),
                      "angle_error": float(self.crossing_angle_error[k, x]),
                      "point": self.crossing_point[k, x].tolist(),
                      "point_error": float(self.crossing_point_error[k, x]),
                      "multiplicity": int(self.crossing_multiplicity[k, x])}
                     for x in range(self.crossing_count[k])]
        return {"type": int(self.contact_type[k]), "base": int(self.contact_base[k]),
                "depth": float(self.depth[k]), "depth_error": float(self.depth_error[k]),
                "point_journal": self.point_journal[k].tolist(),
                "point_journal_error": float(self.point_journal_error[k]),
                "point_bearing": self.point_bearing[k].tolist(),
                "point_bearing_error": float(self.point_bearing_error[k]),
                "normal": self.normal[k].tolist(), "crossings": crossings,
                "certificate": int(self.contact_certificate[k]),
                "certificate_reason": int(self.contact_certificate_reason[k])}

    def poses(self) -> Any:
        """One row per pose, the index the pose number: ``scenario``, ``aligned``,
        ``certificate``, ``certificate_reason``, ``contact_count`` (codes as in the arrays).

        A pandas DataFrame when pandas can be imported, else a dict of these arrays (no copies).
        """
        return _table({name: getattr(self, name) for name in _POSE_FIELDS})

    def contacts(self) -> Any:
        """One row per contact, packed in pose order: ``pose`` and ``slot`` (the contact's pose
        and its index among that pose's contacts), then the contact fields without their
        ``contact_`` prefix (``type``, ``base``, ``depth``, ..., ``certificate``,
        ``certificate_reason``), wider fields spread over columns: ``normal_x``,
        ``crossing_angle_0``, ``crossing_point_1_z``.

        A pandas DataFrame when pandas can be imported, else a dict of equal-length arrays.
        """
        columns = {"pose": self.contact_pose, "slot": self.slot()}
        for field in self._names:
            values = getattr(self, field)
            if field in ("contact_start", "contact_pose") or values.shape[:1] != self.contact_pose.shape:
                continue
            name = field[len("contact_"):] if field.startswith("contact_") else field
            for index in np.ndindex(values.shape[1:]):
                labels = [str(i) for i in index]
                if field in _VECTOR_FIELDS:
                    labels[-1] = "xyz"[index[-1]]
                columns["_".join([name] + labels)] = values[(slice(None),) + index]
        return _table(columns)

    def scenarios(self) -> list:
        """``scenario`` as :class:`ContactScenario` values (a list, length N)."""
        return [self._scenario_enum(int(code)) for code in self.scenario]

    def slot(self) -> np.ndarray:
        """Each contact row's index among its pose's contacts, 0 to 5, shape (M,)."""
        return np.arange(len(self.contact_pose)) - self.contact_start[self.contact_pose]

    def padded(self, field: str) -> np.ndarray:
        """One contact field laid out per pose: shape (N, 6, ...), slots past the pose's
        contact_count filled with NaN (floats), -1 (integer codes) or False.

        >>> batch.padded("depth")[n, k]   # depth of contact k of pose n
        """
        values = getattr(self, field)
        if values.shape[:1] != self.contact_pose.shape or field in ("contact_start", "contact_pose"):
            raise ValueError(f"field = {field!r}: must be one of the contact fields (shape (M, ...))")
        fill: Any = np.nan if np.issubdtype(values.dtype, np.floating) else (
            False if values.dtype == np.bool_ else -1)
        out = np.full((len(self), MAX_CONTACTS) + values.shape[1:], fill, dtype=values.dtype)
        out[self.contact_pose, self.slot()] = values
        return out


class DetectionBatch(_ContactBatch):
    """The contacts of N poses, as NumPy arrays.

    Per pose, shape (N,):

    - ``scenario`` (int8): a :class:`ContactScenario` code, Fig. 2 of the paper; ``none`` 0,
      (a)-(i) 1-9, (j)-(l) 10-12, ``beyond_model`` 13. ``scenarios()`` gives the enum values.
    - ``aligned`` (bool): axes parallel, exactly (eq. 5) or within ``parallel_angle_tolerance``.
    - ``certificate`` (int8): a :class:`Certainty` code (exact 0, certified 1, uncertain 2), the
      weakest over every decision for that pose, "no contact" included; ``certificate_reason``
      (int8): its :class:`CertificateReason` code (none 0 when certified).
    - ``contact_count`` (int8): 0 to 6.

    The contacts of all poses, packed in pose order, shape (M, ...) with M = contact_count.sum();
    pose n owns rows ``contact_start[n]:contact_start[n + 1]`` (``contact_start``: (N + 1,)
    int64), radial before axial, base A before B; ``contact_pose`` (M,) is the pose of each row:

    - ``contact_type`` (int8): :class:`ContactType` (radial 0, axial 1);
    - ``contact_base`` (int8): :class:`ContactBase` (a 0, b 1, mid 2);
    - ``depth`` (M,): penetration depth >= 0, the input's length unit (eq. 23), and
      ``depth_error`` (M,): the true depth lies within it (certified unless the contact is
      uncertain, then inf);
    - ``point_journal``, ``point_bearing``, ``normal`` (M, 3): C_j, C_i and the unit normal, out
      of the bearing, world frame: point_journal - point_bearing = depth * normal up to rounding
      (eqs. 7-10, 14-15, 19-22); ``point_journal_error``, ``point_bearing_error`` (M,): bounds
      on the points' errors (Euclidean), as for depth_error;
    - ``crossing_count`` (int8, M,): rim crossings bounding the penetration arc (0 for line and
      face contacts); ``crossing_angle``, ``crossing_angle_error`` (M, 2) radians,
      ``crossing_point`` (M, 2, 3), ``crossing_point_error`` (M, 2) length: a certified or exact
      crossing lies within its error of the value; NaN in unused slots;
      ``crossing_multiplicity`` (int8, M, 2): 1 crossing, 2 tangency, 0 unused;
    - ``contact_certificate`` (int8, M,): the contact's :class:`Certainty` code, and
      ``contact_certificate_reason`` its :class:`CertificateReason` code.

    Packed rather than padded to (N, 6, ...): a padded batch writes about a kilobyte a pose, as
    much time as the detection of a realistic pose itself. ``padded(field)`` gives the (N, 6, ...)
    view of one field when that shape is handier.

    A batch is also a sequence of poses: ``batch[n]`` (negative n counting from the end) is
    pose n's :class:`JointContacts`, bit for bit the answer of ``detect`` on that pose alone,
    and iterating gives them in order. ``poses()`` and ``contacts()`` give the arrays as two
    tables (pandas DataFrames when pandas is installed).
    """


class PinInHoleBatch(_ContactBatch):
    """The contacts of N pin-in-hole poses, as NumPy arrays: :func:`detect_pin_in_hole`'s answer
    for a batch.

    The arrays of :class:`DetectionBatch`, the link (the hole) in the bearing's place and the pin
    in the journal's, as in :class:`PinInHoleContacts`:

    - ``scenario`` (int8, N,): a :class:`PinInHoleScenario` code (``none`` 0, ``one_edge`` 1,
      ..., ``beyond_model`` 10); ``scenarios()`` gives the enum values;
    - ``aligned``, ``certificate``, ``certificate_reason``, ``contact_count`` (N,), and
      ``contact_start`` (N + 1,): as for :class:`DetectionBatch`;
    - per contact, packed in pose order (M,...): ``contact_type`` radial 0 (an edge or the line
      contact), axial 1 (a stop); ``contact_base`` a 0, b 1 (the link face), mid 2 (the line);
      ``point_journal`` on the pin, ``point_bearing`` on the link, ``normal`` the direction the
      pin penetrates; ``depth`` and the error bounds; the crossings bound the contact's arc on
      the circle that bounds it (a hole edge or a stop's outer circle), in that circle's frame.

    ``batch[n]`` (and iteration) gives pose n's :class:`PinInHoleContacts`, bit for bit the
    answer of :func:`detect_pin_in_hole` on that pose alone; ``len(batch)`` is N.
    """

    _answer = PinInHoleContacts
    _scenario_enum = PinInHoleScenario

    def __getitem__(self, pose: int) -> PinInHoleContacts:  # type: ignore[override]
        """Pose ``pose``'s contacts, as :func:`detect_pin_in_hole` gives them for that pose alone."""
        return super().__getitem__(pose)  # type: ignore[return-value]

    def __iter__(self) -> Iterator[PinInHoleContacts]:  # type: ignore[override]
        return (self[n] for n in range(len(self)))

    def scenarios(self) -> list:
        """``scenario`` as :class:`PinInHoleScenario` values (a list, length N)."""
        return super().scenarios()


class CirclePlaneBatch(ArrayResult):
    """Circle-plane answers for N pairs (a rim against a base plane, eqs. 11-15).

    Shape (N,): ``topology`` (int8, :class:`CirclePlaneTopology`: disjoint 0, tangent 1,
    two_crossings 2, circle_in_plane 3); ``side`` (int8, +1 / -1 / 0); ``crossing_count``;
    ``has_penetration`` (bool), ``penetration_begin``, ``penetration_end`` (rim angles, radians,
    NaN when no penetration), ``penetration_full`` (bool); ``max_signed_distance`` and its
    ``max_signed_distance_error`` (length; positive on the normal's side); ``certificate``
    (int8 :class:`Certainty`) and ``certificate_reason`` (int8 :class:`CertificateReason`).
    Shape (N, 2): ``crossing_angle``, ``crossing_angle_error``,
    ``crossing_point_error``, ``crossing_multiplicity`` (0 unused); ``crossing_point`` (N, 2, 3).
    Unused crossing slots hold NaN.
    """

    _rows_field = "topology"


class CircleCylinderBatch(ArrayResult):
    """Circle-cylinder answers for N pairs (a rim against the bearing wall, eqs. 16-21).

    Shape (N,): ``topology`` (int8, :class:`CircleCylinderTopology`: inside 0, outside 1,
    crossing 2, on_surface 3), ``crossing_count`` (0-4), ``arc_count`` (0-2), ``certificate``,
    ``certificate_reason``.
    Shape (N, 4): ``crossing_angle``, ``crossing_angle_error``, ``crossing_point_error``,
    ``crossing_multiplicity``; ``crossing_point`` (N, 4, 3); sorted by angle, NaN when unused.
    Shape (N, 2): ``arc_begin``, ``arc_end`` (radians, NaN when unused), ``arc_full`` (bool): the
    maximal arcs of rim points strictly beyond the wall.
    """

    _rows_field = "topology"


def detect(dims: JointDimensions, bearing_center: ArrayLike, bearing_axis: ArrayLike,
           journal_center: ArrayLike, journal_axis: ArrayLike, *, certify: bool = True,
           exact_fallback: bool = True, parallel_angle_tolerance: float = 0.0,
           threads: Optional[int] = None) -> Union[JointContacts, DetectionBatch]:
    """Detect every contact between a journal and its bearing (paper Section 3, eqs. 3-26).

    Parameters
    ----------
    dims:
        The joint's :class:`JointDimensions` (Ri, Li, Rj, Lj; any one length unit).
    bearing_center, bearing_axis, journal_center, journal_axis:
        Each of shape (3,) (one pose, the same for every row) or (N, 3) (one per row): the centre
        P of the part's axis segment and its axis direction a (any non-zero length; only the
        direction counts), world frame. Base A of a part is at P + (L/2) a/|a| (eq. 3), base B at
        P - (L/2) a/|a| (eq. 4). Lists and integer arrays are converted to float64; bools,
        complex numbers, datetimes, strings and masked values are refused.
    certify:
        Prove every decision (default). False: plain floating point, every answer uncertain.
    exact_fallback:
        When a floating-point proof fails (near a tangency), decide with exact rational
        arithmetic (default). False: such decisions come back uncertain, with the reason.
    parallel_angle_tolerance:
        Radians, in [0, pi/2). 0 (default): axes are parallel only when a_i x a_j = 0 exactly
        (eq. 5). Larger: nearly parallel axes are treated as parallel (eqs. 6-10) and their
        contacts are uncertain.
    threads:
        Threads for a batch (default None: every core; any positive integer, a limit capped at
        1024 and at the cores the process may run on). The answers do not depend on it.

    Returns
    -------
    JointContacts
        When every pose argument has shape (3,).
    DetectionBatch
        Otherwise: arrays for N poses (see its documentation for the layout).

    Raises
    ------
    ValueError
        A bad value, naming the argument and the row: ``"journal_axis[7] = [0, 0, 0]: must not be
        the zero vector"``; a shape other than (3,) or (N, 3); batched arguments of different N.
    TypeError
        Arguments that are not numbers (or ``dims`` not a :class:`JointDimensions`, a switch
        not True or False, ``threads`` not an integer).
    MemoryError
        The batch's results do not fit in memory (the message names the batch's size).
    KeyboardInterrupt
        Ctrl-C: a batch looks for it every 50 ms or so and stops.

    The detection runs without the GIL.
    """
    if not isinstance(dims, JointDimensions):
        hint = " (JointDimensions(**dims) for a dict)" if isinstance(dims, Mapping) else ""
        raise TypeError(f"dims = {dims!r}: must be a clearjoint.JointDimensions{hint}")
    # By the keys of the library's option list (tests/test_detect.py checks there is one keyword each).
    options = {"certify": certify, "exact_fallback": exact_fallback,
               "parallel_angle_tolerance": parallel_angle_tolerance}
    result = _core.detect(dims, bearing_center, bearing_axis, journal_center, journal_axis, options, threads)
    return DetectionBatch(result) if isinstance(result, dict) else result


def detect_pin_in_hole(dims: PinInHoleDimensions, hole_center: ArrayLike, hole_axis: ArrayLike,
                       pin_center: ArrayLike, pin_axis: ArrayLike, *, certify: bool = True,
                       exact_fallback: bool = True, parallel_angle_tolerance: float = 0.0,
                       threads: Optional[int] = None
                       ) -> Union[PinInHoleContacts, PinInHoleBatch]:
    """Detect every contact between a pin and the hole it passes through: the hole's edges
    against the pin, the stops against the link's faces, the line and face contacts of parallel
    axes (docs/contact-detection.md, "The pin-in-hole joint").

    Parameters
    ----------
    dims:
        The joint's :class:`PinInHoleDimensions` (Rh, L, Rp and the stops).
    hole_center, hole_axis:
        The hole's centre, midway between the link's faces, and its axis (face A is the one the
        axis points to). Shape (3,) or (N, 3), as for :func:`detect`.
    pin_center, pin_axis:
        The pin's point P (at the hole's centre when the pin is centred; the stops' positions
        are measured from it) and its axis.
    certify, exact_fallback, parallel_angle_tolerance, threads:
        As for :func:`detect`.

    Returns
    -------
    PinInHoleContacts
        When every pose argument has shape (3,): its ``scenario`` a :class:`PinInHoleScenario`,
        its ``contacts`` :class:`Contact` objects as :func:`detect` gives them, the link in the
        bearing's place (``point_bearing``) and the pin in the journal's (``point_journal``).
    PinInHoleBatch
        Otherwise: arrays for N poses, packed as :class:`DetectionBatch`'s; also a sequence of
        N :class:`PinInHoleContacts` (``batch[n]``, iteration), each bit for bit the answer on
        that pose alone.

    Raises
    ------
    ValueError
        A bad value, naming the argument and the row (``"pin_axis[3] = [0, 0, 0]: must not be
        the zero vector"``); a shape other than (3,) or (N, 3); batched arguments of different N.
    TypeError
        Arguments that are not numbers, or ``dims`` not a :class:`PinInHoleDimensions`, a switch
        not True or False, ``threads`` not an integer.
    MemoryError
        The batch's results do not fit in memory (the message names the batch's size).
    KeyboardInterrupt
        Ctrl-C: a batch looks for it every 50 ms or so and stops.

    The detection runs without the GIL, a batch spread over threads.
    """
    if not isinstance(dims, PinInHoleDimensions):
        hint = " (PinInHoleDimensions(**dims) for a dict)" if isinstance(dims, Mapping) else ""
        raise TypeError(f"dims = {dims!r}: must be a clearjoint.PinInHoleDimensions{hint}")
    options = {"certify": certify, "exact_fallback": exact_fallback,
               "parallel_angle_tolerance": parallel_angle_tolerance}
    result = _core.detect_pin_in_hole(dims, hole_center, hole_axis, pin_center, pin_axis, options,
                                      threads)
    return PinInHoleBatch(result) if isinstance(result, dict) else result


def intersect_circle_plane(circle_center: ArrayLike, circle_normal: ArrayLike,
                           circle_radius: ArrayLike, plane_point: ArrayLike,
                           plane_normal: ArrayLike, *, certify: bool = True,
                           exact_fallback: bool = True, threads: Optional[int] = None
                           ) -> Union[CirclePlaneIntersection, CirclePlaneBatch]:
    """Intersect a circle (a journal rim) with a plane (a bearing base): eqs. (11)-(15).

    The circle is {x : n . (x - c) = 0, |x - c| = r}; the plane {x : m . (x - p) = 0}, its
    positive side the one m points to (for a bearing base: outside the bearing). Normals need not
    be unit. Vectors have shape (3,) or (N, 3), the radius () or (N,); single rows broadcast.
    Rim angles follow the circle's frame (u, v, n/|n|), u = n x e_k / |n x e_k|, k the axis of
    the smallest |n_k|: x(theta) = c + r (cos(theta) u + sin(theta) v).

    The topology is decided exactly (a floating-point filter, then rationals); crossings come with
    certified error bounds. ``certify=False``: plain floating point, uncertain answers;
    ``exact_fallback=False``: no rationals, answers the filter cannot decide are uncertain.

    Returns a :class:`CirclePlaneIntersection` for one pair, else a :class:`CirclePlaneBatch`.
    Raises ValueError naming the argument and row (``"circle_radius[3] = -1: must be
    positive"``).
    """
    result = _core.intersect_circle_plane(circle_center, circle_normal, circle_radius,
                                          plane_point, plane_normal, certify, exact_fallback,
                                          threads)
    return CirclePlaneBatch(result) if isinstance(result, dict) else result


def intersect_circle_cylinder(circle_center: ArrayLike, circle_normal: ArrayLike,
                              circle_radius: ArrayLike, cylinder_point: ArrayLike,
                              cylinder_axis: ArrayLike, cylinder_radius: ArrayLike, *,
                              certify: bool = True, exact_fallback: bool = True,
                              threads: Optional[int] = None
                              ) -> Union[CircleCylinderIntersection, CircleCylinderBatch]:
    """Intersect a circle (a journal rim) with a cylinder's lateral surface (the bearing wall):
    eqs. (16)-(21).

    The cylinder is {x : |(x - p) x a|^2 = R^2 |a|^2}; points farther from the axis are outside
    (beyond the wall). Every crossing (0 to 4) is found and proved, and so is the absence of
    others; tangencies are decided exactly. Shapes, angles and options as in
    :func:`intersect_circle_plane`.

    Returns a :class:`CircleCylinderIntersection` for one pair, else a
    :class:`CircleCylinderBatch`. Raises ValueError naming the argument and row.
    """
    result = _core.intersect_circle_cylinder(circle_center, circle_normal, circle_radius,
                                             cylinder_point, cylinder_axis, cylinder_radius,
                                             certify, exact_fallback, threads)
    return CircleCylinderBatch(result) if isinstance(result, dict) else result
